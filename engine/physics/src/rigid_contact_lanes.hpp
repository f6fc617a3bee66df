#pragma once
// Internal: two rigid contacts of one colour solved at once, one in each lane of a pair of doubles
// (Box2D v3's wide contact solver, two wide for SSE2's __m128d). Contacts of a colour share no
// movable body (rigid_colours.hpp) and immovable bodies are never written, so solving a pair together
// is solving them one after the other. Each lane runs exactly the operations of solveRigidContacts
// (rigid_contacts.cpp) in the same order: std::max(a, b) is (a < b ? b : a), which is SSE2's
// maxpd(b, a); std::min(a, b) is minpd(b, a); a skipped point keeps its velocities by a bitwise
// select. So SSE2 and the plain pair of doubles (ScalarPair, the fallback without SSE2) give the
// same bits as the scalar sweep, under -ffp-contract=off on any compiler and optimisation level
// (tests/rigid_lanes_test.cpp). Not part of the public API.

#include "rigid_contacts.hpp"

#if defined(__SSE2__) && !defined(RUBE_NO_SIMD)
#include <emmintrin.h>
#define RUBE_RIGID_LANES_SSE2 1
#endif

namespace rube {

/// Two doubles with lane-wise operations: the portable fallback, and the reference the SSE2 pair must match.
struct ScalarPair {
    double v[2];
    struct Mask {
        bool m[2];
    };
    static ScalarPair set(double a, double b) { return {{a, b}}; }
    static ScalarPair splat(double a) { return {{a, a}}; }
    static Mask lanes(bool a, bool b) { return {{a, b}}; }
    double lane(int i) const { return v[i]; }
    friend ScalarPair operator+(ScalarPair a, ScalarPair b) { return {{a.v[0] + b.v[0], a.v[1] + b.v[1]}}; }
    friend ScalarPair operator-(ScalarPair a, ScalarPair b) { return {{a.v[0] - b.v[0], a.v[1] - b.v[1]}}; }
    friend ScalarPair operator*(ScalarPair a, ScalarPair b) { return {{a.v[0] * b.v[0], a.v[1] * b.v[1]}}; }
    friend ScalarPair operator-(ScalarPair a) { return {{-a.v[0], -a.v[1]}}; }
    /// std::max(a, b) lane-wise: a < b ? b : a.
    friend ScalarPair maxOf(ScalarPair a, ScalarPair b) {
        return {{a.v[0] < b.v[0] ? b.v[0] : a.v[0], a.v[1] < b.v[1] ? b.v[1] : a.v[1]}};
    }
    /// std::min(a, b) lane-wise: b < a ? b : a.
    friend ScalarPair minOf(ScalarPair a, ScalarPair b) {
        return {{b.v[0] < a.v[0] ? b.v[0] : a.v[0], b.v[1] < a.v[1] ? b.v[1] : a.v[1]}};
    }
    friend Mask greater(ScalarPair a, ScalarPair b) { return {{a.v[0] > b.v[0], a.v[1] > b.v[1]}}; }
    friend ScalarPair select(Mask m, ScalarPair a, ScalarPair b) {
        return {{m.m[0] ? a.v[0] : b.v[0], m.m[1] ? a.v[1] : b.v[1]}};
    }
};

#ifdef RUBE_RIGID_LANES_SSE2
/// Two doubles in one SSE2 register.
struct Sse2Pair {
    __m128d v;
    struct Mask {
        __m128d m;
    };
    static Sse2Pair set(double a, double b) { return {_mm_set_pd(b, a)}; }
    static Sse2Pair splat(double a) { return {_mm_set1_pd(a)}; }
    static Mask lanes(bool a, bool b) { return {_mm_castsi128_pd(_mm_set_epi64x(b ? -1 : 0, a ? -1 : 0))}; }
    double lane(int i) const { return i == 0 ? _mm_cvtsd_f64(v) : _mm_cvtsd_f64(_mm_unpackhi_pd(v, v)); }
    friend Sse2Pair operator+(Sse2Pair a, Sse2Pair b) { return {_mm_add_pd(a.v, b.v)}; }
    friend Sse2Pair operator-(Sse2Pair a, Sse2Pair b) { return {_mm_sub_pd(a.v, b.v)}; }
    friend Sse2Pair operator*(Sse2Pair a, Sse2Pair b) { return {_mm_mul_pd(a.v, b.v)}; }
    friend Sse2Pair operator-(Sse2Pair a) { return {_mm_xor_pd(a.v, _mm_set1_pd(-0.0))}; }
    // maxpd(x, y) is x > y ? x : y, so maxpd(b, a) is a < b ? b : a: std::max(a, b), NaN and -0 alike.
    friend Sse2Pair maxOf(Sse2Pair a, Sse2Pair b) { return {_mm_max_pd(b.v, a.v)}; }
    // minpd(x, y) is x < y ? x : y, so minpd(b, a) is b < a ? b : a: std::min(a, b).
    friend Sse2Pair minOf(Sse2Pair a, Sse2Pair b) { return {_mm_min_pd(b.v, a.v)}; }
    friend Mask greater(Sse2Pair a, Sse2Pair b) { return {_mm_cmpgt_pd(a.v, b.v)}; }
    friend Sse2Pair select(Mask m, Sse2Pair a, Sse2Pair b) {
        return {_mm_or_pd(_mm_and_pd(m.m, a.v), _mm_andnot_pd(m.m, b.v))};
    }
};
using LanePair = Sse2Pair;
#else
using LanePair = ScalarPair;
#endif

/// Whether a sweep may write a body: one that cannot move keeps its velocities bit for bit.
inline bool movableBody(const RigidState& s) { return s.inverseMass > 0.0 || s.inverseInertia > 0.0; }

/// One side of a pair of contacts, gathered lane-wise.
template <class W>
struct LaneBody {
    W vx, vy, omega, inverseMass, inverseInertia;
    LaneBody(const RigidState& s0, const RigidState& s1)
        : vx(W::set(s0.velocity.x, s1.velocity.x)), vy(W::set(s0.velocity.y, s1.velocity.y)),
          omega(W::set(s0.omega, s1.omega)), inverseMass(W::set(s0.inverseMass, s1.inverseMass)),
          inverseInertia(W::set(s0.inverseInertia, s1.inverseInertia)) {}
    /// v += p / m, omega += (r x p) / I, in the lanes of `apply` only (applyImpulse, lane-wise);
    /// `both` says both lanes apply, and the selects are skipped (the same bits).
    void apply(bool both, typename W::Mask apply, W rx, W ry, W px, W py) {
        const W x = vx + px * inverseMass, y = vy + py * inverseMass;
        const W w = omega + inverseInertia * (rx * py - ry * px);
        vx = both ? x : select(apply, x, vx);
        vy = both ? y : select(apply, y, vy);
        omega = both ? w : select(apply, w, omega);
    }
    void store(RigidState& s, int lane) const {
        if (!movableBody(s)) return;
        s.velocity = {vx.lane(lane), vy.lane(lane)};
        s.omega = omega.lane(lane);
    }
};

/// One Gauss-Seidel step over contacts c0 and c1 (of one colour) at once: solveRigidContacts' loop
/// body in two lanes. `write1` false when c1 is a stand-in for an odd contact out.
template <class W>
void solveContactPair(RigidContact& c0, RigidContact& c1, std::span<RigidState> bodies,
                      const RigidContactSoftness& softness, double invH, bool useBias, bool write1) {
    RigidState& sa0 = bodies[static_cast<std::size_t>(c0.bodyA)];
    RigidState& sa1 = bodies[static_cast<std::size_t>(c1.bodyA)];
    RigidState& sb0 = bodies[static_cast<std::size_t>(c0.bodyB)];
    RigidState& sb1 = bodies[static_cast<std::size_t>(c1.bodyB)];
    LaneBody<W> a(sa0, sa1), b(sb0, sb1);
    const Softness& soft0 = c0.againstFixed ? softness.fixed : softness.movable;
    const Softness& soft1 = c1.againstFixed ? softness.fixed : softness.movable;
    const W zero = W::splat(0.0), one = W::splat(1.0);
    const W nx = W::set(c0.normal.x, c1.normal.x), ny = W::set(c0.normal.y, c1.normal.y);
    const W dpx = W::set(sb0.displacement.x, sb1.displacement.x) - W::set(sa0.displacement.x, sa1.displacement.x);
    const W dpy = W::set(sb0.displacement.y, sb1.displacement.y) - W::set(sa0.displacement.y, sa1.displacement.y);
    W softBias = zero, softMass = one, softImpulse = zero;
    if (useBias) {
        softBias = W::set(soft0.biasRate, soft1.biasRate);
        softMass = W::set(soft0.massScale, soft1.massScale);
        softImpulse = W::set(soft0.impulseScale, soft1.impulseScale);
    }
    const W invHw = W::splat(invH), pushLimit = W::splat(-softness.maxPushSpeed);
    const int count = c0.count > c1.count ? c0.count : c1.count;
    for (int k = 0; k < count; ++k) {
        RigidContactPoint& p0 = c0.points[k];
        RigidContactPoint& p1 = c1.points[k];
        const typename W::Mask has = W::lanes(k < c0.count, k < c1.count);
        const W rAx = W::set(p0.armA.x, p1.armA.x), rAy = W::set(p0.armA.y, p1.armA.y);
        const W rBx = W::set(p0.armB.x, p1.armB.x), rBy = W::set(p0.armB.y, p1.armB.y);
        const W s = nx * ((dpx + rBx) - rAx) + ny * ((dpy + rBy) - rAy) + W::set(p0.baseSeparation, p1.baseSeparation);
        const typename W::Mask speculative = greater(s, zero);
        // Penetrating: the soft push-out when biased (bias 0, mass scale 1, impulse scale 0 when relaxing).
        W bias = useBias ? maxOf(softBias * s, pushLimit) : zero;
        bias = select(speculative, s * invHw, bias);
        const W massScale = select(speculative, one, softMass);
        const W impulseScale = select(speculative, zero, softImpulse);
        const W vn = nx * ((b.vx + -rBy * b.omega) - (a.vx + -rAy * a.omega)) +
                     ny * ((b.vy + rBx * b.omega) - (a.vy + rAx * a.omega));
        const W old = W::set(p0.normalImpulse, p1.normalImpulse);
        const W lambda = -W::set(p0.normalMass, p1.normalMass) * massScale * (vn + bias) - impulseScale * old;
        const W total = maxOf(old + lambda, zero);
        const W delta = total - old;
        const W delivered = W::set(p0.deliveredNormal, p1.deliveredNormal) + delta;
        const W most = maxOf(W::set(p0.maxNormalImpulse, p1.maxNormalImpulse), total);
        const W minus = -delta;
        const bool both = k < c0.count && k < c1.count;
        a.apply(both, has, rAx, rAy, nx * minus, ny * minus);
        b.apply(both, has, rBx, rBy, nx * delta, ny * delta);
        if (k < c0.count) {
            p0.normalImpulse = total.lane(0);
            p0.deliveredNormal = delivered.lane(0);
            p0.maxNormalImpulse = most.lane(0);
        }
        if (write1 && k < c1.count) {
            p1.normalImpulse = total.lane(1);
            p1.deliveredNormal = delivered.lane(1);
            p1.maxNormalImpulse = most.lane(1);
        }
    }
    const bool rubs0 = c0.friction > 0.0, rubs1 = c1.friction > 0.0;
    if (rubs0 || rubs1) {
        const W tx = W::set(c0.tangent.x, c1.tangent.x), ty = W::set(c0.tangent.y, c1.tangent.y);
        const W friction = W::set(c0.friction, c1.friction);
        for (int k = 0; k < count; ++k) {
            RigidContactPoint& p0 = c0.points[k];
            RigidContactPoint& p1 = c1.points[k];
            const bool on0 = rubs0 && k < c0.count, on1 = rubs1 && k < c1.count;
            const typename W::Mask has = W::lanes(on0, on1);
            const W rAx = W::set(p0.armA.x, p1.armA.x), rAy = W::set(p0.armA.y, p1.armA.y);
            const W rBx = W::set(p0.armB.x, p1.armB.x), rBy = W::set(p0.armB.y, p1.armB.y);
            const W vt = tx * ((b.vx + -rBy * b.omega) - (a.vx + -rAy * a.omega)) +
                         ty * ((b.vy + rBx * b.omega) - (a.vy + rAx * a.omega));
            const W limit = friction * W::set(p0.normalImpulse, p1.normalImpulse);
            const W old = W::set(p0.tangentImpulse, p1.tangentImpulse);
            const W v = old - W::set(p0.tangentMass, p1.tangentMass) * vt;
            const W total = minOf(maxOf(v, -limit), limit);
            const W delta = total - old;
            const W delivered = W::set(p0.deliveredTangent, p1.deliveredTangent) + delta;
            const W minus = -delta;
            a.apply(on0 && on1, has, rAx, rAy, tx * minus, ty * minus);
            b.apply(on0 && on1, has, rBx, rBy, tx * delta, ty * delta);
            if (on0) {
                p0.tangentImpulse = total.lane(0);
                p0.deliveredTangent = delivered.lane(0);
            }
            if (write1 && on1) {
                p1.tangentImpulse = total.lane(1);
                p1.deliveredTangent = delivered.lane(1);
            }
        }
    }
    a.store(sa0, 0);
    b.store(sb0, 0);
    if (write1) {
        a.store(sa1, 1);
        b.store(sb1, 1);
    }
}

} // namespace rube
