// Roots of polynomials of degree <= 4 on an interval: isolate by the roots of the derivative (the
// polynomial is monotonic between two of them), then refine each sign change to round-off.
#include "polynomial.hpp"

#include <cmath>
#include <limits>

namespace rube {

int Polynomial::degree() const {
    for (int i = 4; i > 0; --i)
        if (c[i] != 0.0) return i;
    return 0;
}

double Polynomial::operator()(double t) const { return (((c[4] * t + c[3]) * t + c[2]) * t + c[1]) * t + c[0]; }

Polynomial Polynomial::derivative() const { return Polynomial{{c[1], 2.0 * c[2], 3.0 * c[3], 4.0 * c[4], 0.0}}; }

namespace {

// Every second iteration at least halves the bracket; a step-sized bracket reaches neighbouring
// doubles in well under 200 iterations. If the limit is ever reached, l is still a safe answer.
constexpr int kMaxIterations = 400;

bool positive(double v) { return v > 0.0; }

// The root of a monotonic p in (l, r), where p(l) and p(r) are nonzero with opposite signs.
// Safeguarded Newton: a Newton step is taken when it stays inside the bracket and the bracket keeps
// halving; otherwise bisection. Stops when l and r are neighbouring doubles and returns l, the side
// with p(l)'s sign (for a time of impact: just before the surfaces meet, never past them).
double refineRoot(const Polynomial& p, const Polynomial& dp, double l, double r, double fl) {
    double lastWidth = r - l;
    double x = l + 0.5 * (r - l);
    for (int i = 0; i < kMaxIterations; ++i) {
        const double fx = p(x);
        if (fx == 0.0) return x;
        if (positive(fx) == positive(fl)) l = x;
        else r = x;
        const double width = r - l;
        const bool slowProgress = width > 0.5 * lastWidth;
        lastWidth = width;

        const double slope = dp(x);
        double next = slope != 0.0 ? x - fx / slope : x;
        // Newton has converged onto an end of the bracket: probe the neighbouring double inside it,
        // which either closes the bracket or moves that end by one unit in the last place.
        if (next == x) next = x == l ? std::nextafter(l, r) : std::nextafter(r, l);
        if (slowProgress || !(next > l && next < r)) next = l + 0.5 * (r - l);
        if (!(next > l && next < r)) break; // l and r are neighbouring doubles: done to round-off
        x = next;
    }
    return l;
}

} // namespace

int rootsBetween(const Polynomial& p, double lo, double hi, std::array<double, 4>& roots) {
    const int n = p.degree();
    if (n == 0 || !(lo < hi)) return 0;
    if (n == 1) {
        const double t = -p.c[0] / p.c[1];
        if (t > lo && t < hi) {
            roots[0] = t;
            return 1;
        }
        return 0;
    }
    const Polynomial dp = p.derivative();
    std::array<double, 4> critical{};
    const int criticalCount = rootsBetween(dp, lo, hi, critical);

    int count = 0;
    double xl = lo;
    double fl = p(lo);
    for (int i = 0; i <= criticalCount; ++i) {
        const double xr = i < criticalCount ? critical[i] : hi;
        const double fr = p(xr);
        // A zero exactly at a piece's start (an extremum touching zero) is a root; the start of the
        // first piece is lo itself, which is outside the open interval.
        if (fl == 0.0 && xl > lo) roots[count++] = xl;
        else if (fl != 0.0 && fr != 0.0 && positive(fl) != positive(fr)) roots[count++] = refineRoot(p, dp, xl, xr, fl);
        xl = xr;
        fl = fr;
    }
    return count;
}

std::optional<double> earliestRoot(const Polynomial& p, double lo, double hi, bool skipRootAtLo) {
    if (!(lo <= hi) || p.degree() == 0) return std::nullopt;
    const Polynomial dp = p.derivative();
    std::array<double, 4> critical{};
    const int criticalCount = rootsBetween(dp, lo, hi, critical);

    double xl = lo;
    double fl = p(lo);
    if (fl == 0.0 && !skipRootAtLo) return lo;
    // Between neighbouring critical points p is monotonic: at most one root per piece, found by
    // its sign change; the first piece with one holds the earliest root.
    for (int i = 0; i <= criticalCount; ++i) {
        const double xr = i < criticalCount ? critical[i] : hi;
        const double fr = p(xr);
        if (fr == 0.0 && xr > lo) return xr;
        if (fl != 0.0 && positive(fl) != positive(fr)) return refineRoot(p, dp, xl, xr, fl);
        xl = xr;
        fl = fr;
    }
    return std::nullopt;
}

} // namespace rube
