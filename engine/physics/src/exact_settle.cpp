// The exact method's end-of-step settle (exact_settle.hpp).
#include "exact_settle.hpp"

#include "resolve.hpp"

#include "rube/physics/collision.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <tuple>

namespace rube {

namespace {

// Passes over the contacts at the end of a step. Ordered from the ground up, one pass settles a
// stack; more are needed only where a body rests on two others. Stops once nothing overlaps more
// than kSettledDepth.
constexpr int kSettlePasses = 16;
constexpr double kSettledDepth = 1e-12;

// A contact supports when its normal has a real component against gravity; a vertical wall does not
// (with its normal off horizontal only by rounding).
constexpr double kSupportSine = 1e-6;

// The settle's resting threshold for a pair: the world's (2 |g| dt + 1e-3 unless set), or as much
// for the acceleration a spring gives a circle of the pair, |omega^2 (p - x_eq) + 2 zeta omega v|,
// which may be far above g: a spring-held ball resting on the floor (its pair left out of the
// search) sinks |a| dt^2 / 2 within the step and must be settled at rest, not bounced off with the
// speed the spring gave it. A magnet's pull likewise, with gravity: |g + a| (a ball the magnet holds
// from below sinks into it by |g + a| dt^2 / 2 in the step). Impacts within the step keep the
// world's: they are real approaches.
double restingSpeedOf(const StepContext& ctx, const ExactSprings& springs, const MagnetPulls& pulls, double dt, int i,
                      int j) {
    double speed = ctx.restingSpeed;
    if (!pulls.empty())
        for (const int k : {i, j})
            if (k >= 0) speed = std::max(speed, pulls.restingSpeed(static_cast<std::size_t>(k), ctx.def.gravity, dt));
    if (springs.empty()) return speed;
    for (const int k : {i, j}) {
        const SpringPath* path = k >= 0 ? springs.pathOf(k) : nullptr;
        if (!path) continue;
        const Circle& c = ctx.circles[static_cast<std::size_t>(k)];
        const Vec2 a = (c.position - path->equilibrium) * (path->omega * path->omega) +
                       c.velocity * (2.0 * path->zeta * path->omega);
        speed = std::max(speed, 2.0 * a.length() * dt + 1e-3);
    }
    return speed;
}

} // namespace

void ExactSettle::settle(StepContext& ctx, double dt, const RestingPairs& resting, const ExactSprings& springs,
                         std::vector<BlockPair>& blockResting, const MagnetPulls& pulls) {
    collectContacts(ctx, ctx.restingSpeed * dt, resting);
    if (!ctx.bodies.empty()) settleBlockContacts(ctx, ctx.restingSpeed * dt, blockResting);
    if (contacts_.empty()) return;
    orderFromTheGroundUp(ctx);
    for (int pass = 0; pass < kSettlePasses; ++pass) {
        double deepest = 0.0;
        for (const Contact& contact : contacts_) deepest = std::max(deepest, settle(ctx, contact, springs, pulls, dt));
        if (deepest <= kSettledDepth) break;
    }
}

// Every pair closer than `slop` (what a resting approach covers in a step): the settle may push
// a body into a neighbour it was only touching, as a stack's lowest ball into the one above it.
void ExactSettle::collectContacts(const StepContext& ctx, double slop, const RestingPairs& resting) {
    const int circleCount = static_cast<int>(ctx.circles.size());
    contacts_.clear();
    for (int i = 0; i < circleCount; ++i) {
        const Circle& c = ctx.circles[i];
        if (c.motion != Motion::dynamic) continue;
        for (int j = 0; j < circleCount; ++j) {
            const Circle& o = ctx.circles[j];
            if (j == i || (o.motion == Motion::dynamic && j < i)) continue;
            if (circleCircleOverlap(c.position, c.radius + slop, o.position, o.radius))
                contacts_.push_back(Contact{i, Other::circle, j, {}});
        }
        for (int k = 0; k < static_cast<int>(ctx.segments.size()); ++k) {
            const Segment& s = ctx.segments[k];
            // A resting circle keeps the side it came from, even if its centre sank past the line.
            const std::uint8_t state = resting.state(i, Other::segment, k);
            const Vec2 lineNormal = (s.b - s.a).normal();
            const Vec2 side = state == kRestingPlus    ? lineNormal
                              : state == kRestingMinus ? -lineNormal
                                                       : segmentSide(s, c.position);
            if (circleSegmentOverlapOnSide(c.position, c.radius + slop, s, side))
                contacts_.push_back(Contact{i, Other::segment, k, side});
        }
    }
}

// Level 0: held up by something of infinite mass; level n + 1: held up by a body of level n.
// Only contacts against gravity count: a ball squeezed between two walls is not on the ground,
// and two infinite masses pushing one body from both sides would never settle.
void ExactSettle::orderFromTheGroundUp(const StepContext& ctx) {
    constexpr int kFloating = std::numeric_limits<int>::max();
    const Vec2 down = ctx.def.gravity.normalized();
    levels_.assign(ctx.circles.size(), kFloating);
    for (Contact& contact : contacts_) {
        const Circle& c = ctx.circles[contact.circle];
        const Vec2 below = contact.kind == Other::circle
                               ? ctx.circles[contact.other].position
                               : closestPointOnSegment(c.position, ctx.segments[contact.other].a,
                                                       ctx.segments[contact.other].b);
        const Vec2 up = (c.position - below).normalized(); // from the other towards the circle
        const double along = up.dot(down);
        contact.support = along < -kSupportSine ? 1 : along > kSupportSine ? -1 : 0;
        const bool ground = contact.kind != Other::circle || ctx.circles[contact.other].motion != Motion::dynamic;
        if (ground && contact.support > 0) levels_[contact.circle] = 0;
    }
    // Bellman-Ford over the contacts: one round per level of the tallest stack.
    for (bool changed = true; changed;) {
        changed = false;
        for (const Contact& contact : contacts_) {
            if (contact.kind != Other::circle || ctx.circles[contact.other].motion != Motion::dynamic) continue;
            int& lower = contact.support > 0 ? levels_[contact.other] : levels_[contact.circle];
            int& upper = contact.support > 0 ? levels_[contact.circle] : levels_[contact.other];
            if (contact.support != 0 && lower != kFloating && lower + 1 < upper) upper = lower + 1, changed = true;
        }
    }
    // Lower pairs first; ties in index order, so the order is the same on every run.
    const auto key = [&](const Contact& c) {
        const bool dynamicOther = c.kind == Other::circle && ctx.circles[c.other].motion == Motion::dynamic;
        const int lower = dynamicOther ? std::min(levels_[c.circle], levels_[c.other]) : -1;
        return std::make_tuple(lower, c.circle, static_cast<int>(c.kind), c.other);
    };
    std::sort(contacts_.begin(), contacts_.end(), [&](const Contact& x, const Contact& y) { return key(x) < key(y); });
}

// Pushes one contact apart and stops a resting approach (C = 0); returns the overlap removed.
double ExactSettle::settle(StepContext& ctx, const Contact& contact, const ExactSprings& springs,
                           const MagnetPulls& pulls, double dt) const {
    Circle& c = ctx.circles[contact.circle];
    std::optional<Overlap> overlap;
    Vec2 otherPosition, otherVelocity;
    double inverseMassC = c.inverseMass, inverseMassO = 0.0, bounciness = 0.0;
    Circle* dynamicOther = nullptr;
    if (contact.kind == Other::circle) {
        Circle& o = ctx.circles[contact.other];
        overlap = circleCircleOverlap(c.position, c.radius, o.position, o.radius);
        otherPosition = o.position;
        otherVelocity = o.velocity;
        inverseMassO = o.inverseMass;
        bounciness = pairBounciness(c.material, o.material);
        if (o.motion == Motion::dynamic) dynamicOther = &o;
    } else {
        const Segment& s = ctx.segments[contact.other];
        const auto hit = circleSegmentOverlapOnSide(c.position, c.radius, s, contact.side);
        if (hit) overlap = hit->overlap;
        otherVelocity = hit ? s.velocityAt(hit->overlap.point) : s.velocity;
        bounciness = pairBounciness(c.material, s.material);
    }
    if (!overlap) return 0.0;
    const bool isResting = approachSpeed(c.velocity, otherVelocity, overlap->normal) <
                           restingSpeedOf(ctx, springs, pulls, dt, contact.circle, dynamicOther ? contact.other : -1);
    if (dynamicOther && isResting) {
        // The body holding the other up, nearer the ground, holds still as if of infinite mass.
        const int levelC = levels_[contact.circle], levelO = levels_[contact.other];
        if (contact.support < 0 && levelC < levelO) inverseMassC = 0.0;
        if (contact.support > 0 && levelO < levelC) inverseMassO = 0.0;
    }
    pushApart(c.position, inverseMassC, otherPosition, inverseMassO, overlap->normal, overlap->depth);
    resolveImpact(c.velocity, inverseMassC, otherVelocity, inverseMassO, overlap->normal, isResting ? 0.0 : bounciness);
    if (dynamicOther) {
        dynamicOther->position = otherPosition;
        dynamicOther->velocity = otherVelocity;
    }
    return overlap->depth;
}

} // namespace rube
