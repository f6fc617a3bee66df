#pragma once
// Internal: one Gauss-Seidel step over a block's contacts at once, one contact in each lane (Box2D
// v3's wide contact solver; rigid_contact_blocks.hpp). Contacts of a colour share no movable body
// (rigid_colours.hpp) and immovable bodies are never written, so solving a block's lanes together
// is solving its contacts one after the other. Each lane runs exactly the operations of
// solveRigidContacts (rigid_contacts.cpp) in the same order, and a vector's operators are the
// lane's IEEE double operations: std::max(a, b) is spelt a < b ? b : a lane-wise, std::min(a, b)
// b < a ? b : a, and a lane that skips a point keeps its velocities by a select. So the sweep gives
// the scalar sweep's bits under -ffp-contract=off whatever instructions the compiler picks (AVX,
// SSE2 or none), on any compiler and optimisation level (tests/rigid_lanes_test.cpp).
//
// Why four at a time: AVX's width in doubles, so a sweep does a quarter of the instructions. (Two
// blocks' chains of dependent operations interleaved point by point, for the processor to overlap,
// gave nothing measurable: the sweep is bound by its work, not by one contact's latency.) Not part
// of the public API.

#include "rigid_contact_blocks.hpp"
#include "rigid_normal_pair.hpp"

#include <cmath>
#include <cstring>

// Every function here taking or returning a vector is always inlined into the sweep that calls it,
// each compiled for one target (rigid_contact_blocks.cpp), so no vector ever crosses a call whose
// ABI AVX would change: GCC's note that it might is moot.
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace rube {

/// Half a block's lanes: SSE2's width, how processors without AVX run a block (two halves one after
/// the other; they are independent contacts, so the order does not matter).
using HalfLanes = double __attribute__((vector_size(kBlockLanes / 2 * sizeof(double))));
/// A lane-wise truth of vector V.
template <class V>
using MaskOf = decltype(V{} < V{});
/// Lanes in vector V.
template <class V>
inline constexpr int kWidth = static_cast<int>(sizeof(V) / sizeof(double));

/// std::max(a, b) lane-wise: a < b ? b : a.
template <class V>
[[gnu::always_inline]] inline V maxOf(V a, V b) {
    return a < b ? b : a;
}
/// std::min(a, b) lane-wise: b < a ? b : a.
template <class V>
[[gnu::always_inline]] inline V minOf(V a, V b) {
    return b < a ? b : a;
}

/// x in every lane.
template <class V>
[[gnu::always_inline]] inline V splat(double x) {
    V v;
    for (int i = 0; i < kWidth<V>; ++i) v[i] = x;
    return v;
}

/// The truths t[0 .. width) as a mask.
template <class V>
[[gnu::always_inline]] inline MaskOf<V> maskOf(const bool* t) {
    MaskOf<V> m;
    for (int i = 0; i < kWidth<V>; ++i) m[i] = t[i] ? -1 : 0;
    return m;
}

/// The lanes [base, base + width of V) of a block's contacts: where a pass reads and writes its fields.
template <class V>
struct Slice {
    int base = 0;
    [[gnu::always_inline]] V operator()(const Lanes& field) const {
        V v;
        std::memcpy(&v, reinterpret_cast<const double*>(&field) + base, sizeof v);
        return v;
    }
    [[gnu::always_inline]] void set(Lanes& field, V v) const {
        std::memcpy(reinterpret_cast<double*>(&field) + base, &v, sizeof v);
    }
    /// The slice of a mask packed as Lanes (RigidBlock::pointMask and the like).
    [[gnu::always_inline]] MaskOf<V> mask(const Lanes& field) const {
        MaskOf<V> m;
        std::memcpy(&m, reinterpret_cast<const double*>(&field) + base, sizeof m);
        return m;
    }
    /// The slice's lanes of a block's lane bits (RigidBlock::pointLanes and the like).
    [[gnu::always_inline]] unsigned bits(unsigned lanes) const { return (lanes >> base) & ((1u << kWidth<V>)-1); }
    [[gnu::always_inline]] bool all(unsigned lanes) const { return bits(lanes) == (1u << kWidth<V>)-1; }
    [[gnu::always_inline]] bool lane(unsigned lanes, int i) const { return (lanes >> (base + i)) & 1u; }
};

/// The bodies of one side of a slice's contacts, and the slice's largest point count.
template <class V>
struct SliceBodies {
    RigidState* a[kWidth<V>];
    RigidState* b[kWidth<V>];
    int count = 0;
    [[gnu::always_inline]] SliceBodies(const RigidBlock& k, int base, std::span<RigidState> bodies) {
        for (int i = 0; i < kWidth<V>; ++i) {
            a[i] = &bodies[static_cast<std::size_t>(k.bodyA[base + i])];
            b[i] = &bodies[static_cast<std::size_t>(k.bodyB[base + i])];
        }
        const Slice<V> at{base};
        count = at.bits(k.pointLanes[1]) != 0 ? 2 : at.bits(k.pointLanes[0]) != 0 ? 1 : 0;
    }
};

/// Field f of the lanes' bodies s[0 .. width).
template <class V>
[[gnu::always_inline]] inline V gather(RigidState* const* s, double RigidState::*f) {
    V v;
    for (int i = 0; i < kWidth<V>; ++i) v[i] = s[i]->*f;
    return v;
}
/// Component c of vector field f of the lanes' bodies.
template <class V>
[[gnu::always_inline]] inline V gather(RigidState* const* s, Vec2 RigidState::*f, double Vec2::*c) {
    V v;
    for (int i = 0; i < kWidth<V>; ++i) v[i] = (s[i]->*f).*c;
    return v;
}

/// One side of a slice's contacts, gathered lane-wise.
template <class V>
struct LaneBody {
    V vx, vy, omega, inverseMass, inverseInertia;
    /// The velocities gathered from the bodies, the masses from the block (RigidBlock::inverseMassA).
    [[gnu::always_inline]] LaneBody(RigidState* const* s, V inverseMass_, V inverseInertia_)
        : vx(gather<V>(s, &RigidState::velocity, &Vec2::x)), vy(gather<V>(s, &RigidState::velocity, &Vec2::y)),
          omega(gather<V>(s, &RigidState::omega)), inverseMass(inverseMass_), inverseInertia(inverseInertia_) {}
    /// v += p / m, omega += (r x p) / I, in the lanes of `apply` only (applyImpulse, lane-wise);
    /// `all` says every lane applies, and the selects are skipped (the same bits). With Opposite, the
    /// impulse is -p, applied without negating it: v + (-p) / m is v - p / m, and r x (-p) = -(r x p),
    /// since rounding is symmetric in sign (the same bits; a NaN's sign aside).
    template <bool Opposite = false>
    [[gnu::always_inline]] void apply(bool all, MaskOf<V> apply, V rx, V ry, V px, V py) {
        const V turn = inverseInertia * (rx * py - ry * px);
        const V x = Opposite ? vx - px * inverseMass : vx + px * inverseMass;
        const V y = Opposite ? vy - py * inverseMass : vy + py * inverseMass;
        const V w = Opposite ? omega - turn : omega + turn;
        vx = all ? x : (apply ? x : vx);
        vy = all ? y : (apply ? y : vy);
        omega = all ? w : (apply ? w : omega);
    }
    /// Into a body the lane may write (RigidBlock::writesA, writesB: movableBody).
    [[gnu::always_inline]] void store(RigidState& s, int lane) const {
        s.velocity = {vx[lane], vy[lane]};
        s.omega = omega[lane];
    }
};

/// d . ((vB + omegaB x rB) - (vA + omegaA x rA)): how fast the contact point's sides part along d,
/// as pointVelocity and Vec2::dot compute it, lane-wise.
template <class V>
[[gnu::always_inline]] inline V alongPoint(const LaneBody<V>& a, const LaneBody<V>& b, V rAx, V rAy, V rBx, V rBy, V dx,
                                           V dy) {
    // v + (-ry) omega is v - ry omega: the same bits (a NaN's sign aside), one negation fewer.
    return dx * ((b.vx - rBy * b.omega) - (a.vx - rAy * a.omega)) +
           dy * ((b.vy + rBx * b.omega) - (a.vy + rAx * a.omega));
}

/// refreshArms over a slice: rotate(q, r) = (q.x r.x - q.y r.y, q.y r.x + q.x r.y) lane-wise; a
/// stand-in's zero anchors stay zero.
template <class V>
[[gnu::always_inline]] inline void refreshArmsOfSlice(RigidBlock& k, int base, std::span<RigidState> bodies) {
    const Slice<V> at{base};
    const SliceBodies<V> s(k, base, bodies);
    const V qAx = gather<V>(s.a, &RigidState::turnRotation, &Vec2::x);
    const V qAy = gather<V>(s.a, &RigidState::turnRotation, &Vec2::y);
    const V qBx = gather<V>(s.b, &RigidState::turnRotation, &Vec2::x);
    const V qBy = gather<V>(s.b, &RigidState::turnRotation, &Vec2::y);
    for (int j = 0; j < s.count; ++j) {
        RigidBlockPoint& p = k.points[j];
        const V ax = at(p.anchorAx), ay = at(p.anchorAy), bx = at(p.anchorBx), by = at(p.anchorBy);
        at.set(p.armAx, qAx * ax - qAy * ay);
        at.set(p.armAy, qAy * ax + qAx * ay);
        at.set(p.armBx, qBx * bx - qBy * by);
        at.set(p.armBy, qBy * bx + qBx * by);
    }
}

/// measureApproach over a slice: each real point that has not pushed yet this step notes its
/// approach speed -vn, with this contact's own delivered impulses taken back out of vn (the formula
/// at measureApproach), and the substep, into `contacts` (the list the blocks were packed from).
template <class V>
[[gnu::always_inline]] inline void measureApproachOfSlice(const RigidBlock& k, int base,
                                                          std::span<RigidContact> contacts,
                                                          std::span<RigidState> bodies, int substep) {
    constexpr int W = kWidth<V>;
    const Slice<V> at{base};
    const SliceBodies<V> s(k, base, bodies);
    const V zero = splat<V>(0.0);
    // Real points that have not pushed yet: !(maxNormalImpulse > 0), NaN included. Resting contacts
    // have all pushed, and then the bodies are not even gathered.
    MaskOf<V> measured[2] = {};
    bool anyPoint[2] = {false, false};
    for (int j = 0; j < s.count; ++j) {
        measured[j] = at.mask(k.pointMask[j]) & ~(at(k.points[j].maxNormalImpulse) > zero);
        for (int i = 0; i < W; ++i) anyPoint[j] = anyPoint[j] || measured[j][i] != 0;
    }
    if (!anyPoint[0] && !anyPoint[1]) return;
    const LaneBody<V> a(s.a, at(k.inverseMassA), at(k.inverseInertiaA)),
        b(s.b, at(k.inverseMassB), at(k.inverseInertiaB));
    const V nx = at(k.normalX), ny = at(k.normalY), tx = at(k.tangentX), ty = at(k.tangentY);
    for (int j = 0; j < s.count; ++j) {
        if (!anyPoint[j]) continue;
        const RigidBlockPoint& p = k.points[j];
        const V rAx = at(p.armAx), rAy = at(p.armAy), rBx = at(p.armBx), rBy = at(p.armBy);
        V vn = alongPoint(a, b, rAx, rAy, rBx, rBy, nx, ny);
        const V ka = a.inverseInertia * (rAx * ny - rAy * nx), kb = b.inverseInertia * (rBx * ny - rBy * nx);
        for (int q = 0; q < s.count; ++q) {
            const RigidBlockPoint& o = k.points[q];
            const V deliveredNormal = at(o.deliveredNormal), deliveredTangent = at(o.deliveredTangent);
            const MaskOf<V> takes = at.mask(k.pointMask[q]) & ~((deliveredNormal == zero) & (deliveredTangent == zero));
            const V oAx = at(o.armAx), oAy = at(o.armAy), oBx = at(o.armBx), oBy = at(o.armBy);
            const V crossAn = oAx * ny - oAy * nx, crossBn = oBx * ny - oBy * nx;
            const V crossAt = oAx * ty - oAy * tx, crossBt = oBx * ty - oBy * tx;
            const V afterNormal = vn - deliveredNormal * (a.inverseMass + b.inverseMass + ka * crossAn + kb * crossBn);
            const V afterTangent = afterNormal - deliveredTangent * (ka * crossAt + kb * crossBt);
            vn = takes ? afterTangent : vn;
        }
        for (int i = 0; i < W; ++i) {
            if (measured[j][i] == 0) continue;
            RigidContactPoint& point = contacts[static_cast<std::size_t>(k.contact[base + i])].points[j];
            point.approachSpeed = -vn[i];
            point.touchSubstep = substep;
        }
    }
}

/// warmStartRigidContacts over a slice: each point's last impulses applied again, in the lanes whose
/// bodies turn less than `maxTurn` in the substep h; the others start from zero.
template <class V>
[[gnu::always_inline]] inline void warmStartSlice(RigidBlock& k, int base, std::span<RigidState> bodies, double h,
                                                  double maxTurn) {
    constexpr int W = kWidth<V>;
    const Slice<V> at{base};
    const SliceBodies<V> s(k, base, bodies);
    bool warm[W];
    bool allWarm = true;
    for (int i = 0; i < W; ++i) {
        warm[i] = !(std::abs(s.a[i]->omega) * h > maxTurn || std::abs(s.b[i]->omega) * h > maxTurn);
        allWarm = allWarm && warm[i];
    }
    const MaskOf<V> warmLanes = maskOf<V>(warm);
    LaneBody<V> a(s.a, at(k.inverseMassA), at(k.inverseInertiaA)), b(s.b, at(k.inverseMassB), at(k.inverseInertiaB));
    const V nx = at(k.normalX), ny = at(k.normalY), tx = at(k.tangentX), ty = at(k.tangentY);
    const V zero = splat<V>(0.0);
    for (int j = 0; j < s.count; ++j) {
        RigidBlockPoint& p = k.points[j];
        const MaskOf<V> real = at.mask(k.pointMask[j]);
        const MaskOf<V> has = real & warmLanes, zeroed = real & ~warmLanes;
        const bool all = allWarm && at.all(k.pointLanes[j]);
        const V normalImpulse = at(p.normalImpulse), tangentImpulse = at(p.tangentImpulse);
        // impulse = n lambda_n + t lambda_t; A takes -impulse at its arm, B +impulse at its own.
        const V ix = nx * normalImpulse + tx * tangentImpulse;
        const V iy = ny * normalImpulse + ty * tangentImpulse;
        const V deliveredNormal = at(p.deliveredNormal), deliveredTangent = at(p.deliveredTangent);
        at.set(p.deliveredNormal, has ? deliveredNormal + normalImpulse : deliveredNormal);
        at.set(p.deliveredTangent, has ? deliveredTangent + tangentImpulse : deliveredTangent);
        a.template apply<true>(all, has, at(p.armAx), at(p.armAy), ix, iy);
        b.apply(all, has, at(p.armBx), at(p.armBy), ix, iy);
        at.set(p.normalImpulse, zeroed ? zero : normalImpulse);
        at.set(p.tangentImpulse, zeroed ? zero : tangentImpulse);
    }
    // As in the solve: a body that cannot move is never written, so a colour may be shared among workers.
    for (int i = 0; i < W; ++i) {
        if (!warm[i]) continue;
        if (at.lane(k.writesA, i)) a.store(*s.a[i], i);
        if (at.lane(k.writesB, i)) b.store(*s.b[i], i);
    }
}

/// solveRigidContacts' loop body over a slice's contacts, one in each lane. Every field of a point
/// is stored in all lanes, those of a lane past its contact's points (or of a stand-in) included:
/// nothing reads them but the next sweep's masked lanes.
template <class V>
[[gnu::always_inline]] inline void solveSlice(RigidBlock& k, int base, std::span<RigidState> bodies,
                                              const RigidContactSoftness& softness, double invH, bool useBias) {
    constexpr int W = kWidth<V>;
    const Slice<V> at{base};
    const SliceBodies<V> s(k, base, bodies);
    const bool anyRubs = at.bits(k.rubbingLanes[0] | k.rubbingLanes[1]) != 0;
    LaneBody<V> a(s.a, at(k.inverseMassA), at(k.inverseInertiaA)), b(s.b, at(k.inverseMassB), at(k.inverseInertiaB));
    const V zero = splat<V>(0.0), one = splat<V>(1.0);
    const V nx = at(k.normalX), ny = at(k.normalY);
    const V dpx = gather<V>(s.b, &RigidState::displacement, &Vec2::x) -
                  gather<V>(s.a, &RigidState::displacement, &Vec2::x);
    const V dpy = gather<V>(s.b, &RigidState::displacement, &Vec2::y) -
                  gather<V>(s.a, &RigidState::displacement, &Vec2::y);
    V softBias = zero, softMass = one, softImpulse = zero;
    if (useBias)
        for (int i = 0; i < W; ++i) {
            const Softness& soft = softness.of(k.stacking[base + i], k.againstFixed[base + i]);
            softBias[i] = soft.biasRate;
            softMass[i] = soft.massScale;
            softImpulse[i] = soft.impulseScale;
        }
    const V invHw = splat<V>(invH), pushLimit = splat<V>(-softness.maxPushSpeed);
    V bias[2], massScale[2], impulseScale[2];
    for (int j = 0; j < s.count; ++j) {
        const RigidBlockPoint& p = k.points[j];
        const V gap = nx * ((dpx + at(p.armBx)) - at(p.armAx)) + ny * ((dpy + at(p.armBy)) - at(p.armAy)) +
                      at(p.baseSeparation);
        const MaskOf<V> speculative = gap > zero;
        // Penetrating: the soft push-out when biased (bias 0, mass scale 1, impulse scale 0 when relaxing).
        const V push = useBias ? maxOf(softBias * gap, pushLimit) : zero;
        bias[j] = speculative ? gap * invHw : push;
        massScale[j] = speculative ? one : softMass;
        impulseScale[j] = speculative ? zero : softImpulse;
    }
    // Lanes whose two points are solved together (rigid_normal_pair.hpp), from the velocities before
    // either pushes; the others point after point below, and these lanes keep theirs through it.
    MaskOf<V> together = zero < zero;
    bool anyTogether = false, allTogether = false;
    V pairTotal[2] = {zero, zero};
    if (s.count == 2) {
        const RigidBlockPoint &p1 = k.points[0], &p2 = k.points[1];
        const V rA1x = at(p1.armAx), rA1y = at(p1.armAy), rB1x = at(p1.armBx), rB1y = at(p1.armBy);
        const V rA2x = at(p2.armAx), rA2y = at(p2.armAy), rB2x = at(p2.armBx), rB2y = at(p2.armBy);
        const V vn1 = alongPoint(a, b, rA1x, rA1y, rB1x, rB1y, nx, ny);
        const V vn2 = alongPoint(a, b, rA2x, rA2y, rB2x, rB2y, nx, ny);
        const PairMass<V> mass(a.inverseMass + b.inverseMass, a.inverseInertia, b.inverseInertia, rA1x * ny - rA1y * nx,
                               rB1x * ny - rB1y * nx, rA2x * ny - rA2y * nx, rB2x * ny - rB2y * nx);
        const NormalPair<V, MaskOf<V>> pair = solveNormalPair<V, MaskOf<V>>(
            mass.k11, mass.k22, mass.k12, massScale[0], massScale[1], vn1, vn2, bias[0], bias[1], at(p1.normalImpulse),
            at(p2.normalImpulse), zero, one);
        together = pair.solved & at.mask(k.pointMask[1]);
        unsigned togetherLanes = 0;
        for (int i = 0; i < W; ++i) togetherLanes |= together[i] != 0 ? 1u << i : 0u;
        anyTogether = togetherLanes != 0;
        // Every real lane together (a pyramid's blocks, mostly): nothing is left to go point by point.
        allTogether = togetherLanes == at.bits(k.pointLanes[0]);
        pairTotal[0] = pair.x1;
        pairTotal[1] = pair.x2;
    }
    for (int j = 0; j < (allTogether ? 0 : s.count); ++j) {
        RigidBlockPoint& p = k.points[j];
        const bool all = !anyTogether && at.all(k.pointLanes[j]);
        const MaskOf<V> has = at.mask(k.pointMask[j]) & ~together;
        const V rAx = at(p.armAx), rAy = at(p.armAy), rBx = at(p.armBx), rBy = at(p.armBy);
        const V vn = alongPoint(a, b, rAx, rAy, rBx, rBy, nx, ny);
        const V old = at(p.normalImpulse);
        const V lambda = -at(p.normalMass) * massScale[j] * (vn + bias[j]) - impulseScale[j] * old;
        const V total = maxOf(old + lambda, zero);
        const V delta = total - old;
        const V px = nx * delta, py = ny * delta;
        a.template apply<true>(all, has, rAx, rAy, px, py);
        b.apply(all, has, rBx, rBy, px, py);
        // The lanes solved together keep theirs, for the pass below.
        const V delivered = at(p.deliveredNormal), most = at(p.maxNormalImpulse);
        at.set(p.normalImpulse, together ? old : total);
        at.set(p.deliveredNormal, together ? delivered : delivered + delta);
        at.set(p.maxNormalImpulse, together ? most : maxOf(most, total));
    }
    // The pairs' impulses, point 1 then point 2, on the velocities the loop above left untouched.
    if (anyTogether)
        for (int j = 0; j < 2; ++j) {
            RigidBlockPoint& p = k.points[j];
            const V old = at(p.normalImpulse), total = pairTotal[j];
            const V delta = total - old;
            const V px = nx * delta, py = ny * delta;
            const bool all = allTogether && at.all(k.pointLanes[0]);
            a.template apply<true>(all, together, at(p.armAx), at(p.armAy), px, py);
            b.apply(all, together, at(p.armBx), at(p.armBy), px, py);
            const V delivered = at(p.deliveredNormal), most = at(p.maxNormalImpulse);
            at.set(p.normalImpulse, together ? total : old);
            at.set(p.deliveredNormal, together ? delivered + delta : delivered);
            at.set(p.maxNormalImpulse, together ? maxOf(most, total) : most);
        }
    if (anyRubs) {
        const V tx = at(k.tangentX), ty = at(k.tangentY), friction = at(k.friction), belt = at(k.tangentSpeed);
        for (int j = 0; j < s.count; ++j) {
            RigidBlockPoint& p = k.points[j];
            const bool all = at.all(k.rubbingLanes[j]);
            const MaskOf<V> has = at.mask(k.rubbingMask[j]);
            const V rAx = at(p.armAx), rAy = at(p.armAy), rBx = at(p.armBx), rBy = at(p.armBy);
            const V vt = alongPoint(a, b, rAx, rAy, rBx, rBy, tx, ty) + belt;
            const V limit = friction * at(p.normalImpulse);
            const V old = at(p.tangentImpulse);
            const V total = minOf(maxOf(old - at(p.tangentMass) * vt, -limit), limit);
            const V delta = total - old;
            const V px = tx * delta, py = ty * delta;
            a.template apply<true>(all, has, rAx, rAy, px, py);
            b.apply(all, has, rBx, rBy, px, py);
            // A lane without friction keeps its impulses as the scalar sweep leaves them.
            const V delivered = at(p.deliveredTangent);
            at.set(p.tangentImpulse, has ? total : old);
            at.set(p.deliveredTangent, has ? delivered + delta : delivered);
        }
    }
    for (int i = 0; i < W; ++i) {
        if (at.lane(k.writesA, i)) a.store(*s.a[i], i);
        if (at.lane(k.writesB, i)) b.store(*s.b[i], i);
    }
}

} // namespace rube

#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
