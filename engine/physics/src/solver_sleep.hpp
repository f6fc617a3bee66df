#pragma once
// Internal: sleeping for the solver, as Box2D's islands do it. A pile that has come to rest costs
// nothing: circles and rigid bodies that stay slow (under WorldDef::sleepSpeed, their surfaces' spin
// too: a rigid body's omega times its bounding radius) for WorldDef::timeToSleep together with
// everything they touch or a joint ties them to are put to sleep as one island, with zero velocity
// and spin, and the solver then treats them as fixed until something reaches them.
// Slow is not enough: a circle sleeps only while its contacts can hold it against gravity (the push
// gravity gives it, less what its contact normals, and with two contacts or more their friction
// cones, can cancel, is about zero), so a ball creeping down a shallow incline keeps sliding. A rigid
// body is held the same way by its contact points (a box on a slope steeper than its friction angle
// is not); a body a joint or pivot ends on is held by it (a joint can pull any way), and an island
// with a running motor (JointMotor on, speed not 0) never sleeps. A torque left over (a seesaw still
// tipping) is not in the test: it turns the body faster than sleepSpeed within timeToSleep unless it
// is smaller than sleepSpeed / (timeToSleep extent) per second squared, as in Box2D.
//
// What wakes an island, before the step solves anything:
//   - a velocity or spin changed from outside (an explosion, a field, the game's balloons);
//   - an awake dynamic circle near enough to be a candidate pair (its path's box for a bullet);
//   - an awake rigid body, or a moving kinematic one, whose contacts reach it (RigidStage::reached);
//   - a moving kinematic body (path-driven circle or segment) whose swept box reaches it;
//   - a joint whose other end is awake (a joint added to it between steps);
//   - a rope whose other end is awake or a moving kinematic circle.
// Ropes (solver_sleep_ropes.cpp) are part of the islands though the world enforces them after the
// method: a rope's two circles share an island, a taut rope holds its circle towards its other end
// (one ray, as a frictionless contact: a pendulum hanging straight down is held, one held aside is
// not), and a circle's speed is judged as the rope will leave it (less the stretching speed the
// rope takes out after the step), so a weight hanging still is slow although the solver has just
// given it g dt.
// A waking island starts slow from zero again. Sleeping changes nothing a settled scene shows: the
// bodies it stops were slower than a centimetre a second and held where they were; only a drift
// that nothing pushes (under 1 cm/s, on a level floor or in free flight) is stopped with them.

#include "broadphase_grid.hpp"
#include "rigid_contacts.hpp"
#include "rube/physics/joint.hpp"
#include "rube/physics/pivot.hpp"
#include "rube/physics/rigid_body.hpp"
#include "rube/physics/rope.hpp"
#include "solver_soft_step.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace rube {

/// Wakes every asleep circle and rigid body (a method that does not keep sleep is about to move them).
void wakeAll(std::span<Circle> circles, std::span<RigidBody> bodies = {});

/// The rigid part of the islands, empty in a world of circles only.
struct RigidSleepInput {
    std::span<RigidBody> bodies;
    std::span<const RigidContact> contacts; ///< the step's rigid contacts (RigidStage::contacts)
    std::span<const Joint> joints;
    std::span<const Pivot> pivots;
    std::span<const int> reached; ///< sleepers an awake or moving body's contacts reach: circle c, or -1 - body
    std::span<const Rope> ropes;  ///< the world's ropes (solver_sleep_ropes.cpp), in any world
    std::span<const std::uint8_t> stalledMotors = {}; ///< per joint: 1 where its motor is stalled at a limit
};

/// The circles a step looks at to wake and put islands to sleep.
class SleepIslands {
public:
    /// Before the step: wakes the islands of sleepers whose velocity or spin was changed from
    /// outside, that an awake dynamic circle is within contact margins of (`margins` per solver body), that a bullet's
    /// path box
    /// (`bulletPaths`) or a moving kinematic body's swept box reaches. `circleBoxes` and
    /// `segmentBoxes` are the step's contact boxes (kinematic ones swept over the step). True when
    /// any island woke: the caller then finds the step's contacts again.
    bool wakeReached(std::span<Circle> circles, std::span<const Segment> segments, std::span<const CandidatePair> pairs,
                     std::span<const double> margins, std::span<const BoundingBox> circleBoxes,
                     std::span<const BoundingBox> segmentBoxes, std::span<const BoundingBox> bulletPaths,
                     const RigidSleepInput& rigid);

    /// After the step: counts how long each awake dynamic circle has been slow, joins circles with a
    /// contact (speculative ones too) into islands, and puts to sleep every island that has been
    /// slow for `timeToSleep`, whose every member its contacts hold against `gravity`, and that is
    /// not carried by a moving kinematic body.
    void update(std::span<Circle> circles, std::span<const Segment> segments,
                std::span<const ContactConstraint> contacts, double dt, double sleepSpeed, double timeToSleep,
                Vec2 gravity, const RigidSleepInput& rigid);

private:
    /// Per node in update: not an awake dynamic body, awake but not slow for long enough, or ready to sleep.
    enum : std::uint8_t { other, awake, ready };
    /// The directions a circle's contacts can push it in, kept as the nearest to `up` on either side
    /// (in 2-D two rays span every cone the others do: Caratheodory for cones).
    struct HoldRays {
        Vec2 left, right;                       // unit rays counter-clockwise and clockwise of up
        double leftDot = -2.0, rightDot = -2.0; // their cosines with up; -2: none yet
        void offer(Vec2 up, Vec2 ray);
        bool holds(Vec2 up, double push) const;
    };
    int find(int i);
    void join(int a, int b); // the lower root names the island, so one with a circle is named by a circle
    void demoteUnheld(std::span<const Circle> circles, std::span<const Segment> segments,
                      std::span<const ContactConstraint> contacts, Vec2 gravity, const RigidSleepInput& rigid);
    void countSlowBodies(const RigidSleepInput& rigid, int circleCount, double dt, double sleepSpeed,
                         double timeToSleep, int& readyCount);
    void joinRigid(std::span<const Circle> circles, std::span<const Segment> segments, const RigidSleepInput& rigid);
    // Ropes (solver_sleep_ropes.cpp): the velocities the rope pass will leave, the rays taut ropes
    // hold along, the islands they join, and the sleepers a rope from an awake end reaches.
    std::span<const Vec2> ropeVelocities(std::span<const Circle> circles, std::span<const Rope> ropes);
    void offerRopeRays(std::span<const Circle> circles, std::span<const Rope> ropes, Vec2 up);
    void joinRopes(std::span<const Circle> circles, std::span<const Rope> ropes);
    static void ropeReached(std::span<const Circle> circles, std::span<const Rope> ropes, std::vector<int>& reached);

    // Nodes: the circles, then the rigid bodies (circle count + body index).
    std::vector<int> parent_;            // union-find over the nodes ready to sleep
    std::vector<std::uint8_t> state_;    // per node: other, awake or ready (update's enum)
    std::vector<std::uint8_t> slowness_; // scratch: per circle, moving, slow, or slow but spinning
    std::vector<std::uint8_t> blocked_; // per circle, then per root: touches an awake circle or a moving kinematic body
    std::vector<int> asleep_;           // scratch: the sleepers this step
    std::vector<int> asleepBodies_;     // scratch: the rigid sleepers this step
    std::vector<std::uint8_t> islandReached_; // scratch: per island (a circle index), something reached it this step
    std::vector<std::uint8_t> rigidIslandReached_; // scratch: per island named -1 - body, by body
    std::vector<std::uint8_t> jointHeld_;          // scratch: per node, a joint or pivot ends on it
    std::vector<HoldRays> normalRays_,
        coneRays_;             // scratch: per node, what its contacts' normals, and friction cones, can push
    std::vector<int> holding_; // scratch: per node, its contact points that can push
    std::vector<int> ropeReached_;   // scratch: asleep circles a rope from an awake or moving end reaches
    std::vector<Vec2> ropeVelocity_; // scratch: per circle, its velocity once the ropes have taken their stretch out
};

} // namespace rube
