// The `solver` time-step method: a substepped sequential-impulse contact solver with soft contacts,
// relax passes and restitution at the end (the "soft step" of Box2D v3), speculative contacts found
// once per step through a uniform grid, and a continuous sweep for circles faster than their margin.
#include "broadphase_grid.hpp"
#include "field_pass.hpp"
#include "joint_stage.hpp"
#include "rigid_stage.hpp"
#include "solver_bounce_flight.hpp"
#include "solver_friction.hpp"
#include "solver_impact_normal.hpp"
#include "solver_narrowphase.hpp"
#include "solver_sleep.hpp"
#include "solver_soft_step.hpp"
#include "solver_sweep.hpp"
#include "solver_turning.hpp"
#include "step_method.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace rube {

namespace {

/// Speculative distance every circle gets on top of its motion, as a fraction of its radius: a struck
/// row with gaps of up to half a radius still has its contacts when the blow runs through it.
constexpr double kSpeculativePerRadius = 0.25;
/// A dynamic circle's margin never exceeds this many radii; beyond it the continuous sweep takes over,
/// so a bullet does not drag every shape along its 83 m path into the contact list.
constexpr double kMaxMarginPerRadius = 1.0;
/// A path longer than this many grid cells is not filed along its length: the body is a bullet.
constexpr int kMaxSweepCellsPerAxis = 8;
/// Grid cells this much wider than the typical filing box, so that box fits one cell.
constexpr double kCellPerFilingSpan = 1.1;

// The contact tuning, chosen by measuring the 1000-ball pile of tests/solver_test.cpp and 16 variants
// of its spawn jitter (largest overlap in the last second, settling) against the time per step.
/// Stiffness of contacts between dynamic circles. The resting overlap is the load over the spring,
/// F / (m omega^2), so the deepest force chain in a 40-ball pile sets how stiff it must be.
constexpr double kContactHertz = 200.0;
/// Stiffer than this fraction of the substep rate and the pile never comes to rest (Box2D v3 stops
/// at a quarter with one relax pass; three relax passes hold it at 0.42, two at 0.35: at 8 substeps
/// of 60 Hz that caps the contacts at 168 Hz, and two passes at 200 Hz left piles jiggling).
constexpr double kMaxHertzPerSubstepRate = 0.35;
/// Contacts against infinite mass move one body only: twice as stiff is as stable (Box2D v3).
constexpr double kStaticHertzScale = 2.0;
/// Heavily over-damped: overlap is pushed out without bouncing.
constexpr double kDampingRatio = 10.0;
/// m/s: the soft push-out never exceeds this, so deep overlaps resolve gently.
constexpr double kMaxPushSpeed = 3.0;
/// Rigid passes after each substep's position update. Two passes at 168 Hz cost a third less than
/// three at 200 Hz; the worst overlap in the last second over spawn variants of the pile went from
/// 3.2 mm (16 variants) to 3.8 mm (32 variants; limit 5 mm), all settled. One pass needs a quarter of
/// the substep rate (120 Hz), and then the worst pile overlaps 12 mm; two at 0.31 hit 7.9 mm once.
/// With pushing contacts swept first in their group (orderContacts), 96 spawn variants: worst 4.7 mm,
/// mean 3.05 (4.4 and 2.99 in the order before); one still crept at 1.2 cm/s after 10 s (at rest by 12 s).
constexpr int kRelaxIterations = 2;
/// Of those passes, the stacking contacts (RigidContact::stacking: between shapes that no pivot or
/// joint holds) take part in this many; the pivots, the joints and every other contact in all.
/// One pass holds Box2D's 5050-box pyramid (largest move 0.20 m, top box 0.14 m down, with
/// rigid_softness.cpp's 70 Hz stacking contacts) in about 15 % less time a step. A mechanism needs the
/// second: with one, a catapult's paddle (the belt-drive level) threw its ball 4.6 cm further by the
/// top of its arc, past the flag, its pivot and the ball's contact not yet agreeing after the
/// push-out; a hammer's head came 1.7 to 1.9 mm off its handle on striking a ball, where the weld
/// holds it within 1 mm (tests/parts/hammer_test.cpp).
constexpr int kRigidContactRelaxPasses = 1;
/// A step in which some dynamic circle travels more than this many radii gets one relax pass more:
/// a blow running down a row (a 100 m/s striker into ten balls against a wall) needs the third pass
/// to reach the far end before the row is squeezed. A falling pile stays under it (20 m/s, 3.3 radii).
constexpr double kFastTravelPerRadius = 5.0;
constexpr int kFastRelaxIterations = 3;

class SolverMethod final : public StepMethod {
public:
    void step(StepContext& ctx, double dt) override {
        prepareBodies(ctx, dt);
        findContacts(ctx, dt);
        // Sleepers that something reached wake before anything is solved, and the contacts are found
        // again with them moving (each pass wakes at least one island, so this ends).
        while (ctx.sleep && sleep_.wakeReached(ctx.circles, ctx.segments, pairs_, margins_, circleBoxes_, segmentBoxes_,
                                               bulletPaths(dt), rigidSleep(ctx))) {
            prepareBodies(ctx, dt);
            findContacts(ctx, dt);
        }
        if (turning_)
            turningContacts_.attach(contacts_, ctx.circles, ctx.segments, bodies_, inverseMass_, omega_,
                                    frictionBodies_);
        solve(ctx, dt);
        finish(ctx, dt);
    }
    bool integratesRotation() const override { return true; }
    bool keepsSleep() const override { return true; }
    bool keepsRigidSleep() const override { return true; }
    void remapSlots(const SlotRemap& remap) override {
        cache_.remap(remap);
        rigid_.remapSlots(remap);
    }
    // The rigid stage keeps contacts and warm starts between steps that a quiet step would have to
    // renew as its full step does: worlds with rigid bodies or joints take the full step.
    bool restsQuietly(const StepContext& ctx) const override { return ctx.bodies.empty() && ctx.joints.empty(); }
    void restQuietly(StepContext& ctx) override {
        // The full step of a world entirely asleep finds no contact (each needs an awake dynamic
        // circle) and stores that none: warm starts begin afresh when something wakes. The rest it
        // fills in is scratch, refilled at the start of each step.
        hasRigid_ = false;
        cache_.storeNone(static_cast<int>(ctx.circles.size()), static_cast<int>(ctx.segments.size()));
    }

private:
    void prepareBodies(const StepContext& ctx, double dt);
    void findContacts(const StepContext& ctx, double dt);
    void solve(const StepContext& ctx, double dt);
    void finish(StepContext& ctx, double dt);
    void findFriction(const StepContext& ctx);
    void markWarmContacts();
    void flyFreeCirclesExactly(const StepContext& ctx, double dt);
    void takeBackMagnetKicks(const StepContext& ctx, double dt, int substeps);
    void restPulledContacts(const StepContext& ctx, double dt);
    // Per circle: a bullet, or pulled by a magnet this step (carryPastImpact leaves both alone).
    std::span<const std::uint8_t> notCarried() {
        notCarried_.assign(isBullet_.begin(), isBullet_.end());
        for (std::size_t i = 0; i < pullKicks_.size() && i < notCarried_.size(); ++i)
            if (pullKicks_[i] != Vec2{}) notCarried_[i] = 1;
        return notCarried_;
    }
    std::span<const BoundingBox> bulletPaths(double dt);
    RigidSleepInput rigidSleep(const StepContext& ctx) const {
        if (!hasRigid_) return {{}, {}, {}, {}, {}, ctx.ropes};
        return {ctx.bodies, rigid_.contacts(),     ctx.joints, ctx.pivots, rigid_.reached(),
                ctx.ropes,  rigid_.stalledMotors()};
    }

    int circleCount_ = 0;
    int segmentCount_ = 0;
    bool fastStep_ = false; // some dynamic circle travels more than kFastTravelPerRadius radii
    bool turning_ = false;  // some segment turns this step (a rotating paddle)
    TurningContacts turningContacts_;
    std::vector<SolverBody> bodies_;      // circles first, then segments
    std::vector<double> inverseMass_;     // per solver body
    std::vector<double> margins_;         // per solver body: how far it may move this step, plus slop
    std::vector<Vec2> start_;             // circle positions at the start of the step
    std::vector<std::uint8_t> isDynamic_; // per circle
    std::vector<std::uint8_t> isBullet_;  // per circle: filed where it starts, not along its path
    std::vector<int> bullets_;
    std::vector<BoundingBox> circleBoxes_, segmentBoxes_; // contact boxes: margin-fattened
    std::vector<BoundingBox> filingBoxes_;                // per circle: the contact box plus where it is heading
    std::vector<SweptSegment> sweptSegments_;
    std::vector<CandidatePair> pairs_;
    std::vector<std::int64_t> connected_; // circle pairs a joint keeps apart from colliding (joint_stage.hpp)
    std::vector<ContactConstraint> contacts_;
    std::vector<ContactRecord> records_;
    std::vector<double> gaps_; // per contact: its gap during the current substep's relax passes
    // Rotation and friction, touched only in steps where some circle spins or some pair has friction.
    bool anyRotation_ = false;
    std::vector<FrictionTerms> frictions_;     // parallel to contacts_ in steps with rotation
    std::vector<FrictionBody> frictionBodies_; // per solver body in steps with rotation
    std::vector<double> tangentImpulses_;      // scratch: the friction impulses the cache keeps
    std::vector<double> omega_;                // per solver body: angular velocity (segments stay 0)
    std::vector<int> rotating_;                // circles that turn this step
    std::vector<double> turn_;                 // per rotating circle: angle turned this step
    std::vector<std::uint8_t> marks_;          // scratch: circle already listed as rotating
    ContactOrderScratch orderScratch_;
    BroadphaseGrid grid_;
    ContactCache cache_;
    ContinuousSweep sweep_;
    // Rigid bodies (boxes, capsules) and pivots: only in steps whose world has some.
    bool hasRigid_ = false;
    RigidStage rigid_;
    SleepIslands sleep_;
    std::vector<BoundingBox> bulletPaths_; // scratch: each bullet's box over its whole path this step
    std::vector<std::uint8_t> inFlight_;   // per circle: dynamic, and no contact pushed it this step
    std::vector<std::uint8_t> inContact_;  // scratch: per circle, some contact pushed it this step
    std::vector<Vec2> pullKicks_;          // per circle, the magnets' kick taken back this step (empty: none)
    std::vector<Vec2> pullSteps_;          // per circle, the part of it each substep gives back
    std::vector<std::uint8_t> notCarried_; // scratch: per circle, a bullet or pulled
};

std::span<const BoundingBox> SolverMethod::bulletPaths(double dt) {
    bulletPaths_.clear();
    for (const int i : bullets_) {
        const BoundingBox& box = circleBoxes_[static_cast<std::size_t>(i)];
        const Vec2 move = bodies_[static_cast<std::size_t>(i)].velocity * dt;
        bulletPaths_.push_back({{box.min.x + std::min(move.x, 0.0), box.min.y + std::min(move.y, 0.0)},
                                {box.max.x + std::max(move.x, 0.0), box.max.y + std::max(move.y, 0.0)}});
    }
    return bulletPaths_;
}

void SolverMethod::prepareBodies(const StepContext& ctx, double dt) {
    circleCount_ = static_cast<int>(ctx.circles.size());
    segmentCount_ = static_cast<int>(ctx.segments.size());
    const std::size_t bodyCount = ctx.circles.size() + ctx.segments.size();
    bodies_.resize(bodyCount);
    inverseMass_.resize(bodyCount);
    margins_.resize(bodyCount);
    start_.resize(ctx.circles.size());
    isDynamic_.resize(ctx.circles.size());
    circleBoxes_.resize(ctx.circles.size());
    filingBoxes_.resize(ctx.circles.size());
    isBullet_.resize(ctx.circles.size());
    segmentBoxes_.resize(ctx.segments.size());
    sweptSegments_.resize(ctx.segments.size());
    // Over a step a body moves at most |v| dt + |g| dt^2 (its speed grows by at most |g| dt).
    const double gravityTravel = ctx.def.gravity.length() * dt * dt;
    fastStep_ = false;
    anyRotation_ = false;
    turning_ = false;
    for (int i = 0; i < circleCount_; ++i) {
        const Circle& c = ctx.circles[i];
        // An asleep circle is fixed for the step: no gravity, no contacts of its own.
        const bool dynamic = c.motion == Motion::dynamic && c.inverseMass > 0.0 && !c.sleep.asleep;
        const Vec2 v = c.motion == Motion::fixed ? Vec2{} : c.velocity;
        start_[i] = c.position;
        bodies_[i] = {v, {}};
        inverseMass_[i] = dynamic ? c.inverseMass : 0.0;
        isDynamic_[i] = dynamic ? 1 : 0;
        // Model no more than the scene needs: rotation only once a circle can turn (it spins, or it
        // could meet friction); otherwise no angular state is touched at all.
        if (dynamic && c.inverseInertia > 0.0 && (c.material.friction > 0.0 || c.angularVelocity != 0.0))
            anyRotation_ = true;
        const double travel = v.length() * dt;
        if (dynamic && travel > kFastTravelPerRadius * c.radius) fastStep_ = true;
        double margin = kSpeculativePerRadius * c.radius + travel;
        if (dynamic) margin = std::min(margin + gravityTravel, kMaxMarginPerRadius * c.radius);
        margins_[i] = margin;
        const Vec2 reach{c.radius + margin, c.radius + margin};
        circleBoxes_[i] = {c.position - reach, c.position + reach};
    }
    // A joint on a circle turns it (a wheel on its axle, a gear): the step models rotation.
    if (!ctx.joints.empty() && jointsTurnCircles(ctx.joints)) anyRotation_ = true;
    for (int s = 0; s < segmentCount_; ++s) {
        const Segment& seg = ctx.segments[s];
        const Vec2 v = seg.motion() == Motion::kinematic ? seg.velocity : Vec2{};
        const int body = circleCount_ + s;
        bodies_[body] = {v, {}};
        inverseMass_[body] = 0.0;
        margins_[body] = v.length() * dt; // the circle's own margin carries the slop
        sweptSegments_[s] = {seg.a, seg.b, v * dt, seg.radius};
        const Vec2 m = v * dt;
        double reach = seg.radius;
        if (seg.angularVelocity != 0.0) {
            // A turning segment's ends move up to |omega| times their distance from the pivot farther.
            const Vec2 pivot = lerp(seg.a, seg.b, seg.pivotAlong);
            const double turn = std::abs(seg.angularVelocity) *
                                std::max((seg.a - pivot).length(), (seg.b - pivot).length()) * dt;
            margins_[body] += turn;
            reach += turn;
            turning_ = true;
        }
        const Vec2 lo{std::min({seg.a.x, seg.b.x, seg.a.x + m.x, seg.b.x + m.x}),
                      std::min({seg.a.y, seg.b.y, seg.a.y + m.y, seg.b.y + m.y})};
        const Vec2 hi{std::max({seg.a.x, seg.b.x, seg.a.x + m.x, seg.b.x + m.x}),
                      std::max({seg.a.y, seg.b.y, seg.a.y + m.y, seg.b.y + m.y})};
        segmentBoxes_[s] = {lo - Vec2{reach, reach}, hi + Vec2{reach, reach}};
    }
}

void SolverMethod::findContacts(const StepContext& ctx, double dt) {
    // Circles are filed along the path they are heading for, so the continuous pass finds them
    // through the grid. Cells are a little wider than the typical filing box (each counted at most
    // twice its contact box, so a few bullets do not blow the cells up), so most circles are "small".
    double spanSum = 0.0;
    int dynamicCount = 0;
    for (int i = 0; i < circleCount_; ++i) {
        BoundingBox filing = circleBoxes_[i];
        const double r = ctx.circles[i].radius;
        const Vec2 end = start_[i] + bodies_[i].velocity * dt;
        filing.min = {std::min(filing.min.x, end.x - r), std::min(filing.min.y, end.y - r)};
        filing.max = {std::max(filing.max.x, end.x + r), std::max(filing.max.y, end.y + r)};
        filingBoxes_[i] = filing;
        if (!isDynamic_[i]) continue;
        const double span = std::max(filing.max.x - filing.min.x, filing.max.y - filing.min.y);
        spanSum += std::min(span, 2.0 * (circleBoxes_[i].max.x - circleBoxes_[i].min.x));
        ++dynamicCount;
    }
    pairs_.clear();
    bullets_.clear();
    if (dynamicCount > 0) {
        const double cellSize = kCellPerFilingSpan * spanSum / dynamicCount;
        constexpr double inf = std::numeric_limits<double>::infinity();
        BoundingBox region{{inf, inf}, {-inf, -inf}};
        for (int i = 0; i < circleCount_; ++i) {
            const BoundingBox& filing = filingBoxes_[i];
            const double span = std::max(filing.max.x - filing.min.x, filing.max.y - filing.min.y);
            // A bullet's path would cover too many cells: it is filed where it starts.
            isBullet_[i] = isDynamic_[i] && span > kMaxSweepCellsPerAxis * cellSize ? 1 : 0;
            if (isBullet_[i]) {
                filingBoxes_[i] = circleBoxes_[i];
                bullets_.push_back(i);
            }
            if (!isDynamic_[i] && !ctx.circles[i].sleep.asleep)
                continue; // sleepers inside the grid, not in its border cells
            region.min = {std::min(region.min.x, filingBoxes_[i].min.x), std::min(region.min.y, filingBoxes_[i].min.y)};
            region.max = {std::max(region.max.x, filingBoxes_[i].max.x), std::max(region.max.y, filingBoxes_[i].max.y)};
        }
        // Within the world's bounds: escaped bodies are clamped into the grid's border cells.
        const BoundingBox bounds{ctx.def.bounds.min - Vec2{cellSize, cellSize},
                                 ctx.def.bounds.max + Vec2{cellSize, cellSize}};
        const BoundingBox clipped{{std::max(region.min.x, bounds.min.x), std::max(region.min.y, bounds.min.y)},
                                  {std::min(region.max.x, bounds.max.x), std::min(region.max.y, bounds.max.y)}};
        if (clipped.min.x <= clipped.max.x && clipped.min.y <= clipped.max.y) region = clipped;
        grid_.build(filingBoxes_, sweptSegments_, region, cellSize, 4 * circleCount_ + 64);
        grid_.findPairs(circleBoxes_, segmentBoxes_, isDynamic_, pairs_);
    }
    // Two circles a joint joins do not touch unless it says they collide (collideConnected).
    connectedCirclePairs(ctx.joints, connected_);
    if (!connected_.empty())
        std::erase_if(pairs_, [&](const CandidatePair& p) {
            return p.other < circleCount_ && connectedCircles(connected_, p.circle, p.other);
        });
    buildContacts(pairs_, ctx.circles, ctx.segments, margins_, inverseMass_, cache_, contacts_, records_);
    // A pair closing fast is caught where it will touch, not where it starts (a glance at a cap).
    aimAtTimeOfImpact(contacts_, records_, ctx.circles, ctx.segments, inverseMass_, ctx.def.gravity, dt,
                      dt / std::max(1, ctx.def.substeps), ctx.restingSpeed);
    const Vec2 up = ctx.def.gravity.lengthSquared() > 0.0 ? -ctx.def.gravity.normalized() : Vec2{0.0, 1.0};
    orderContacts(contacts_, records_, start_, inverseMass_, up, grid_.cellSize(), orderScratch_);
    hasRigid_ = !ctx.bodies.empty() || !ctx.joints.empty(); // joints are solved in the rigid stage
    if (hasRigid_) rigid_.prepare(ctx, dt);
    frictions_.clear();
    frictionBodies_.clear();
    rotating_.clear();
    if (anyRotation_) findFriction(ctx);
}

void SolverMethod::findFriction(const StepContext& ctx) {
    const auto& circles = ctx.circles;
    const auto& segments = ctx.segments;
    // A pair's friction is the product of both materials' (as its bounciness is, and as Chipmunk does).
    buildFriction(
        contacts_, records_, circles, inverseMass_,
        [&](std::size_t k) {
            const ContactConstraint& c = contacts_[k];
            const double other = c.b < circleCount_
                                     ? circles[static_cast<std::size_t>(c.b)].material.friction
                                     : segments[static_cast<std::size_t>(c.b - circleCount_)].material.friction;
            return circles[static_cast<std::size_t>(c.a)].material.friction * other;
        },
        frictions_);
    buildFrictionBodies(circles, segments, bodies_.size(), frictionBodies_);
    omega_.assign(bodies_.size(), 0.0);
    marks_.assign(ctx.circles.size(), 0);
    const auto list = [&](int body) {
        if (body >= circleCount_ || marks_[static_cast<std::size_t>(body)] ||
            !isDynamic_[static_cast<std::size_t>(body)])
            return;
        marks_[static_cast<std::size_t>(body)] = 1;
        rotating_.push_back(body);
    };
    for (int i = 0; i < circleCount_; ++i)
        if (circles[static_cast<std::size_t>(i)].angularVelocity != 0.0) list(i);
    for (std::size_t k = 0; k < frictions_.size(); ++k) {
        if (frictions_[k].friction <= 0.0) continue;
        list(contacts_[k].a);
        list(contacts_[k].b);
    }
    if (hasRigid_) rigid_.listFrictionCircles(list);
    listJointedCircles(ctx.joints, list);
    for (const int i : rotating_)
        omega_[static_cast<std::size_t>(i)] = circles[static_cast<std::size_t>(i)].angularVelocity;
    turn_.assign(rotating_.size(), 0.0);
}

void SolverMethod::solve(const StepContext& ctx, double dt) {
    const int substeps = std::max(1, ctx.def.substeps);
    const double h = dt / substeps;
    const double hertz = std::min(kContactHertz, kMaxHertzPerSubstepRate / h);
    const Softness softness[2] = {makeSoftness(hertz, kDampingRatio, h),
                                  makeSoftness(kStaticHertzScale * hertz, kDampingRatio, h)};
    const Vec2 gravityStep = ctx.def.gravity * h;
    gaps_.resize(contacts_.size());
    const int relaxIterations = fastStep_ ? kFastRelaxIterations : kRelaxIterations;
    // Friction is solved with the soft sweep only: the relax passes restore the normal velocities
    // the push-out added, which friction does not depend on (and a third of the cost is saved).
    FrictionState frictionState{frictions_, frictionBodies_, omega_};
    const FrictionState* friction = anyRotation_ ? &frictionState : nullptr;
    if (hasRigid_) rigid_.bind(bodies_, anyRotation_ ? std::span<double>(omega_) : std::span<double>{}, ctx.circles);
    if (!hasRigid_) markWarmContacts();
    takeBackMagnetKicks(ctx, dt, substeps);
    for (int k = 0; k < substeps; ++k) {
        for (int i = 0; i < circleCount_; ++i)
            if (isDynamic_[i]) bodies_[i].velocity += gravityStep;
        for (std::size_t i = 0; i < pullSteps_.size(); ++i) bodies_[i].velocity += pullSteps_[i];
        if (hasRigid_) rigid_.integrateVelocities(gravityStep);
        if (hasRigid_) rigid_.warmStart();
        warmStartContacts(contacts_, bodies_, inverseMass_, friction);
        if (hasRigid_) rigid_.solve(h, true);
        solveContacts(contacts_, records_, bodies_, inverseMass_, softness, h, k, kMaxPushSpeed, friction);
        for (SolverBody& b : bodies_) b.displacement += b.velocity * h;
        for (std::size_t r = 0; r < rotating_.size(); ++r)
            turn_[r] += omega_[static_cast<std::size_t>(rotating_[r])] * h;
        if (hasRigid_) rigid_.integratePositions(h);
        for (int r = 0; r < relaxIterations; ++r) {
            if (hasRigid_) rigid_.solve(h, false, r >= kRigidContactRelaxPasses);
            relaxContacts(contacts_, records_, bodies_, inverseMass_, gaps_, r == 0, h, k);
        }
    }
    if (hasRigid_) rigid_.applyRestitution(ctx.restingSpeed);
    if (!hasRigid_) flyFreeCirclesExactly(ctx, dt);
    if (!pullKicks_.empty()) restPulledContacts(ctx, dt);
    // Rigid bodies hold circles through their own contacts, which the count of a circle's contacts
    // does not see; bullets are bounced by the continuous pass.
    // A circle a magnet pulls is not carried either: the carried flight knows gravity only.
    if (!hasRigid_)
        carryPastImpact(contacts_, records_, bodies_, ctx.circles, inverseMass_,
                        pullKicks_.empty() ? std::span<const std::uint8_t>(isBullet_) : notCarried(), circleCount_,
                        ctx.restingSpeed, ctx.def.gravity, dt, h);
    applyRestitution(contacts_, records_, bodies_, inverseMass_, ctx.restingSpeed, gravityStep);
    if (turning_) turningContacts_.detach(contacts_);
    tangentImpulses_.clear();
    if (anyRotation_)
        for (const FrictionTerms& f : frictions_) tangentImpulses_.push_back(f.impulse);
    cache_.store(contacts_, tangentImpulses_, circleCount_, segmentCount_);
}

// A magnet's pull, kicked in whole at the step's start (field_pass.cpp), brought a ball it holds on
// the magnet back at the kick's speed every step, a touch fast enough to bounce: a ball hanging still
// reported 0.23 m/s away from the magnet every step. As in exact (method_exact.cpp), the kick is taken
// back and given as gravity is, a share each substep, so the contact holds the ball as it holds one
// resting under gravity; after the step the velocity gets half the change of pull (finish: velocity
// Verlet, as exact). Asleep circles are not dynamic this step: the kick has woken any it reached.
void SolverMethod::takeBackMagnetKicks(const StepContext& ctx, double dt, int substeps) {
    pullKicks_.clear();
    pullSteps_.clear();
    if (ctx.magnets.empty()) return;
    pullKicks_.assign(static_cast<std::size_t>(circleCount_), Vec2{});
    pullSteps_.assign(static_cast<std::size_t>(circleCount_), Vec2{});
    for (int i = 0; i < circleCount_; ++i) {
        if (!isDynamic_[i]) continue;
        const Vec2 kick = magnetKick(ctx.magnets, ctx.circles[static_cast<std::size_t>(i)], dt);
        if (kick == Vec2{}) continue;
        bodies_[i].velocity -= kick;
        pullKicks_[static_cast<std::size_t>(i)] = kick;
        pullSteps_[static_cast<std::size_t>(i)] = kick / substeps;
    }
}

// The resting threshold is twice what gravity gives in a step (World::stepContext): a ball the pull
// presses on something gains 2 |g + a| dt in a step, and a touch no faster rests too (as exact's
// settle has it, exact_settle.cpp), or the ball the magnet holds would bounce off it every step.
void SolverMethod::restPulledContacts(const StepContext& ctx, double dt) {
    const auto threshold = [&](int body) {
        if (body >= circleCount_ || pullKicks_[static_cast<std::size_t>(body)] == Vec2{}) return 0.0;
        return 2.0 * (ctx.def.gravity * dt + pullKicks_[static_cast<std::size_t>(body)]).length() + 1e-3;
    };
    for (std::size_t k = 0; k < contacts_.size(); ++k) {
        ContactRecord& r = records_[k];
        if (r.firstTouch < 0 || r.bounciness == 0.0) continue;
        if (r.approachSpeed <= std::max(threshold(contacts_[k].a), threshold(contacts_[k].b))) r.bounciness = 0.0;
    }
}

void SolverMethod::markWarmContacts() {
    // A contact that starts the step warm (pushing since the last step) may push without ever being
    // marked as touching (ContactRecord::firstTouch): its circles are held, not in flight.
    inContact_.assign(isDynamic_.size(), 0);
    for (const ContactConstraint& c : contacts_) {
        if (c.impulse <= 0.0) continue;
        inContact_[static_cast<std::size_t>(c.a)] = 1;
        if (c.b < circleCount_) inContact_[static_cast<std::size_t>(c.b)] = 1;
    }
}

void SolverMethod::flyFreeCirclesExactly(const StepContext& ctx, double dt) {
    // The substeps' semi-implicit Euler (v += g h, then x += v h) puts a falling circle at
    // x0 + v0 t + g t (t + h) / 2: half a substep of gravity ahead of the exact parabola. A circle no
    // contact pushed this step (none warm at its start, none touching within it: its speculative
    // contacts only watched) felt nothing but gravity within the step (fields, drag and ropes act
    // between steps, in World; rigid bodies' steps are left alone), so it flies the exact method's
    // free flight instead: x1 = x0 + v0 dt + g dt^2 / 2, v1 = v0 + g dt. Its flight then starts every
    // bounce from the state as given, as the exact method's does. The substeps' path lies below the
    // exact one by g t h / 2, so a floor it did not touch the exact path does not touch either.
    for (std::size_t k = 0; k < contacts_.size(); ++k) {
        if (records_[k].firstTouch < 0) continue;
        const ContactConstraint& c = contacts_[k];
        inContact_[static_cast<std::size_t>(c.a)] = 1;
        if (c.b < circleCount_) inContact_[static_cast<std::size_t>(c.b)] = 1;
    }
    const Vec2 g = ctx.def.gravity;
    for (int i = 0; i < circleCount_; ++i) {
        if (!isDynamic_[i] || inContact_[static_cast<std::size_t>(i)]) continue;
        const Vec2 v0 = ctx.circles[static_cast<std::size_t>(i)].velocity;
        const Vec2 pull = pullKicks_.empty() ? Vec2{} : pullKicks_[static_cast<std::size_t>(i)];
        if (pull == Vec2{}) {
            bodies_[i] = {v0 + g * dt, v0 * dt + g * (0.5 * dt * dt)};
            continue;
        }
        // Pulled by a magnet: v0 less its kick, then g and the pull a = kick / dt as one acceleration.
        const Vec2 u = v0 - pull;
        bodies_[i] = {u + g * dt + pull, u * dt + (g * dt + pull) * (0.5 * dt)};
    }
}

void SolverMethod::finish(StepContext& ctx, double dt) {
    for (int i = 0; i < circleCount_; ++i) {
        Circle& c = ctx.circles[i];
        if (isDynamic_[i]) {
            c.position = start_[i] + bodies_[i].displacement;
            c.velocity = bodies_[i].velocity;
        } else if (c.motion == Motion::kinematic) {
            c.position = start_[i] + c.velocity * dt; // straight along this step's velocity
        }
    }
    for (std::size_t i = 0; i < pullKicks_.size(); ++i)
        if (pullKicks_[i] != Vec2{})
            ctx.circles[i].velocity += (magnetKick(ctx.magnets, ctx.circles[i], dt) - pullKicks_[i]) * 0.5;
    if (hasRigid_) rigid_.finish(ctx);
    for (std::size_t r = 0; r < rotating_.size(); ++r) {
        Circle& c = ctx.circles[static_cast<std::size_t>(rotating_[r])];
        c.angularVelocity = omega_[static_cast<std::size_t>(rotating_[r])];
        c.angle += turn_[r];
    }
    const std::size_t firstImpact = ctx.impacts.size();
    // The sweep sees segments at their start, moving with their velocity over the step.
    inFlight_.assign(isDynamic_.begin(), isDynamic_.end());
    if (hasRigid_)
        std::fill(inFlight_.begin(), inFlight_.end(), std::uint8_t{0}); // boxes' contacts are not listed here
    for (std::size_t k = 0; k < contacts_.size(); ++k) {
        const ContactConstraint& c = contacts_[k];
        if (c.impulse <= 0.0 && records_[k].firstTouch < 0) continue;
        inFlight_[static_cast<std::size_t>(c.a)] = 0;
        if (c.b < circleCount_) inFlight_[static_cast<std::size_t>(c.b)] = 0;
    }
    const SweepInput sweepInput{
        start_, margins_, bullets_, isBullet_, isDynamic_, cache_, inFlight_, kMaxSweepCellsPerAxis, connected_};
    int impacts = sweep_.run(sweepInput, grid_, ctx, dt);
    if (hasRigid_) impacts += rigid_.sweep(ctx, dt);
    for (Segment& seg : ctx.segments) {
        if (seg.motion() != Motion::kinematic) continue;
        seg.a += seg.velocity * dt;
        seg.b += seg.velocity * dt;
    }
    impacts += recordContactImpacts(contacts_, records_, ctx.circles, ctx);
    if (hasRigid_) impacts += rigid_.recordImpacts(ctx);
    // Report in time order; ties by circle and other body, so the order never depends on the sort.
    std::sort(ctx.impacts.begin() + static_cast<std::ptrdiff_t>(firstImpact), ctx.impacts.end(),
              [](const Impact& a, const Impact& b) {
                  if (a.time != b.time) return a.time < b.time;
                  if (a.circle != b.circle) return a.circle < b.circle;
                  if (a.otherKind != b.otherKind) return a.otherKind < b.otherKind;
                  if (a.other != b.other) return a.other < b.other;
                  return a.body < b.body;
              });
    ctx.stats.maxEventsInStep = std::max(ctx.stats.maxEventsInStep, impacts);
    if (ctx.sleep)
        sleep_.update(ctx.circles, ctx.segments, contacts_, dt, ctx.def.sleepSpeed, ctx.def.timeToSleep,
                      ctx.def.gravity, rigidSleep(ctx));
}

} // namespace

std::unique_ptr<StepMethod> makeSolverMethod() { return std::make_unique<SolverMethod>(); }

} // namespace rube
