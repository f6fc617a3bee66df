#pragma once
// Internal: polynomials of degree at most 4 and their earliest root on an interval, for times of
// impact under constant acceleration (a quadratic against a line face, a quartic against a point).

#include <array>
#include <optional>

namespace rube {

/// c[0] + c[1] t + c[2] t^2 + c[3] t^3 + c[4] t^4.
struct Polynomial {
    std::array<double, 5> c{};

    /// The highest power with a nonzero coefficient (0 for constants, including the zero polynomial).
    int degree() const;
    /// p(t) by Horner's rule, always in the same order so results are bit-reproducible.
    double operator()(double t) const;
    /// p'(t) as a polynomial.
    Polynomial derivative() const;
};

/// Every root of p strictly inside (lo, hi), in increasing order; returns how many were written.
/// Roots are isolated by the roots of p' (between two of those p is monotonic) and refined on a
/// sign change, so a double root that touches zero without crossing is found only if p is exactly 0 there.
int rootsBetween(const Polynomial& p, double lo, double hi, std::array<double, 4>& roots);

/// The earliest root of p in [lo, hi], to round-off: the returned t is the last double before the
/// sign change (p(t) still has the sign p had at lo), or a point where p is exactly 0.
/// With `skipRootAtLo`, p(lo) == 0 does not count (two bodies touching and moving apart).
/// The zero polynomial has no isolated roots and gives nothing.
std::optional<double> earliestRoot(const Polynomial& p, double lo, double hi, bool skipRootAtLo = false);

} // namespace rube
