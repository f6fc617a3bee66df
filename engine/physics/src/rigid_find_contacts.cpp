// The rigid stage's contacts, found once a step: the pairs the broadphase lists, each one's manifold
// and contact made by the workers, then listed in pair order with the segments' after each body's,
// and the sleepers an awake body or a moving kinematic one reaches.
#include "rigid_stage.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace rube {

namespace {

/// A pair of joint ends as one number: rigid body i as i, circle c as -1 - c.
constexpr std::int64_t kPairBase = std::int64_t{1} << 32;
constexpr std::int64_t kNoBody = std::numeric_limits<std::int64_t>::min();

} // namespace

BoundingBox RigidStage::boundsOf(const RoundedPolygon& p, double extra) {
    BoundingBox b{p.vertices[0], p.vertices[0]};
    for (int i = 1; i < p.count; ++i) {
        b.min = {std::min(b.min.x, p.vertices[i].x), std::min(b.min.y, p.vertices[i].y)};
        b.max = {std::max(b.max.x, p.vertices[i].x), std::max(b.max.y, p.vertices[i].y)};
    }
    const Vec2 grow{p.radius + extra, p.radius + extra};
    return {b.min - grow, b.max + grow};
}

void RigidStage::findContacts(const StepContext& ctx, double dt) {
    listed_.clear();
    listedEnds_.clear();
    madeBySegment_.clear();
    reached_.clear();
    states_.resize(rigidCount_);
    otherBody_.clear();
    otherSlot_.assign(ctx.circles.size() + ctx.segments.size(), -1);
    const auto& bodies = ctx.bodies;
    const double gravityTravel = ctx.def.gravity.length() * dt * dt;
    const std::size_t n = bodies.size();
    const auto isDynamic = [&](std::size_t i) { return states_[i].inverseMass > 0.0; };
    const auto& boxes = boxes_; // made by prepare()
    // The circle solver's bodies are not bound yet: effective masses need only the rigid states and
    // the circles' masses and inertias, so a stand-in view serves (a zero omega per body says the
    // circles may turn: their inertia enters the tangent mass).
    others_.assign(ctx.circles.size() + ctx.segments.size(), SolverBody{});
    zeros_.assign(others_.size(), 0.0);
    const RigidSolverView massView{states_, others_, zeros_, ctx.circles};
    // Bodies a joint ties together do not collide (a chain's links overlap at their hinges), as in Box2D,
    // unless the joint says they do (collideConnected).
    connected_.clear();
    for (const Joint& j : ctx.joints) {
        if (j.def.collideConnected) continue;
        const std::int64_t a = j.bodyA >= 0 ? j.bodyA : j.circleA >= 0 ? -1 - j.circleA : kNoBody;
        const std::int64_t b = j.bodyB >= 0 ? j.bodyB : j.circleB >= 0 ? -1 - j.circleB : kNoBody;
        if (a == kNoBody || b == kNoBody) continue;
        connected_.push_back(std::min(a, b) * kPairBase + std::max(a, b));
    }
    std::sort(connected_.begin(), connected_.end());
    const auto tied = [&](BodySide a, BodySide b) {
        if (connected_.empty()) return false;
        const std::int64_t x = a.rigid ? a.index : -1 - a.index, y = b.rigid ? b.index : -1 - b.index;
        return std::binary_search(connected_.begin(), connected_.end(), std::min(x, y) * kPairBase + std::max(x, y));
    };
    const auto made = [&](BodySide a, BodySide b, Vec2 centreA, Vec2 centreB, const Manifold& m, const Material& ma,
                          const Material& mb) {
        return makeRigidContact(massView, a, b, centreA, centreB, m, ma.friction * mb.friction,
                                ma.bounciness * mb.bounciness);
    };
    // A contact listed (in list order): its sides get their solver bodies here, one after the other,
    // and it is copied into the list afterwards, by the workers. `source` is its pair's slot in made_,
    // or -1 - its slot in madeBySegment_.
    const auto append = [&](int source, BodySide a, BodySide b) {
        listed_.push_back(source);
        listedEnds_.push_back({solverBodyOf(a), solverBodyOf(b)});
    };
    const auto add = [&](BodySide a, BodySide b, Vec2 centreA, Vec2 centreB, const Manifold& m, const Material& ma,
                         const Material& mb) {
        if (m.count == 0) return; // tied pairs were given no manifold (below)
        madeBySegment_.push_back(made(a, b, centreA, centreB, m, ma, mb));
        append(-static_cast<int>(madeBySegment_.size()), a, b);
    };
    // Sleepers: a contact with an awake body, or a moving kinematic body's box, reaches them.
    const auto asleep = [&](std::size_t i) { return bodies[i].sleep.asleep; };
    const auto circleAsleep = [&](std::size_t c) { return ctx.circles[c].sleep.asleep; };
    const auto moving = [](Motion motion, Vec2 v, double omega) {
        return motion == Motion::kinematic && (v != Vec2{} || omega != 0.0);
    };
    bool anyAwake = false, anyAsleep = false;
    for (std::size_t i = 0; i < n; ++i) {
        anyAwake = anyAwake || isDynamic(i) || moving(bodies[i].motion, bodies[i].velocity, bodies[i].angularVelocity);
        anyAsleep = anyAsleep || asleep(i);
    }
    for (const Circle& c : ctx.circles) {
        anyAwake = anyAwake || (c.motion == Motion::dynamic && c.inverseMass > 0.0 && !c.sleep.asleep) ||
                   moving(c.motion, c.velocity, 0.0);
        anyAsleep = anyAsleep || c.sleep.asleep;
    }
    // Model no more than the scene needs: with every body asleep or fixed, no pair can act or wake
    // anything but a moving kinematic segment (below), so a sleeping scene pays no pair search.
    if (!anyAwake) {
        if (anyAsleep) reachBySegments(ctx, dt);
        return;
    }
    // Circles by the box they may reach this step; the broadphase lists the pairs whose boxes overlap in
    // the order the double loop over bodies, then circles, visited them, so contacts keep their order.
    circleBoxes_.resize(ctx.circles.size());
    circleReach_.resize(ctx.circles.size());
    for (std::size_t c = 0; c < ctx.circles.size(); ++c) {
        const Circle& circle = ctx.circles[c];
        const bool circleDynamic = circle.motion == Motion::dynamic && circle.inverseMass > 0.0;
        const Vec2 v = circle.motion == Motion::fixed ? Vec2{} : circle.velocity;
        circleReach_[c] = kSpeculativeDistance + v.length() * dt + (circleDynamic ? gravityTravel : 0.0);
        const Vec2 grow{circle.radius + circleReach_[c], circle.radius + circleReach_[c]};
        circleBoxes_[c] = {circle.position - grow, circle.position + grow};
    }
    pairFinder_.find(boxes, circleBoxes_, pairs_);
    // The narrowphase, each pair's manifold into its own slot (shared among the workers: any split
    // gives the same manifolds), then the contacts made from them below in pair order, as one loop would.
    const auto circleDynamic = [&](std::size_t c) {
        const Circle& circle = ctx.circles[c];
        return circle.motion == Motion::dynamic && circle.inverseMass > 0.0 && !circleAsleep(c);
    };
    // Each pair's contact is made there too (its effective masses read only the states and the stand-ins).
    manifolds_.resize(pairs_.size());
    made_.resize(pairs_.size());
    forShares(pool_, pairs_.size(), kPairChunk, [&](std::size_t first, std::size_t last) {
        for (std::size_t k = first; k < last; ++k) {
            const auto i = static_cast<std::size_t>(pairs_[k].body), other = static_cast<std::size_t>(pairs_[k].other);
            Manifold& m = manifolds_[k];
            m.count = 0;
            const BodySide side{static_cast<int>(i), true};
            if (other < n) {
                const BodySide otherSide{static_cast<int>(other), true};
                if ((isDynamic(i) || isDynamic(other)) && !tied(side, otherSide)) {
                    m = collideRoundedPolygons(shapes_[i], shapes_[other], reach_[i] + reach_[other]);
                    if (m.count != 0)
                        made_[k] = made(side, otherSide, bodies[i].position, bodies[other].position, m,
                                        bodies[i].material, bodies[other].material);
                }
            } else if (const BodySide circleSide{static_cast<int>(other - n), false};
                       (isDynamic(i) || circleDynamic(other - n)) && !tied(side, circleSide)) {
                const Circle& circle = ctx.circles[other - n];
                m = collideRoundedPolygons(shapes_[i], makeRoundedPolygon(circle), reach_[i] + circleReach_[other - n]);
                if (m.count != 0)
                    made_[k] = made(side, circleSide, bodies[i].position, circle.position, m, bodies[i].material,
                                    circle.material);
            }
        }
    });
    // Each segment's shape and the box it may reach, once for all the bodies.
    segmentShapes_.resize(ctx.segments.size());
    segmentReach_.resize(ctx.segments.size());
    segmentBoxes_.resize(ctx.segments.size());
    for (std::size_t s = 0; s < ctx.segments.size(); ++s) {
        const Segment& seg = ctx.segments[s];
        segmentReach_[s] = seg.motion() == Motion::kinematic ? seg.velocity.length() * dt : 0.0;
        segmentShapes_[s] = makeRoundedPolygon(seg);
        segmentBoxes_[s] = boundsOf(segmentShapes_[s], segmentReach_[s]);
    }
    std::size_t next = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const RigidBody& bi = bodies[i];
        const BodySide side{static_cast<int>(i), true};
        for (; next < pairs_.size() && pairs_[next].body == static_cast<int>(i); ++next) {
            const auto other = static_cast<std::size_t>(pairs_[next].other);
            if (other < n) {
                const std::size_t j = other;
                if (!isDynamic(i) && !isDynamic(j)) {
                    // Neither moves under the solver: a moving kinematic body still reaches a sleeper.
                    const RigidBody& bj = bodies[j];
                    if (asleep(i) && moving(bj.motion, bj.velocity, bj.angularVelocity))
                        reached_.push_back(-1 - static_cast<int>(i));
                    if (asleep(j) && moving(bi.motion, bi.velocity, bi.angularVelocity))
                        reached_.push_back(-1 - static_cast<int>(j));
                    continue;
                }
                if (manifolds_[next].count == 0) continue;
                append(static_cast<int>(next), side, {static_cast<int>(j), true});
                if (asleep(i)) reached_.push_back(-1 - static_cast<int>(i));
                if (asleep(j)) reached_.push_back(-1 - static_cast<int>(j));
                continue;
            }
            const std::size_t c = other - n;
            const Circle& circle = ctx.circles[c];
            if (!isDynamic(i) && !circleDynamic(c)) {
                if (asleep(i) && moving(circle.motion, circle.velocity, 0.0))
                    reached_.push_back(-1 - static_cast<int>(i));
                if (circleAsleep(c) && moving(bi.motion, bi.velocity, bi.angularVelocity))
                    reached_.push_back(static_cast<int>(c));
                continue;
            }
            if (manifolds_[next].count == 0) continue;
            append(static_cast<int>(next), side, {static_cast<int>(c), false});
            if (asleep(i)) reached_.push_back(-1 - static_cast<int>(i));
            if (circleAsleep(c)) reached_.push_back(static_cast<int>(c));
        }
        if (!isDynamic(i)) continue;
        for (std::size_t s = 0; s < ctx.segments.size(); ++s) {
            const Segment& seg = ctx.segments[s];
            const BodySide segmentSide{circleCount_ + static_cast<int>(s), false};
            if (!boxes[i].overlaps(segmentBoxes_[s]) || tied(side, segmentSide)) continue;
            const std::size_t before = madeBySegment_.size();
            add(side, segmentSide, bi.position, seg.a,
                collideRoundedPolygons(shapes_[i], segmentShapes_[s], reach_[i] + segmentReach_[s]), bi.material,
                seg.material);
            // A conveyor carries what rubs on it: its belt runs along a -> b (as the circles' FrictionBody).
            if (seg.surfaceSpeed != 0.0 && madeBySegment_.size() > before) {
                RigidContact& c = madeBySegment_.back();
                c.tangentSpeed = c.tangent.dot(seg.beltVelocity());
            }
        }
    }
    if (anyAsleep) reachBySegments(ctx, dt);
}

void RigidStage::reachBySegments(const StepContext& ctx, double dt) {
    // A moving kinematic segment (a paddle, a lift) reaches an asleep rigid body its swept box meets.
    for (std::size_t s = 0; s < ctx.segments.size(); ++s) {
        const Segment& seg = ctx.segments[s];
        if (seg.motion() != Motion::kinematic || (seg.velocity == Vec2{} && seg.angularVelocity == 0.0)) continue;
        const double turn = std::abs(seg.angularVelocity) * (seg.b - seg.a).length() * dt;
        const BoundingBox box = boundsOf(makeRoundedPolygon(seg), seg.velocity.length() * dt + turn);
        for (std::size_t i = 0; i < ctx.bodies.size(); ++i)
            if (ctx.bodies[i].sleep.asleep && boxes_[i].overlaps(box)) reached_.push_back(-1 - static_cast<int>(i));
    }
}

int RigidStage::solverBodyOf(BodySide side) {
    if (side.rigid) return side.index;
    int& slot = otherSlot_[static_cast<std::size_t>(side.index)];
    if (slot < 0) {
        slot = static_cast<int>(rigidCount_ + otherBody_.size());
        otherBody_.push_back(side.index);
    }
    return slot;
}

} // namespace rube
