// Lecture 3's blocks in the event-driven methods: the earliest impact of a block against everything
// else, Newton's resolve along the axis (or normal) of impact, and the blocks' motion between events.
#include "block_pairs.hpp"

#include "resolve.hpp"
#include "step_method.hpp"

#include <algorithm>

namespace rube {

namespace {

bool isDynamic(Motion m) { return m == Motion::dynamic; }

bool isResting(std::span<const BlockPair> resting, int block, Other kind, int other) {
    return std::any_of(resting.begin(), resting.end(),
                       [&](const BlockPair& p) { return p.block == block && p.kind == kind && p.other == other; });
}

} // namespace

BlockEvent earliestBlockImpact(const StepContext& ctx, int i, const BlockSearch& search) {
    BlockEvent best;
    const RigidBody& b = ctx.bodies[i];
    const bool dynamic = isDynamic(b.motion);
    const Vec2 acceleration = dynamic ? search.gravity : Vec2{};
    const auto consider = [&](const std::optional<Collision>& hit, Other kind, int other) {
        if (hit && hit->timeOfImpact < best.time)
            best = BlockEvent{hit->timeOfImpact, i, kind, other, hit->normal, hit->contactPoint};
    };
    // A held-still other (turn-based) contributes no velocity unless a script moves it.
    const auto otherVelocity = [&](Vec2 v, Motion m) {
        return search.othersStandStill && m != Motion::kinematic ? Vec2{} : v;
    };
    if (dynamic) {
        // Only a dynamic block can hit a segment: both others have infinite mass.
        for (int k = 0; k < static_cast<int>(ctx.segments.size()); ++k) {
            const Segment& s = ctx.segments[k];
            if (isResting(search.resting, i, Other::segment, k)) continue;
            const BlockMotion motion{b.position, b.velocity - s.velocity, b.halfExtents, acceleration};
            const auto hit = blockSegmentCollision(motion, s.a, s.b, s.radius, search.horizon);
            consider(hit, hit && hit->lineCap ? Other::segmentCap : Other::segment, k);
        }
    }
    for (int j = 0; j < static_cast<int>(ctx.circles.size()); ++j) {
        const Circle& c = ctx.circles[j];
        const bool dynamicOther = isDynamic(c.motion);
        if ((!dynamic && !dynamicOther) || isResting(search.resting, i, Other::circle, j)) continue;
        // Relative motion: two falling bodies share gravity, so between them it cancels.
        const Vec2 relativeAcceleration = acceleration - (dynamicOther ? search.gravity : Vec2{});
        const BlockMotion motion{b.position, b.velocity - otherVelocity(c.velocity, c.motion), b.halfExtents,
                                 relativeAcceleration};
        consider(blockCircleCollision(motion, c.position, c.radius, search.horizon), Other::circle, j);
    }
    for (int j = search.eachPairOnce ? i + 1 : 0; j < static_cast<int>(ctx.bodies.size()); ++j) {
        const RigidBody& o = ctx.bodies[j];
        const bool dynamicOther = isDynamic(o.motion);
        if (j == i || !isBlock(o) || (!dynamic && !dynamicOther) || isResting(search.resting, i, Other::body, j))
            continue;
        const Vec2 relativeAcceleration = acceleration - (dynamicOther ? search.gravity : Vec2{});
        const BlockMotion motion{b.position, b.velocity - otherVelocity(o.velocity, o.motion), b.halfExtents,
                                 relativeAcceleration};
        consider(blockBlockCollision(motion, o.position, o.halfExtents, search.horizon), Other::body, j);
    }
    return best;
}

BlockPartner blockPartner(const StepContext& ctx, Other kind, int other) {
    if (kind == Other::circle) {
        const Circle& c = ctx.circles[other];
        return {c.velocity, c.inverseMass, c.material, isDynamic(c.motion)};
    }
    if (kind == Other::body) {
        const RigidBody& o = ctx.bodies[other];
        return {o.velocity, o.inverseMass, o.material, isDynamic(o.motion)};
    }
    const Segment& s = ctx.segments[other];
    return {s.velocity, 0.0, s.material, false};
}

double resolveBlockImpact(StepContext& ctx, const BlockEvent& event, double time, bool resting, bool record) {
    RigidBody& b = ctx.bodies[event.block];
    const BlockPartner partner = blockPartner(ctx, event.kind, event.other);
    Vec2 otherVelocity = partner.velocity;
    // v' = u - C (v - u) on the normal's component, u the centre of mass's (lecture 3); for a block
    // against a block or a face the normal is an axis, so this is the lecture's x- or y-only rule.
    const double approach = resolveImpact(b.velocity, b.inverseMass, otherVelocity, partner.inverseMass, event.normal,
                                          resting ? 0.0 : pairBounciness(b.material, partner.material));
    if (partner.dynamic) {
        if (event.kind == Other::circle) ctx.circles[event.other].velocity = otherVelocity;
        else ctx.bodies[event.other].velocity = otherVelocity;
    }
    if (record) {
        ctx.impacts.push_back(Impact{-1, event.kind, event.other, time, event.contactPoint, event.normal,
                                     std::max(approach, 0.0), event.block});
        ++ctx.stats.impacts;
    }
    return approach;
}

void advanceBlocks(StepContext& ctx, double t) {
    if (t <= 0.0) return;
    const Vec2 g = ctx.def.gravity;
    for (RigidBody& b : ctx.bodies) {
        if (!isBlock(b)) continue;
        if (b.motion == Motion::dynamic) {
            b.position += b.velocity * t + g * (0.5 * t * t); // p + v t + g t^2 / 2
            b.velocity += g * t;
        } else if (b.motion == Motion::kinematic) {
            b.position += b.velocity * t;
        }
    }
}

} // namespace rube
