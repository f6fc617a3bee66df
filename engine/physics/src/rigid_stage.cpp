// The rigid bodies' part of the solver's step: states and shapes, the contacts bound and packed,
// the substep stages, restitution and the write-back. The contacts are found in
// rigid_find_contacts.cpp, their stiffness chosen in rigid_softness.cpp.
#include "rigid_stage.hpp"

#include "speed_limits.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>

namespace rube {

namespace {

/// Radians a body may turn in a substep and still warm start its contacts: 0.25 at 480 Hz is 120 rad/s,
/// far above a tipping domino or a spinning drop (30 rad/s) and far below a struck bullet's spin.
constexpr double kMaxWarmStartTurn = 0.25;
/// Blocks (of four contacts) in a chunk of a per-block loop: the approach measure, the arms.
constexpr std::size_t kBlockLoopChunk = 16;

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
    chooseSoftnesses(h);
    findContacts(ctx, dt);
    states_.resize(rigidCount_ + otherBody_.size()); // the listed circles and segments: filled at bind()
    preparePivots(ctx.pivots, ctx.bodies, pivots_);
    // Joints are as stiff as pivots (the same softness).
    joints_.prepare(ctx, h, pivotSoftness_);
    markHeld(ctx);
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
            c.stacking = stacking(c);
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
    joints_.motorsStalled(stalledMotors_);
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
