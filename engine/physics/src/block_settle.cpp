// Lecture 3's "try to correct overlapping positions, resolve collisions" for blocks: the discrete
// method's push-out, and the exact method's end-of-step settle of resting blocks.
#include "block_pairs.hpp"

#include "resolve.hpp"
#include "step_method.hpp"

#include <algorithm>
#include <tuple>

namespace rube {

namespace {

// Passes of the settle; it stops once nothing overlaps more than kSettledDepth (as the circles' settle).
constexpr int kSettlePasses = 16;
constexpr double kSettledDepth = 1e-12;
// A contact holds a body up when its normal has a real component against gravity (not a vertical wall).
constexpr double kSupportSine = 1e-6;

// A block's contact at the end of a step, in the order the settle takes them.
struct BlockContact {
    double height = 0.0; ///< of the contact point against gravity: the settle goes from the ground up
    int block = -1;
    Other kind = Other::body;
    int other = -1;
    Vec2 side; ///< a segment face's side
};

// What a block overlaps of its partner now; nothing when they do not.
std::optional<Overlap> overlapOf(const StepContext& ctx, const RigidBody& b, Other kind, int other, Vec2 side,
                                 double slop) {
    const Vec2 half = b.halfExtents + Vec2{slop, slop};
    if (kind == Other::circle) {
        const Circle& c = ctx.circles[other];
        return blockCircleOverlap(b.position, half, c.position, c.radius);
    }
    if (kind == Other::body) {
        const RigidBody& o = ctx.bodies[other];
        return blockBlockOverlap(b.position, half, o.position, o.halfExtents);
    }
    const Segment& s = ctx.segments[other];
    return blockSegmentOverlapOnSide(b.position, half, s.a, s.b, s.radius, side);
}

// Pushes block i and its partner apart along the overlap's normal, split by inverse mass, and resolves
// their approach with C (0 when resting). Returns the approach speed before.
double separate(StepContext& ctx, int i, Other kind, int other, const Overlap& overlap, double inverseMassBlock,
                double inverseMassOther, double bounciness) {
    RigidBody& b = ctx.bodies[i];
    const BlockPartner partner = blockPartner(ctx, kind, other);
    Vec2 otherPosition = kind == Other::circle ? ctx.circles[other].position
                         : kind == Other::body ? ctx.bodies[other].position
                                               : Vec2{};
    Vec2 otherVelocity = partner.velocity;
    pushApart(b.position, inverseMassBlock, otherPosition, inverseMassOther, overlap.normal, overlap.depth);
    const double approach = resolveImpact(b.velocity, inverseMassBlock, otherVelocity, inverseMassOther, overlap.normal,
                                          bounciness);
    if (partner.dynamic && kind == Other::circle) {
        ctx.circles[other].position = otherPosition;
        ctx.circles[other].velocity = otherVelocity;
    } else if (partner.dynamic && kind == Other::body) {
        ctx.bodies[other].position = otherPosition;
        ctx.bodies[other].velocity = otherVelocity;
    }
    return approach;
}

// Calls visit(kind, other, side) for every partner block i may touch: segments (dynamic blocks only),
// then blocks of a higher index, then circles; pairs with no dynamic body are left out.
template <class Visit>
void forEachPartner(const StepContext& ctx, int i, Visit visit) {
    const RigidBody& b = ctx.bodies[i];
    const bool dynamic = b.motion == Motion::dynamic;
    if (dynamic)
        for (int k = 0; k < static_cast<int>(ctx.segments.size()); ++k) visit(Other::segment, k);
    for (int j = i + 1; j < static_cast<int>(ctx.bodies.size()); ++j)
        if (isBlock(ctx.bodies[j]) && (dynamic || ctx.bodies[j].motion == Motion::dynamic)) visit(Other::body, j);
    for (int j = 0; j < static_cast<int>(ctx.circles.size()); ++j)
        if (dynamic || ctx.circles[j].motion == Motion::dynamic) visit(Other::circle, j);
}

} // namespace

int separateBlockOverlaps(StepContext& ctx, std::span<const Vec2> startCentres, double sideDelay, double time) {
    int count = 0;
    for (int i = 0; i < static_cast<int>(ctx.bodies.size()); ++i) {
        if (!isBlock(ctx.bodies[i])) continue;
        forEachPartner(ctx, i, [&](Other kind, int other) {
            const RigidBody& b = ctx.bodies[i];
            Vec2 side;
            if (kind == Other::segment) {
                // The side the centre started on (the segment moved back to where it was then): a block
                // is pushed back the way it came, so it tunnels only past speed x dt = 2 (reach + radius).
                Segment before = ctx.segments[other];
                before.a -= before.velocity * sideDelay;
                before.b -= before.velocity * sideDelay;
                side = segmentSide(before, startCentres[i]);
            }
            const std::optional<Overlap> overlap = overlapOf(ctx, b, kind, other, side, 0.0);
            if (!overlap) return;
            const BlockPartner partner = blockPartner(ctx, kind, other);
            const double approach = separate(ctx, i, kind, other, *overlap, b.inverseMass, partner.inverseMass,
                                             pairBounciness(b.material, partner.material));
            const Other reported = kind == Other::segment && overlap->normal != side ? Other::segmentCap : kind;
            ctx.impacts.push_back(
                Impact{-1, reported, other, time, overlap->point, overlap->normal, std::max(approach, 0.0), i});
            ++ctx.stats.impacts;
            ++count;
        });
    }
    return count;
}

void settleBlockContacts(StepContext& ctx, double slop, std::span<const BlockPair> resting) {
    std::vector<BlockContact> contacts;
    const Vec2 up = -ctx.def.gravity.normalized();
    for (int i = 0; i < static_cast<int>(ctx.bodies.size()); ++i) {
        if (!isBlock(ctx.bodies[i])) continue;
        forEachPartner(ctx, i, [&](Other kind, int other) {
            const RigidBody& b = ctx.bodies[i];
            Vec2 side;
            if (kind == Other::segment) {
                // A resting block keeps the side it came from.
                const auto rest = std::find_if(resting.begin(), resting.end(), [&](const BlockPair& p) {
                    return p.block == i && p.kind == Other::segment && p.other == other;
                });
                side = rest != resting.end() ? rest->side : segmentSide(ctx.segments[other], b.position);
            }
            if (const auto overlap = overlapOf(ctx, b, kind, other, side, slop))
                contacts.push_back(BlockContact{overlap->point.dot(up), i, kind, other, side});
        });
    }
    if (contacts.empty()) return;
    // From the ground up; ties in index order, so the order is the same on every run.
    std::sort(contacts.begin(), contacts.end(), [](const BlockContact& x, const BlockContact& y) {
        return std::tie(x.height, x.block, x.kind, x.other) < std::tie(y.height, y.block, y.kind, y.other);
    });
    for (int pass = 0; pass < kSettlePasses; ++pass) {
        double deepest = 0.0;
        for (const BlockContact& contact : contacts) {
            const RigidBody& b = ctx.bodies[contact.block];
            const std::optional<Overlap> overlap = overlapOf(ctx, b, contact.kind, contact.other, contact.side, 0.0);
            if (!overlap) continue;
            const BlockPartner partner = blockPartner(ctx, contact.kind, contact.other);
            const bool isResting = approachSpeed(b.velocity, partner.velocity, overlap->normal) < ctx.restingSpeed;
            double inverseMassBlock = b.inverseMass, inverseMassOther = partner.inverseMass;
            if (isResting && partner.dynamic) {
                // The body below holds still, as if of infinite mass, against the one it carries.
                const double along = overlap->normal.dot(up);
                if (along > kSupportSine) inverseMassOther = 0.0;
                else if (along < -kSupportSine) inverseMassBlock = 0.0;
            }
            if (inverseMassBlock == 0.0 && inverseMassOther == 0.0) inverseMassOther = partner.inverseMass;
            separate(ctx, contact.block, contact.kind, contact.other, *overlap, inverseMassBlock, inverseMassOther,
                     isResting ? 0.0 : pairBounciness(b.material, partner.material));
            deepest = std::max(deepest, overlap->depth);
        }
        if (deepest <= kSettledDepth) break;
    }
}

} // namespace rube
