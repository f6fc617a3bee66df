#pragma once
// Internal: both normal impulses of a two-point contact at once (Box2D v2's block solver, with the
// soft step's scaling). Not part of the public API.
//
// One point after the other, the first point of a box landing flat takes the whole landing: its push
// turns the box, the second point then sees less approach and pushes less, and the box turns through
// the landing's substeps (a 0.5 x 2 m box dropped upright from 2 m left its first bounce tilted 0.88
// degrees). Solved together, equal points take equal impulses.
//
// With x the points' new total impulses and x0 the old ones, K the pair's 2 x 2 effective-mass
// inverse (K_ij = 1/mA + 1/mB + (rAi x n)(rAj x n) / IA + (rBi x n)(rBj x n) / IB) and v the normal
// speeds before the update, the soft step's rule for one point, x = s x0 - s (v + bias) / K_ii with
// s the mass scale (Catto, "Soft Constraints": x = x0 + lambda, lambda = -s (v + bias) / K_ii - (1 -
// s) x0), is the row of w = M x + c = 0 with M_ii = K_ii / s, M_12 = K_12 and c = v + bias - K x0.
// Both rows at once, pushing only, is the linear complementarity problem x >= 0, w >= 0, x w = 0,
// solved by trying its four cases in turn: both push, only the first, only the second, neither. A
// relax pass and restitution are the same with s = 1 (restitution's bias is minus the target speed).
//
// Written once over T, a double or a vector of doubles whose lanes are separate contacts (with
// masks as the comparisons give them), so the scalar reference and the lanes compute each lane's
// value with the same operations in the same order: the same bits (tests/rigid_lanes_test.cpp).

namespace rube {

/// The two new total impulses and, lane-wise, whether a case of the problem held (false: K is singular,
/// the points too close together, or rounding left no case; the caller then solves point by point).
template <class T, class Mask>
struct NormalPair {
    T x1, x2;
    Mask solved;
};

/// Solves w = M x + c for x >= 0, w >= 0, x w = 0, with M = [[k11 / s1, k12], [k12, k22 / s2]] and
/// c_i = (v_i + bias_i) - (K x0)_i. `zero` and `one` are 0 and 1 as T (splat for vectors).
template <class T, class Mask>
[[gnu::always_inline]] inline NormalPair<T, Mask> solveNormalPair(T k11, T k22, T k12, T s1, T s2, T v1, T v2, T bias1,
                                                                  T bias2, T old1, T old2, T zero, T one) {
    const T c1 = (v1 + bias1) - (k11 * old1 + k12 * old2);
    const T c2 = (v2 + bias2) - (k12 * old1 + k22 * old2);
    const T m11 = k11 / s1, m22 = k22 / s2;
    const T diagonal = m11 * m22;
    const T det = diagonal - k12 * k12;
    const Mask regular = det > diagonal * 1e-9;
    // A singular lane (or a stand-in's zeros) divides by 1 instead; its result is not used.
    const T safeDet = regular ? det : one, safe11 = m11 > zero ? m11 : one, safe22 = m22 > zero ? m22 : one;
    // Both push: x = -M^-1 c.
    const T both1 = (k12 * c2 - m22 * c1) / safeDet, both2 = (k12 * c1 - m11 * c2) / safeDet;
    const Mask both = regular & (both1 >= zero) & (both2 >= zero);
    // Only the first: x1 = -c1 / M11, and the second point's w2 = M12 x1 + c2 must not pull.
    const T first = -c1 / safe11;
    const Mask onlyFirst = regular & (first >= zero) & (k12 * first + c2 >= zero);
    const T second = -c2 / safe22;
    const Mask onlySecond = regular & (second >= zero) & (k12 * second + c1 >= zero);
    const Mask neither = regular & (c1 >= zero) & (c2 >= zero);
    NormalPair<T, Mask> r;
    r.x1 = both ? both1 : onlyFirst ? first : zero;
    r.x2 = both ? both2 : onlyFirst ? zero : onlySecond ? second : zero;
    r.solved = both | onlyFirst | onlySecond | neither;
    return r;
}

/// K's entries for points 1 and 2 of a contact: (rA1 x n, rB1 x n) and (rA2 x n, rB2 x n) given,
/// with the bodies' inverse masses summed in `m` and their inverse inertias.
template <class T>
struct PairMass {
    T k11, k22, k12;
    [[gnu::always_inline]] PairMass(T m, T inverseInertiaA, T inverseInertiaB, T rn1A, T rn1B, T rn2A, T rn2B)
        : k11(m + inverseInertiaA * rn1A * rn1A + inverseInertiaB * rn1B * rn1B),
          k22(m + inverseInertiaA * rn2A * rn2A + inverseInertiaB * rn2B * rn2B),
          k12(m + inverseInertiaA * rn1A * rn2A + inverseInertiaB * rn1B * rn2B) {}
};

} // namespace rube
