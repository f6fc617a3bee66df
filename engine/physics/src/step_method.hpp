#pragma once
// Internal: the one interface every time-step method implements. Not part of the public API.

#include "rube/physics/fields.hpp"
#include "rube/physics/world.hpp"

#include <memory>
#include <span>
#include <vector>

namespace rube {

struct SlotRemap;
class WorkerPool;

/// What a method may touch during one step. Kinematic bodies already carry this step's velocity;
/// a method moves them linearly with it (the world snaps them onto their path afterwards).
struct StepContext {
    const WorldDef& def;
    std::span<Circle> circles;
    std::span<Segment> segments;
    std::span<RigidBody> bodies;        ///< boxes and capsules (only the methods that model them move them)
    double time;                        ///< world time at the start of the step
    double restingSpeed;                ///< resolved from def.restingSpeed (never 0)
    std::vector<Impact>& impacts;       ///< append every impact resolved, in order
    StepStats& stats;                   ///< add impacts, resting contacts, caps hit; set maxEventsInStep
    std::span<const Pivot> pivots = {}; ///< rigid bodies pinned to the world (the solver models them)
    std::span<const Rope> ropes =
        {}; ///< the world's ropes (the world enforces them after the step; auto keeps roped circles together)
    std::span<const Joint> joints =
        {};             ///< the joints that act (the solver models them; auto gives their islands to it)
    WorkerPool* workers = nullptr; ///< the world's threads (WorldDef::workers); null runs everything here
    /// The world's magnets, whose kick (field_pass.hpp) every magnetic circle has had at this step's
    /// start. The exact method takes the kick back and moves the circle under the pull as it does under
    /// gravity, so that a ball the pull holds on the magnet rests there (field_pass.cpp has no contacts).
    std::span<const Magnet> magnets = {};
    bool sleep = false; ///< islands may fall asleep this step (WorldDef::sleepSpeed; rigid bodies, joints, ropes:
                        ///< keepsRigidSleep)
};

/// A time-step method: advances every body over dt.
class StepMethod {
public:
    virtual ~StepMethod() = default;
    virtual void step(StepContext& context, double dt) = 0;
    /// True when the method turns circles itself (friction torques); otherwise the world carries
    /// each circle's angle on at its constant angular velocity.
    virtual bool integratesRotation() const { return false; }
    /// True when the method honours asleep circles (and wakes them itself); the world wakes every
    /// circle before a method that does not.
    virtual bool keepsSleep() const { return false; }
    /// True when the method's islands take rigid bodies, pivots and joints too (the solver's); a
    /// method that keeps only the circles' sleep is given no sleep in a world with any of them.
    virtual bool keepsRigidSleep() const { return false; }
    /// Bodies left or (re)entered the world's arrays between steps: what the method keeps per body
    /// from step to step (warm starts, stints) follows them to their new slots (world_handles.hpp),
    /// so a world goes on as if what left had never been there.
    virtual void remapSlots(const SlotRemap&) {}
    /// True when the method can take a step of a world entirely asleep and still (quiet_step.hpp)
    /// as restQuietly, without its per-body passes: the solver in a world without rigid bodies or joints.
    virtual bool restsQuietly(const StepContext&) const { return false; }
    /// Such a step: changes in the method's own state only what its full step of that world would.
    virtual void restQuietly(StepContext&) {}
};

std::unique_ptr<StepMethod> makeDiscreteMethod();
std::unique_ptr<StepMethod> makeTurnBasedMethod();
std::unique_ptr<StepMethod> makeExactMethod();
std::unique_ptr<StepMethod> makeSolverMethod();
std::unique_ptr<StepMethod> makeAutoMethod();

} // namespace rube
