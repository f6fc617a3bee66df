#pragma once
// Internal: the `solver` time-step method's class (method_solver.cpp: the step, the substeps and
// restitution; solver_find_contacts.cpp: its bodies' margins and the step's contacts, found once
// through the uniform grid). Not part of the public API; makeSolverMethod (step_method.hpp) makes one.
#include "broadphase_grid.hpp"
#include "joint_stage.hpp"
#include "magnet_pulls.hpp"
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

#include <cstdint>
#include <vector>

namespace rube {

/// A path longer than this many grid cells is not filed along its length: the body is a bullet.
inline constexpr int kMaxSweepCellsPerAxis = 8;
/// A step in which some dynamic circle travels more than this many radii gets one relax pass more:
/// a blow running down a row (a 100 m/s striker into ten balls against a wall) needs the third pass
/// to reach the far end before the row is squeezed. A falling pile stays under it (20 m/s, 3.3 radii).
inline constexpr double kFastTravelPerRadius = 5.0;
inline constexpr int kFastRelaxIterations = 3;

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
    void takeBackMagnetKicks(const StepContext& ctx, double dt);
    void restPulledContacts(const StepContext& ctx, double dt);
    // Per circle: a bullet, or pulled by a magnet this step (carryPastImpact leaves both alone).
    std::span<const std::uint8_t> notCarried() {
        notCarried_.assign(isBullet_.begin(), isBullet_.end());
        for (std::size_t i = 0; i < pulls_.size() && i < notCarried_.size(); ++i)
            if (pulls_.kick(i) != Vec2{}) notCarried_[i] = 1;
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
    MagnetPulls pulls_;                    // the magnets' kicks taken back this step (magnet_pulls.hpp)
    std::vector<std::uint8_t> notCarried_; // scratch: per circle, a bullet or pulled
};

} // namespace rube
