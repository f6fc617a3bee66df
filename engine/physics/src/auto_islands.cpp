// auto's islands: who could meet whom within the step (see auto_islands.hpp). The solver's uniform
// grid finds the overlapping boxes in O(n + pairs), so a pile of a thousand balls pays about what
// the solver's own broadphase does, not a million box tests.
#include "auto_islands.hpp"

#include "exact_springs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rube {
namespace {

/// Grid cells this much wider than the typical neighbourhood box, so that box fits one cell.
constexpr double kCellPerSpan = 1.1;

// The box of p + v t + a t^2 / 2 over t in [0, dt]: its ends, and on each axis the turning point
// t* = -v / a where the parabola reverses, when that falls within the step.
BoundingBox parabolaBox(Vec2 p, Vec2 v, Vec2 a, double dt) {
    const Vec2 end = p + v * dt + a * (0.5 * dt * dt);
    BoundingBox box{{std::min(p.x, end.x), std::min(p.y, end.y)}, {std::max(p.x, end.x), std::max(p.y, end.y)}};
    const auto turn = [&](double p0, double v0, double a0, double& lo, double& hi) {
        if (a0 == 0.0) return;
        const double t = -v0 / a0;
        if (!(t > 0.0 && t < dt)) return;
        const double extreme = p0 + v0 * t + 0.5 * a0 * t * t;
        lo = std::min(lo, extreme);
        hi = std::max(hi, extreme);
    };
    turn(p.x, v.x, a.x, box.min.x, box.max.x);
    turn(p.y, v.y, a.y, box.min.y, box.max.y);
    return box;
}

BoundingBox fattened(BoundingBox box, double by) {
    box.min -= Vec2{by, by};
    box.max += Vec2{by, by};
    return box;
}

BoundingBox sweptPoints(Vec2 a, Vec2 b, Vec2 motion) {
    const Vec2 a1 = a + motion, b1 = b + motion;
    return {{std::min({a.x, b.x, a1.x, b1.x}), std::min({a.y, b.y, a1.y, b1.y})},
            {std::max({a.x, b.x, a1.x, b1.x}), std::max({a.y, b.y, a1.y, b1.y})}};
}

// Where a segment's surface may be during the step: a turning one anywhere on the disc its ends
// sweep about the pivot, a translating one between its start and end.
BoundingBox segmentReach(const Segment& s, double dt) {
    if (s.angularVelocity != 0.0) {
        const Vec2 pivot = lerp(s.a, s.b, s.pivotAlong);
        const double arm = std::max(pivot.distance(s.a), pivot.distance(s.b)) + s.radius;
        return fattened(sweptPoints(pivot, pivot, s.velocity * dt), arm);
    }
    return fattened(sweptPoints(s.a, s.b, s.velocity * dt), s.radius);
}

} // namespace

int AutoIslands::find(std::vector<int>& parent, int node) {
    int root = node;
    while (parent[static_cast<std::size_t>(root)] != root) root = parent[static_cast<std::size_t>(root)];
    while (parent[static_cast<std::size_t>(node)] != root) {
        const int next = parent[static_cast<std::size_t>(node)];
        parent[static_cast<std::size_t>(node)] = root;
        node = next;
    }
    return root;
}

void AutoIslands::join(std::vector<int>& parent, int a, int b) {
    a = find(parent, a);
    b = find(parent, b);
    if (a == b) return;
    // The lower index is the root, so an island is named by its lowest node whatever the join order.
    if (a < b) parent[static_cast<std::size_t>(b)] = a;
    else parent[static_cast<std::size_t>(a)] = b;
}

void AutoIslands::build(const StepContext& ctx, double dt) {
    const std::span<const Rope> ropes = ctx.ropes;
    const int circleCount = static_cast<int>(ctx.circles.size());
    const int nodeCount = circleCount + static_cast<int>(ctx.bodies.size());
    const Vec2 g = ctx.def.gravity;
    // Exact settles pairs closer than this at the end of a step (its resting slop): they must share an island.
    const double slop = ctx.restingSpeed * dt;
    parent_.resize(static_cast<std::size_t>(nodeCount));
    looseParent_.resize(static_cast<std::size_t>(nodeCount));
    sizes_.resize(static_cast<std::size_t>(nodeCount));
    boxes_.resize(static_cast<std::size_t>(nodeCount));
    isNode_.assign(static_cast<std::size_t>(nodeCount), 0);
    friction_.assign(static_cast<std::size_t>(nodeCount), 0);
    needs_.assign(static_cast<std::size_t>(nodeCount), 0);
    order_.clear();
    frictionShared_.clear();
    for (int i = 0; i < nodeCount; ++i)
        parent_[static_cast<std::size_t>(i)] = looseParent_[static_cast<std::size_t>(i)] = i;

    // A circle on a spring to a fixed point with a closed form is exact's (exact_springs.hpp); its
    // reach is a disc of its speed bound (the parabola box does not hold a spring's path). Two
    // springs on one circle are the solver's.
    springReach_.assign(static_cast<std::size_t>(circleCount), -1.0);
    for (const Joint& j : ctx.joints) {
        const int i = springCircle(j);
        if (i < 0 || i >= circleCount || !exactSpringRefusal(j, ctx.circles, g, !ctx.bodies.empty()).empty()) continue;
        const Circle& c = ctx.circles[static_cast<std::size_t>(i)];
        if (c.motion != Motion::dynamic || c.inverseMass <= 0.0) continue;
        double& reach = springReach_[static_cast<std::size_t>(i)];
        reach = reach >= 0.0 ? std::numeric_limits<double>::infinity()
                             : springSpeedBound(springPathOf(j, c, g), c.position, c.velocity) * dt;
    }
    for (int i = 0; i < circleCount; ++i) {
        const Circle& c = ctx.circles[static_cast<std::size_t>(i)];
        if (c.motion != Motion::dynamic) {
            if (c.material.friction > 0.0)
                frictionShared_.push_back(fattened(sweptPoints(c.position, c.position, c.velocity * dt), c.radius));
            continue;
        }
        const auto n = static_cast<std::size_t>(i);
        isNode_[n] = 1;
        friction_[n] = c.material.friction > 0.0;
        const double spring = springReach_[n];
        boxes_[n] = spring >= 0.0 && std::isfinite(spring)
                        ? fattened(BoundingBox{c.position, c.position}, c.radius + 2.0 * spring + slop)
                        : fattened(parabolaBox(c.position, c.velocity, g, dt),
                                   c.radius + c.velocity.length() * dt + slop);
        sizes_[n] = c.radius;
        order_.push_back(i);
    }
    for (std::size_t b = 0; b < ctx.bodies.size(); ++b) {
        const RigidBody& body = ctx.bodies[b];
        const auto n = static_cast<std::size_t>(circleCount) + b;
        isNode_[n] = 1;
        const bool dynamic = body.motion == Motion::dynamic;
        const BoundingBox path = parabolaBox(body.position, body.velocity, dynamic ? g : Vec2{}, dt);
        boxes_[n] = fattened(path, boundingRadius(body) + body.velocity.length() * dt + slop);
        sizes_[n] = boundingRadius(body);
        // Exact moves lecture 3's blocks only: a turning body needs the solver if it can move at all.
        needs_[n] = !isBlock(body) && body.motion != Motion::fixed;
        order_.push_back(static_cast<int>(n));
    }
    for (const Pivot& p : ctx.pivots)
        if (p.body >= 0 && static_cast<std::size_t>(p.body) < ctx.bodies.size())
            needs_[static_cast<std::size_t>(circleCount + p.body)] = 1;
    for (const Segment& s : ctx.segments)
        if (s.material.friction > 0.0) frictionShared_.push_back(segmentReach(s, dt));

    // The solver's uniform grid over the neighbourhood boxes (which hold the reach boxes) finds the
    // overlapping pairs in O(n): cells a little wider than the typical box, each box's span counted
    // at most at four sizes, so a few bullets do not blow the cells up. Pairs come out in index
    // order, so the islands are the same on every machine.
    looseBoxes_.clear();
    double spanSum = 0.0;
    constexpr double inf = std::numeric_limits<double>::infinity();
    BoundingBox region{{inf, inf}, {-inf, -inf}};
    // A body whose state is not finite (a NaN) stays out of the grid, an island of its own: its box
    // would poison the cells of every other.
    std::erase_if(order_, [&](int node) {
        const BoundingBox& box = boxes_[static_cast<std::size_t>(node)];
        return !isFinite(box.min) || !isFinite(box.max) || !std::isfinite(sizes_[static_cast<std::size_t>(node)]);
    });
    for (const int node : order_) {
        const auto n = static_cast<std::size_t>(node);
        const BoundingBox near = fattened(boxes_[n], sizes_[n]);
        looseBoxes_.push_back(near);
        spanSum += std::min(std::max(near.max.x - near.min.x, near.max.y - near.min.y), 8.0 * sizes_[n]);
        region.min = {std::min(region.min.x, near.min.x), std::min(region.min.y, near.min.y)};
        region.max = {std::max(region.max.x, near.max.x), std::max(region.max.y, near.max.y)};
    }
    if (order_.size() > 1) {
        const double cellSize = std::max(kCellPerSpan * spanSum / static_cast<double>(order_.size()), 1e-9);
        // Within the world's bounds: escaped bodies are clamped into the grid's border cells.
        const BoundingBox bounds{ctx.def.bounds.min - Vec2{cellSize, cellSize},
                                 ctx.def.bounds.max + Vec2{cellSize, cellSize}};
        const BoundingBox clipped{{std::max(region.min.x, bounds.min.x), std::max(region.min.y, bounds.min.y)},
                                  {std::min(region.max.x, bounds.max.x), std::min(region.max.y, bounds.max.y)}};
        if (clipped.min.x <= clipped.max.x && clipped.min.y <= clipped.max.y) region = clipped;
        // Asleep circles and rigid bodies only wait to be found: two of them were joined when they fell asleep
        // together (below), and two sleeping islands apart have nothing to tell each other. A
        // sleeping pile then costs what its awake visitors look at.
        looks_.resize(order_.size());
        for (std::size_t k = 0; k < order_.size(); ++k) {
            const int node = order_[k];
            looks_[k] = node >= circleCount ? !ctx.bodies[static_cast<std::size_t>(node - circleCount)].sleep.asleep
                                            : !ctx.circles[static_cast<std::size_t>(node)].sleep.asleep;
        }
        grid_.build(looseBoxes_, {}, region, cellSize, 4 * static_cast<int>(order_.size()) + 64);
        grid_.findPairs(looseBoxes_, {}, looks_, pairs_);
        for (const CandidatePair& pair : pairs_) {
            const int a = order_[static_cast<std::size_t>(pair.circle)],
                      b = order_[static_cast<std::size_t>(pair.other)];
            join(looseParent_, a, b);
            if (boxes_[static_cast<std::size_t>(a)].overlaps(boxes_[static_cast<std::size_t>(b)])) join(parent_, a, b);
        }
    }
    const auto joinBoth = [&](int a, int b) {
        join(parent_, a, b);
        join(looseParent_, a, b);
    };
    // Roped circles, and circles and rigid bodies the solver put to sleep together (they wake together).
    const auto dynamicCircle = [&](int i) {
        return i >= 0 && i < circleCount && ctx.circles[static_cast<std::size_t>(i)].motion == Motion::dynamic;
    };
    for (const Rope& rope : ropes)
        if (!rope.cut && dynamicCircle(rope.circle) && dynamicCircle(rope.other)) joinBoth(rope.circle, rope.other);
    // An island is named by a circle's index, or by -1 - a rigid body's when it has no circle
    // (solver_sleep.hpp): the whole sleeping island, joints and all, wakes and goes to one method.
    const auto sleepNode = [&](int island) {
        if (island >= 0) return dynamicCircle(island) ? island : -1;
        const int body = -1 - island;
        return body < static_cast<int>(ctx.bodies.size()) ? circleCount + body : -1;
    };
    for (int i = 0; i < circleCount; ++i) {
        const Circle& c = ctx.circles[static_cast<std::size_t>(i)];
        if (c.motion != Motion::dynamic || !c.sleep.asleep) continue;
        if (const int n = sleepNode(c.sleep.island); n >= 0) joinBoth(i, n);
    }
    for (std::size_t b = 0; b < ctx.bodies.size(); ++b) {
        const RigidBody& body = ctx.bodies[b];
        if (!body.sleep.asleep) continue;
        if (const int n = sleepNode(body.sleep.island); n >= 0) joinBoth(circleCount + static_cast<int>(b), n);
    }
    // Joints are the solver's: a jointed body needs it, and a joint's two ends share an island (a
    // gear's and a belt's wheels are tied through their revolutes' ends). Only a spring to a fixed
    // point with a closed form is exact's (its reach above).
    const auto jointNode = [&](int circle, int body) {
        return body >= 0 ? circleCount + body : dynamicCircle(circle) ? circle : -1;
    };
    for (const Joint& j : ctx.joints) {
        const int held = springCircle(j);
        if (held >= 0 && held < circleCount && j.bodyA < 0 && j.bodyB < 0 &&
            std::isfinite(springReach_[static_cast<std::size_t>(held)]) &&
            springReach_[static_cast<std::size_t>(held)] >= 0.0)
            continue;
        const int a = jointNode(j.circleA, j.bodyA), b = jointNode(j.circleB, j.bodyB);
        if (a >= 0) needs_[static_cast<std::size_t>(a)] = 1;
        if (b >= 0) needs_[static_cast<std::size_t>(b)] = 1;
        if (a >= 0 && b >= 0) joinBoth(a, b);
    }
    // Friction needs two surfaces with friction (a pair's is the product): a circle with friction
    // that may reach a shared shape with friction.
    for (int i = 0; i < circleCount; ++i) {
        if (!friction_[static_cast<std::size_t>(i)]) continue;
        const BoundingBox& box = boxes_[static_cast<std::size_t>(i)];
        if (std::any_of(frictionShared_.begin(), frictionShared_.end(),
                        [&](const BoundingBox& s) { return s.overlaps(box); }))
            needs_[static_cast<std::size_t>(i)] = 1;
    }

    // Islands in order of their lowest node (the root), members in index order.
    islandOf_.assign(static_cast<std::size_t>(nodeCount), -1);
    islands_.clear();
    frictionCircles_.clear();
    nonBlocks_.clear();
    for (int n = 0; n < nodeCount; ++n) {
        if (!isNode_[static_cast<std::size_t>(n)]) continue;
        const int root = find(parent_, n);
        if (root == n) {
            islandOf_[static_cast<std::size_t>(n)] = static_cast<int>(islands_.size());
            islands_.push_back(Island{});
            islands_.back().neighbourhood = find(looseParent_, n);
            frictionCircles_.push_back(0);
            nonBlocks_.push_back(0);
        } else {
            islandOf_[static_cast<std::size_t>(n)] = islandOf_[static_cast<std::size_t>(root)];
        }
        const auto k = static_cast<std::size_t>(islandOf_[static_cast<std::size_t>(n)]);
        Island& island = islands_[k];
        ++island.count;
        const bool dynamic = n < circleCount ||
                             ctx.bodies[static_cast<std::size_t>(n - circleCount)].motion == Motion::dynamic;
        if (dynamic) ++island.dynamicBodies;
        if (needs_[static_cast<std::size_t>(n)]) island.needsSolver = true;
        if (friction_[static_cast<std::size_t>(n)] && ++frictionCircles_[k] > 1) island.needsSolver = true;
        if (n >= circleCount && !isBlock(ctx.bodies[static_cast<std::size_t>(n - circleCount)])) nonBlocks_[k] = 1;
    }
    // Exact sees lecture 3's blocks only: a body near any other shape, fixed or not, is the solver's.
    for (std::size_t k = 0; k < islands_.size(); ++k)
        if (nonBlocks_[k] && islands_[k].dynamicBodies > 0) islands_[k].needsSolver = true;
    int first = 0;
    for (Island& island : islands_) {
        island.first = first;
        first += island.count;
        island.count = 0;
    }
    members_.resize(static_cast<std::size_t>(first));
    for (int n = 0; n < nodeCount; ++n) {
        if (islandOf_[static_cast<std::size_t>(n)] < 0) continue;
        Island& island = islands_[static_cast<std::size_t>(islandOf_[static_cast<std::size_t>(n)])];
        members_[static_cast<std::size_t>(island.first + island.count++)] = n;
    }
}

} // namespace rube
