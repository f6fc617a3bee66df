// The `auto` time-step method: the cheapest method that holds, chosen step by step from what the
// scene is doing. The exact method is the reference and costs little while bodies are few and
// impacts sparse; it stops being cheap (its search is O(n^2) per event) and stops holding (no
// friction, no rolling) as soon as contacts pile up or friction matters. The solver holds there.
// Continuous detection comes with both: exact is continuous by construction, and the solver
// sweeps only the circles that are fast relative to their size (solver_sweep), so slow bodies
// never pay for it.
//
// The rule, checked every step (each test is O(n), against a step's O(n) or more):
//   1. a pair that could touch with friction (a dynamic circle and another shape, both with
//      friction > 0): solver, the only method with Coulomb friction and rolling;
//   2. otherwise exact, if it can be afforded: every event it resolves costs a search over the
//      n x (n + m) pairs, so it is given kExactBudget pair tests a step, that is kExactBudget /
//      (n (n + m)) events. When that is fewer than kFewestEvents (a thousand balls allow none)
//      the solver takes the step. Otherwise exact runs with that event cap; a step that reaches
//      it is a crowd (a pile, a stack being struck), so the state is put back as it was and the
//      solver takes this step and the next ones, for a stint that doubles each time exact fails
//      again (a lasting crowd costs one failed trial per stint, not one per step).
// The measure is a count of work, never a clock, so the choice is the same on every machine.
#include "solver_sleep.hpp"
#include "step_method.hpp"

#include <algorithm>
#include <cstdint>

namespace rube {
namespace {

constexpr std::int64_t kExactBudget = 65536; // pair tests a step may spend on exact searches
constexpr std::int64_t kFewestEvents = 16;    // fewer affordable than this and exact is not tried
constexpr int kFirstStint = 30;   // steps on the solver after exact first fails
constexpr int kLongestStint = 960;

class AutoMethod final : public StepMethod {
public:
    AutoMethod() : exact_(makeExactMethod()) {}

    void step(StepContext& ctx, double dt) override {
        const std::int64_t affordable = affordableEvents(ctx);
        const bool solverNow = solverStepsLeft_ > 0 || affordable < kFewestEvents || frictionPair(ctx) ||
                               anyTurning(ctx.bodies, ctx.pivots); // turning bodies and pivots: only the solver models them
        // Exact moves every body: sleepers (the solver's) wake before it tries.
        if (!solverNow) wakeAll(ctx.circles);
        if (!solverNow && tryExact(ctx, dt, affordable)) {
            ctx.stats.exactBodySteps += dynamicBodies(ctx);
            usedSolver_ = false;
            stint_ = kFirstStint;
            return;
        }
        if (!solverNow) {
            // Exact gave up on this step: the solver takes it and the next stint_ - 1 steps.
            solverStepsLeft_ = stint_;
            stint_ = std::min(2 * stint_, kLongestStint);
        }
        if (solverStepsLeft_ > 0) --solverStepsLeft_;
        // A solver that sat out some steps starts afresh: its warm-start impulses belong to contacts
        // that have since moved.
        if (!usedSolver_ || !solver_) solver_ = makeSolverMethod();
        usedSolver_ = true;
        ++ctx.stats.autoSolverSteps;
        ctx.stats.solverBodySteps += dynamicBodies(ctx);
        solver_->step(ctx, dt);
    }

    bool integratesRotation() const override { return usedSolver_; }
    bool keepsSleep() const override { return true; }

private:
    static std::int64_t dynamicBodies(const StepContext& ctx) {
        return static_cast<std::int64_t>(
            std::count_if(ctx.circles.begin(), ctx.circles.end(), [](const Circle& c) { return c.motion == Motion::dynamic; }) +
            std::count_if(ctx.bodies.begin(), ctx.bodies.end(), [](const RigidBody& b) { return b.motion == Motion::dynamic; }));
    }

    // How many events exact may resolve this step within the budget: one search is a test of
    // every dynamic circle against every shape.
    static std::int64_t affordableEvents(const StepContext& ctx) {
        const auto dynamic = static_cast<std::int64_t>(
            std::count_if(ctx.circles.begin(), ctx.circles.end(), [](const Circle& c) { return c.motion == Motion::dynamic; }) +
            std::count_if(ctx.bodies.begin(), ctx.bodies.end(), [](const RigidBody& b) { return b.motion == Motion::dynamic; }));
        const auto shapes = static_cast<std::int64_t>(ctx.circles.size() + ctx.segments.size() + ctx.bodies.size());
        return kExactBudget / std::max<std::int64_t>(1, dynamic * shapes);
    }

    static bool frictionPair(const StepContext& ctx) {
        int dynamicWithFriction = 0;
        bool otherWithFriction = false;
        for (const Circle& c : ctx.circles) {
            if (c.material.friction <= 0.0) continue;
            if (c.motion == Motion::dynamic) ++dynamicWithFriction;
            else otherWithFriction = true;
        }
        // A pair's friction is the product of both: it takes two with friction to make one.
        if (dynamicWithFriction == 0) return false;
        if (dynamicWithFriction > 1 || otherWithFriction) return true;
        return std::any_of(ctx.segments.begin(), ctx.segments.end(), [](const Segment& s) { return s.material.friction > 0.0; });
    }

    // Exact under the affordable event cap; false (with everything put back as it was) when it hits it.
    bool tryExact(StepContext& ctx, double dt, std::int64_t affordable) {
        circlesBefore_.assign(ctx.circles.begin(), ctx.circles.end());
        segmentsBefore_.assign(ctx.segments.begin(), ctx.segments.end());
        bodiesBefore_.assign(ctx.bodies.begin(), ctx.bodies.end()); // lecture 3's blocks move under exact too
        const std::size_t impactsBefore = ctx.impacts.size();
        const StepStats statsBefore = ctx.stats;
        WorldDef trialDef = ctx.def;
        trialDef.maxEventsPerStep = static_cast<int>(std::min<std::int64_t>(ctx.def.maxEventsPerStep, affordable));
        StepContext trial{trialDef, ctx.circles, ctx.segments, ctx.bodies, ctx.time, ctx.restingSpeed, ctx.impacts, ctx.stats, ctx.pivots};
        exact_->step(trial, dt);
        if (ctx.stats.capsHit == statsBefore.capsHit) return true;
        std::copy(circlesBefore_.begin(), circlesBefore_.end(), ctx.circles.begin());
        std::copy(segmentsBefore_.begin(), segmentsBefore_.end(), ctx.segments.begin());
        std::copy(bodiesBefore_.begin(), bodiesBefore_.end(), ctx.bodies.begin());
        ctx.impacts.resize(impactsBefore);
        ctx.stats = statsBefore;
        return false;
    }

    std::unique_ptr<StepMethod> exact_;
    std::unique_ptr<StepMethod> solver_;
    bool usedSolver_ = false;
    int solverStepsLeft_ = 0;
    int stint_ = kFirstStint;
    std::vector<Circle> circlesBefore_;
    std::vector<Segment> segmentsBefore_;
    std::vector<RigidBody> bodiesBefore_;
};

} // namespace

std::unique_ptr<StepMethod> makeAutoMethod() { return std::make_unique<AutoMethod>(); }

} // namespace rube
