// The rigid bodies' part of the solver's step: states, contacts found once per step, substep stages.
#include "rigid_stage.hpp"

#include "speed_limits.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>

namespace rube {

namespace {

/// Speculative distance every pair gets on top of its motion (Box2D's four linear slops): a plank
/// resting on a ball keeps its contact while either moves a little.
constexpr double kSpeculativeDistance = 0.02;
/// Stiffness of rigid contacts between two movable bodies (and twice that against infinite mass),
/// at most this fraction of the substep rate, heavily damped: the circle contacts' tuning.
constexpr double kContactHertz = 60.0;
/// Stiffness of the stacking contacts (RigidContact::stacking: between shapes no pivot or joint
/// holds), likewise capped. A box resting under load L overlaps by L / (m omega^2) (makeSoftness'
/// spring), so a pyramid sinks by the sum of its rows' loads over omega^2. At 70 Hz, relaxed once
/// (method_solver.cpp, kRigidContactRelaxPasses), Box2D's 100-row pyramid sinks 0.14 m and no box
/// moves more than 0.20 m; at 60 Hz a box then moved 0.25 m. The other contacts keep 60 Hz: a
/// ball's and a mechanism's, stiffer, changed how seesaws, buckets, paddles and counterweights throw
/// and catch (three levels' wrong attempts reached the goal at 65 and 70 Hz, and at 90 the
/// chain-door's solution no longer did).
constexpr double kStackContactHertz = 70.0;
constexpr double kMaxHertzPerSubstepRate = 0.25;
constexpr double kStaticHertzScale = 2.0;
constexpr double kContactDampingRatio = 10.0;
/// Radians a body may turn in a substep and still warm start its contacts: 0.25 at 480 Hz is 120 rad/s,
/// far above a tipping domino or a spinning drop (30 rad/s) and far below a struck bullet's spin.
constexpr double kMaxWarmStartTurn = 0.25;
/// Pivots: stiffer than contacts and less damped, as Box2D v3's joints (twice the contact hertz).
constexpr double kPivotHertz = 120.0;
constexpr double kPivotDampingRatio = 2.0;
/// Blocks (of four contacts) in a chunk of a per-block loop: the approach measure, the arms.
constexpr std::size_t kBlockLoopChunk = 16;
/// Candidate pairs in a chunk of the narrowphase (a manifold costs about 0.1 us).
constexpr std::size_t kPairChunk = 64;
/// A pair of joint ends as one number: rigid body i as i, circle c as -1 - c.
constexpr std::int64_t kPairBase = std::int64_t{1} << 32;
constexpr std::int64_t kNoBody = std::numeric_limits<std::int64_t>::min();

BoundingBox boundsOf(const RoundedPolygon& p, double extra) {
    BoundingBox b{p.vertices[0], p.vertices[0]};
    for (int i = 1; i < p.count; ++i) {
        b.min = {std::min(b.min.x, p.vertices[i].x), std::min(b.min.y, p.vertices[i].y)};
        b.max = {std::max(b.max.x, p.vertices[i].x), std::max(b.max.y, p.vertices[i].y)};
    }
    const Vec2 grow{p.radius + extra, p.radius + extra};
    return {b.min - grow, b.max + grow};
}

} // namespace

void RigidStage::prepare(const StepContext& ctx, double dt) {
    pool_ = ctx.workers;
    circleCount_ = static_cast<int>(ctx.circles.size());
    const std::size_t n = ctx.bodies.size();
    rigidCount_ = n;
    states_.resize(n);
    startPosition_.resize(n);
    startAngle_.resize(n);
    startVelocity_.resize(n);
    startOmega_.resize(n);
    gravity_ = ctx.def.gravity;
    stepTime_ = dt;
    substeps_ = std::max(1, ctx.def.substeps);
    speedLimit_ = ctx.def.maxTranslation / dt; // the step's limits, held at every substep (speed_limits.cpp)
    spinLimit_ = ctx.def.maxRotation / dt;
    clamps_ = 0;
    thickness_.resize(n);
    reach_.resize(n);
    shapes_.resize(n);
    shapeKeys_.resize(n);
    boxes_.resize(n);
    const double gravityTravel = ctx.def.gravity.length() * dt * dt;
    // Each body's own slots only: any split among the workers gives the same states and shapes.
    forShares(pool_, n, kBodyChunk, [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) {
            const RigidBody& b = ctx.bodies[i];
            // An asleep body is fixed for the step: no gravity, and contacts only with awake bodies (which wake it).
            const bool dynamic = b.motion == Motion::dynamic && b.inverseMass > 0.0 && !b.sleep.asleep;
            RigidState& s = states_[i];
            s = RigidState{};
            s.velocity = b.motion == Motion::fixed ? Vec2{} : b.velocity;
            s.omega = b.motion == Motion::fixed || b.fixedRotation ? 0.0 : b.angularVelocity;
            s.inverseMass = dynamic ? b.inverseMass : 0.0;
            s.inverseInertia = dynamic && !b.fixedRotation ? b.inverseInertia : 0.0;
            startPosition_[i] = b.position;
            startAngle_[i] = b.angle;
            thickness_[i] = b.shape == BodyShape::box ? std::min(b.halfExtents.x, b.halfExtents.y) : b.halfExtents.y;
            startVelocity_[i] = s.velocity;
            startOmega_[i] = s.omega;
            // Over the step a point of the body moves at most (|v| + |omega| extent) dt + |g| dt^2. A body
            // at rest (asleep, fixed) skips the call to hypot, which gives +0 for a zero vector too.
            const double speed = s.velocity == Vec2{} ? 0.0 : s.velocity.length();
            reach_[i] = kSpeculativeDistance + (speed + std::abs(s.omega) * boundingRadius(b)) * dt +
                        (dynamic ? gravityTravel : 0.0);
            // The shape (a sine, a cosine and four normals) only when the body has moved or changed
            // since it was made: asleep and fixed bodies, most of a settled machine's, keep theirs.
            const ShapeKey key{b.position, b.angle, b.halfExtents, b.shape, true};
            if (!(shapeKeys_[i] == key)) {
                shapes_[i] = makeRoundedPolygon(b, b.position, b.angle);
                shapeKeys_[i] = key;
            }
            boxes_[i] = boundsOf(shapes_[i], reach_[i]); // what the body may reach this step
        }
    });
    // The bodies the substeps move. The others are still and no impulse reaches them (the sweeps
    // write movable bodies only), so their displacement and turn stay zero: a settled machine's
    // asleep bodies cost the substeps nothing.
    movers_.clear();
    for (std::size_t i = 0; i < n; ++i) {
        const RigidState& s = states_[i];
        if (movableBody(s) || !(s.velocity == Vec2{}) || s.omega != 0.0) movers_.push_back(static_cast<int>(i));
    }
    const double h = dt / std::max(1, ctx.def.substeps);
    substep_ = 0;
    substepTime_ = h;
    const double hertz = std::min(kContactHertz, kMaxHertzPerSubstepRate / h);
    contactSoftness_.movable = makeSoftness(hertz, kContactDampingRatio, h);
    contactSoftness_.fixed = makeSoftness(kStaticHertzScale * hertz, kContactDampingRatio, h);
    const double stackHertz = std::min(kStackContactHertz, kMaxHertzPerSubstepRate / h);
    contactSoftness_.stackMovable = makeSoftness(stackHertz, kContactDampingRatio, h);
    contactSoftness_.stackFixed = makeSoftness(kStaticHertzScale * stackHertz, kContactDampingRatio, h);
    pivotSoftness_ = makeSoftness(std::min(kPivotHertz, 2.0 * kMaxHertzPerSubstepRate / h), kPivotDampingRatio, h);
    findContacts(ctx, dt);
    states_.resize(rigidCount_ + otherBody_.size()); // the listed circles and segments: filled at bind()
    preparePivots(ctx.pivots, ctx.bodies, pivots_);
    // Joints are as stiff as pivots (the same softness).
    joints_.prepare(ctx, h, pivotSoftness_);
    markHeld(ctx);
}

bool RigidStage::stacking(const RigidContact& c, std::size_t circleCount) const {
    const auto shape = [&](BodySide side, int body) {
        const bool circle = !side.rigid && static_cast<std::size_t>(side.index) < circleCount;
        return !circle && held_[static_cast<std::size_t>(body)] == 0;
    };
    return shape(c.a, c.bodyA) && shape(c.b, c.bodyB);
}

void RigidStage::markHeld(const StepContext& ctx) {
    held_.assign(states_.size(), 0);
    const auto rigid = [&](int body) {
        if (body >= 0) held_[static_cast<std::size_t>(body)] = 1;
    };
    const auto circle = [&](int c) {
        // A jointed circle no rigid contact touches has no solver body here, and needs none.
        if (c >= 0 && otherSlot_[static_cast<std::size_t>(c)] >= 0)
            held_[static_cast<std::size_t>(otherSlot_[static_cast<std::size_t>(c)])] = 1;
    };
    for (const Pivot& p : ctx.pivots) rigid(p.body);
    for (const Joint& j : ctx.joints) {
        rigid(j.bodyA);
        rigid(j.bodyB);
        circle(j.circleA);
        circle(j.circleB);
    }
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

void RigidStage::bind(std::span<SolverBody> others, std::span<double> omega, std::span<const Circle> circles) {
    view_ = RigidSolverView{std::span<RigidState>(states_).first(rigidCount_), others, omega, circles};
    joints_.bind(view_);
    // A listed circle's masses as load() reads them, once for the step: an asleep circle is fixed,
    // and its inertia counts only when the step models rotation. A segment has infinite mass.
    for (std::size_t k = 0; k < otherBody_.size(); ++k) {
        RigidState& s = states_[rigidCount_ + k];
        s = RigidState{};
        const auto i = static_cast<std::size_t>(otherBody_[k]);
        if (i >= circles.size()) continue;
        const Circle& c = circles[i];
        const bool movable = c.motion == Motion::dynamic && !c.sleep.asleep;
        if (movable) s.inverseMass = c.inverseMass;
        if (movable && !omega.empty()) s.inverseInertia = c.inverseInertia;
    }
    // The contacts, listed in findContacts, go straight to their places in colour order, copied by
    // the workers from where they were made (the slots are kept between steps, so a list as long as
    // the last costs no construction), and each point gets last step's impulses back. The lookups
    // go in the list's order, which is the cache's key order: each gallops on from the last, where
    // in colour order it would start over (the impulses are the same either way).
    colours_.assign(listedEnds_, states_);
    const std::span<const int> place = colours_.placeOfListed();
    contacts_.resize(listed_.size());
    forShares(pool_, listed_.size(), kPairChunk, [&](std::size_t first, std::size_t last) {
        RigidContactCache::Lookup lookup(cache_);
        for (std::size_t k = first; k < last; ++k) {
            RigidContact& c = contacts_[static_cast<std::size_t>(place[k])];
            c = listedContact(k);
            c.bodyA = listedEnds_[k].bodyA;
            c.bodyB = listedEnds_[k].bodyB;
            chooseSoftness(std::span(&c, 1), states_);
            c.stacking = stacking(c, circles.size());
            lookup.apply(c);
        }
    });
    blocks_.pack(contacts_, colours_, states_, pool_);
    refreshBlockArms(blocks_.all(), states_);
}

void RigidStage::loadOthers() {
    const bool spins = !view_.omega.empty();
    for (std::size_t k = 0; k < otherBody_.size(); ++k) {
        RigidState& s = states_[rigidCount_ + k];
        const auto i = static_cast<std::size_t>(otherBody_[k]);
        const SolverBody& b = view_.others[i];
        s.velocity = b.velocity;
        s.displacement = b.displacement;
        // A circle's contact point stays where the normal meets its surface however it turns, so its
        // turn never moves an anchor (turnRotation stays 1, 0); only its spin enters the point's velocity.
        s.omega = spins && i < view_.circles.size() ? view_.omega[i] : 0.0;
    }
}

void RigidStage::storeOthers() {
    const bool spins = !view_.omega.empty();
    for (std::size_t k = 0; k < otherBody_.size(); ++k) {
        const RigidState& s = states_[rigidCount_ + k];
        const auto i = static_cast<std::size_t>(otherBody_[k]);
        view_.others[i].velocity = s.velocity;
        if (spins && i < view_.circles.size()) view_.omega[i] = s.omega;
    }
}

void RigidStage::integrateVelocities(Vec2 gravityStep) {
    forShares(pool_, movers_.size(), kBodyChunk, [&](std::size_t first, std::size_t last) {
        for (std::size_t k = first; k < last; ++k) {
            RigidState& s = states_[static_cast<std::size_t>(movers_[k])];
            if (s.inverseMass > 0.0) s.velocity += gravityStep;
        }
    });
}

void RigidStage::warmStart() {
    loadOthers();
    const int substep = substep_++;
    // Each contact reads its bodies and writes only itself: any share of the list gives the same bits.
    const std::span<RigidBlock> blocks = blocks_.all();
    forShares(pool_, blocks.size(), kBlockLoopChunk, [&](std::size_t first, std::size_t last) {
        measureBlockApproach(blocks.subspan(first, last - first), contacts_, states_, substep);
    });
    warmStartPivots(pivots_, view_);
    if (!joints_.empty()) {
        joints_.warmStart();
        loadOthers(); // the joints may have pushed a listed circle
    }
    sweepBlocks(pool_, blocks_, [&](std::size_t first, std::size_t last) {
        warmStartBlocks(blocks.subspan(first, last - first), states_, substepTime_, kMaxWarmStartTurn);
    });
    storeOthers();
}

void RigidStage::solve(double h, bool useBias, bool everyRelaxOnly) {
    solvePivots(pivots_, view_, pivotSoftness_, useBias);
    if (!joints_.empty()) joints_.solve(useBias);
    if (everyRelaxOnly && !blocks_.anyEveryRelax()) return;
    loadOthers();
    const std::span<RigidBlock> blocks = blocks_.all();
    sweepBlocks(pool_, blocks_, [&](std::size_t first, std::size_t last) {
        solveBlocks(blocks.subspan(first, last - first), states_, contactSoftness_, h, useBias, everyRelaxOnly);
    });
    storeOthers();
}

void RigidStage::integratePositions(double h) {
    // Per body, then per contact: each writes only its own slot. Clamps are counted per chunk and
    // summed (integers: the sum does not depend on the split).
    std::atomic<std::int64_t> clamps{0};
    const auto move = [&](std::size_t first, std::size_t last) {
        std::int64_t count = 0;
        for (std::size_t k = first; k < last; ++k) {
            RigidState& s = states_[static_cast<std::size_t>(movers_[k])];
            // No substep moves a body faster than the step's limits allow (issue 27: a wedged capsule's
            // spin fed back through its contacts within one step, 15 to 11,000 rad/s, then NaN).
            if (s.inverseMass > 0.0 || s.inverseInertia > 0.0)
                count += clampRigidMotion(s.velocity, s.omega, speedLimit_, spinLimit_);
            s.displacement += s.velocity * h;
            if (s.omega == 0.0) continue;
            s.turn += s.omega * h;
            s.turnRotation = {std::cos(s.turn), std::sin(s.turn)};
        }
        if (count != 0) clamps.fetch_add(count, std::memory_order_relaxed);
    };
    const std::span<RigidBlock> blocks = blocks_.all();
    const auto arms = [&](std::size_t first, std::size_t last) {
        refreshBlockArms(blocks.subspan(first, last - first), states_);
    };
    if (worthSharing(pool_, rigidCount_, kBodyChunk)) {
        // Two phases: the arms read both bodies' turns.
        const std::size_t sizes[2] = {movers_.size(), blocks.size()}, chunks[2] = {kBodyChunk, kBlockLoopChunk};
        auto work = [&](int phase, std::size_t first, std::size_t last) {
            if (phase == 0) move(first, last);
            else arms(first, last);
        };
        pool_->run(2, sizes, chunks, work);
    } else {
        move(0, movers_.size());
        arms(0, blocks.size());
    }
    clamps_ += clamps.load(std::memory_order_relaxed);
    if (!joints_.empty()) joints_.integrateCircleTurns(h);
}

void RigidStage::applyRestitution(double threshold) {
    blocks_.unpack(contacts_, pool_); // the substeps' impulses and arms, for restitution, the cache, events and sleep
    cache_.store(contacts_, colours_.placeOfListed(), pool_); // the last substep's impulses, not restitution's bounce
    beforeBounce_.resize(states_.size());
    forShares(pool_, states_.size(), kBodyChunk, [&](std::size_t first, std::size_t last) {
        std::copy(states_.begin() + static_cast<std::ptrdiff_t>(first),
                  states_.begin() + static_cast<std::ptrdiff_t>(last),
                  beforeBounce_.begin() + static_cast<std::ptrdiff_t>(first));
    });
    loadOthers();
    sweepColours(pool_, colours_, [&](std::size_t first, std::size_t last) {
        applyRigidRestitution(std::span(contacts_).subspan(first, last - first), states_, threshold);
    });
    storeOthers();
    capBounceEnergy();
}

void RigidStage::finish(StepContext& ctx) const {
    ctx.stats.speedClamps += clamps_;
    forShares(pool_, ctx.bodies.size(), kBodyChunk, [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) {
            RigidBody& b = ctx.bodies[i];
            if (b.motion == Motion::fixed || b.sleep.asleep) continue;
            const RigidState& s = states_[i];
            b.position = startPosition_[i] + s.displacement;
            b.angle += s.turn;
            b.velocity = s.velocity;
            b.angularVelocity = s.omega;
        }
    });
}

} // namespace rube
