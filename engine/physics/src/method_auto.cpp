// The `auto` time-step method: the cheapest method that holds, chosen step by step and island by
// island from what the scene is doing. The exact method is the reference and costs little while
// bodies are few and impacts sparse; it stops being cheap (its search is O(n^2) per event) and
// stops holding (no friction, no rolling, no turning bodies) as soon as contacts pile up or
// friction matters. The solver holds there. Continuous detection comes with both: exact is
// continuous by construction, and the solver sweeps only the circles that are fast relative to
// their size (solver_sweep), so slow bodies never pay for it.
//
// Each step the bodies are grouped into islands (auto_islands: bodies that could meet within the
// step), and each island gets its method:
//   1. the solver, if only the solver models it: a pair that could touch with friction (a dynamic
//      circle with friction and another shape with friction), a turning body, a pivot, a joint
//      (a joint's ends share an island);
//   2. the solver, if exact cannot be afforded for its neighbourhood (the islands a body's size
//      apart, a crowd forming): every event exact resolves costs a search over the n x (n + m)
//      pairs, and it is given kExactBudget pair tests a step, that is kExactBudget / (n (n + m))
//      events; fewer than kFewestEvents (a thousand balls allow none) and the solver takes it;
//   3. the solver, if the island is serving a stint there (below);
//   4. exact otherwise. All exact islands run together as one exact step (so a scene that is all
//      exact takes exact's steps bit for bit) under the event cap their union affords; when even
//      their union cannot be afforded, the most crowded neighbourhoods go to the solver first. A trial that reaches the
//      cap is a crowd (a pile, a stack being struck): the state is put back, the island with the most impacts in the
//      trial goes to the solver for a stint that doubles each time exact fails on it again (a lasting crowd costs one
//      failed trial per stint, not one per step), and the others try again once.
// The solver islands then run together as one solver step, on the world itself with exact's
// bodies shown as fixed. Static segments and non-dynamic circles are shared; rigid bodies, ropes
// and sleepers stay within their islands. The measure is a
// count of work, never a clock, and islands go in order of their lowest body index, so the choice
// is the same on every machine.
#include "auto_islands.hpp"
#include "auto_subset.hpp"
#include "exact_springs.hpp"
#include "solver_sleep.hpp"
#include "step_method.hpp"
#include "world_handles.hpp"

#include <algorithm>
#include <cstdint>

namespace rube {
namespace {

constexpr std::int64_t kExactBudget = 65536; // pair tests a step may spend on exact searches
constexpr std::int64_t kFewestEvents = 16;   // fewer affordable than this and exact is not tried
constexpr int kFirstStint = 30;              // steps on the solver after exact first fails
constexpr int kLongestStint = 960;
constexpr int kExactTrials = 2;
// A world of more dynamic bodies than this that was wholly the solver's (a pile) keeps the solver
// for a few steps before its islands are looked at again, 8 and doubling up to 64 while it stays
// wholly the solver's: the island pass costs about what the solver's broadphase does, and a
// thousand balls at rest would pay it every step for nothing.
constexpr std::int64_t kBigWorld = 64;
constexpr int kFirstRecheck = 8;
constexpr int kLongestRecheck = 64; // exact trials a step: the first, and one without the island blamed

// How many events exact may resolve within the budget, for `dynamic` moving bodies among `shapes`.
std::int64_t affordableEvents(std::int64_t dynamic, std::int64_t shapes) {
    return kExactBudget / std::max<std::int64_t>(1, dynamic * shapes);
}

class AutoMethod final : public StepMethod {
public:
    AutoMethod() : exact_(makeExactMethod()) {}

    void step(StepContext& ctx, double dt) override {
        const std::size_t nodeCount = ctx.circles.size() + ctx.bodies.size();
        if (stintLeft_.size() != nodeCount || circleCount_ != ctx.circles.size()) {
            // Bodies were added: node numbers mean other bodies now.
            stintLeft_.assign(nodeCount, 0);
            stintLength_.assign(nodeCount, kFirstStint);
            circleCount_ = ctx.circles.size();
            solverOnlyFor_ = 0;
        }
        const bool ranSolverBefore = usedSolver_;
        usedSolver_ = false;
        if (solverOnlyFor_ == 0 && wholeWorldExact(ctx, dt)) {
            for (int& left : stintLeft_)
                if (left > 0) --left;
            return;
        }
        if (solverOnlyFor_ > 0) {
            // A big world that was wholly the solver's a step ago: it is the solver's again (the
            // solver holds everywhere), and the islands are looked at again in a few steps.
            --solverOnlyFor_;
            onExact_.assign(1, 0);
            runSolver(ctx, dt, false, ranSolverBefore, dynamicBodies(ctx));
        } else {
            islands_.build(ctx, dt);
            choose(ctx);
            const bool exactOnSubset = runExact(ctx, dt);
            runSolver(ctx, dt, exactOnSubset, ranSolverBefore, dynamicBodiesOn(false));
            const std::int64_t dynamic = dynamicBodiesOn(true) + dynamicBodiesOn(false);
            if (dynamic > kBigWorld && dynamicBodiesOn(true) == 0) {
                solverOnlyFor_ = recheck_ - 1;
                recheck_ = std::min(2 * recheck_, kLongestRecheck);
            } else {
                recheck_ = kFirstRecheck;
            }
        }
        for (int& left : stintLeft_)
            if (left > 0) --left;
    }

    bool integratesRotation() const override { return usedSolver_; }
    bool keepsSleep() const override { return true; }
    // The solver's islands sleep whole (rigid bodies, pivots and joints with them), and an asleep
    // island stays one auto island (AutoIslands::build), so it is never split between the methods;
    // exact wakes whatever it is given before it moves it.
    bool keepsRigidSleep() const override { return true; }
    void remapSlots(const SlotRemap& remap) override {
        exact_->remapSlots(remap);
        if (solver_) solver_->remapSlots(remap);
        // Stints follow their nodes (circles, then rigid bodies), unless they were already stale.
        const std::size_t oldCircles = remap.circles.to.size(), oldNodes = oldCircles + remap.bodies.to.size();
        if (stintLeft_.size() != oldNodes || circleCount_ != oldCircles) return;
        SlotMap nodes;
        nodes.size = remap.circles.size + remap.bodies.size;
        nodes.to.resize(oldNodes);
        for (std::size_t n = 0; n < oldNodes; ++n) {
            const int old = static_cast<int>(n);
            const int to = n < oldCircles ? remap.circles(old) : remap.bodies(old - static_cast<int>(oldCircles));
            nodes.to[n] = to < 0 ? -1 : n < oldCircles ? to : remap.circles.size + to;
        }
        remapParallel(stintLeft_, nodes, 0);
        remapParallel(stintLength_, nodes, kFirstStint);
        circleCount_ = static_cast<std::size_t>(remap.circles.size);
    }

private:
    // The whole world on exact without an island pass, when nothing in it could need the solver
    // (no pair with friction, nothing turning, no stint) and exact's events over all of it can be
    // afforded: what the island pass would choose, at the old cost. False when it does not apply
    // or exact hit its cap (everything put back; the island pass then decides).
    bool wholeWorldExact(StepContext& ctx, double dt) {
        if (frictionPair(ctx) || anyTurning(ctx.bodies, ctx.pivots) || !ctx.joints.empty() ||
            std::any_of(stintLeft_.begin(), stintLeft_.end(), [](int left) { return left > 0; }))
            return false;
        const std::int64_t dynamic = dynamicBodies(ctx);
        const auto shapes = static_cast<std::int64_t>(ctx.circles.size() + ctx.segments.size() + ctx.bodies.size());
        const std::int64_t affordable = affordableEvents(dynamic, shapes);
        if (affordable < kFewestEvents) return false;
        wakeAll(ctx.circles, ctx.bodies); // exact moves every body: the solver's sleepers wake first
        circlesBefore_.assign(ctx.circles.begin(), ctx.circles.end());
        segmentsBefore_.assign(ctx.segments.begin(), ctx.segments.end());
        bodiesBefore_.assign(ctx.bodies.begin(), ctx.bodies.end());
        const std::size_t impactsBefore = ctx.impacts.size();
        const StepStats statsBefore = ctx.stats;
        WorldDef trialDef = ctx.def;
        trialDef.maxEventsPerStep = static_cast<int>(std::min<std::int64_t>(ctx.def.maxEventsPerStep, affordable));
        StepContext trial{trialDef,         ctx.circles, ctx.segments, ctx.bodies, ctx.time,
                          ctx.restingSpeed, ctx.impacts, ctx.stats,    ctx.pivots, ctx.ropes};
        trial.sleep = ctx.sleep;
        trial.magnets = ctx.magnets;
        exact_->step(trial, dt);
        if (ctx.stats.capsHit == statsBefore.capsHit) {
            ctx.stats.exactBodySteps += dynamic;
            std::fill(stintLength_.begin(), stintLength_.end(), kFirstStint);
            recheck_ = kFirstRecheck;
            return true;
        }
        std::copy(circlesBefore_.begin(), circlesBefore_.end(), ctx.circles.begin());
        std::copy(segmentsBefore_.begin(), segmentsBefore_.end(), ctx.segments.begin());
        std::copy(bodiesBefore_.begin(), bodiesBefore_.end(), ctx.bodies.begin());
        ctx.impacts.resize(impactsBefore);
        ctx.stats = statsBefore;
        return false;
    }

    // True when a pair could touch with friction somewhere (a pair's friction is the product of
    // both: it takes two surfaces with friction).
    static bool frictionPair(const StepContext& ctx) {
        int dynamicWithFriction = 0;
        bool otherWithFriction = false;
        for (const Circle& c : ctx.circles) {
            if (c.material.friction <= 0.0) continue;
            if (c.motion == Motion::dynamic) ++dynamicWithFriction;
            else otherWithFriction = true;
        }
        if (dynamicWithFriction == 0) return false;
        if (dynamicWithFriction > 1 || otherWithFriction) return true;
        return std::any_of(ctx.segments.begin(), ctx.segments.end(),
                           [](const Segment& s) { return s.material.friction > 0.0; });
    }

    static std::int64_t dynamicBodies(const StepContext& ctx) {
        return static_cast<std::int64_t>(std::count_if(ctx.circles.begin(), ctx.circles.end(),
                                                       [](const Circle& c) { return c.motion == Motion::dynamic; }) +
                                         std::count_if(ctx.bodies.begin(), ctx.bodies.end(),
                                                       [](const RigidBody& b) { return b.motion == Motion::dynamic; }));
    }

    std::int64_t sharedShapes(const StepContext& ctx) const {
        const auto circles = std::count_if(ctx.circles.begin(), ctx.circles.end(),
                                           [](const Circle& c) { return c.motion != Motion::dynamic; });
        return static_cast<std::int64_t>(circles) + static_cast<std::int64_t>(ctx.segments.size());
    }

    bool inStint(const Island& island) const {
        const auto members = islands_.members(island);
        return std::any_of(members.begin(), members.end(),
                           [&](int n) { return stintLeft_[static_cast<std::size_t>(n)] > 0; });
    }

    // Rules 1 to 3 of the header, and rule 4's union: fills onExact_ per island.
    void choose(const StepContext& ctx) {
        const auto islands = islands_.islands();
        const std::int64_t shared = sharedShapes(ctx);
        onExact_.assign(islands.size(), 0);
        crowdDynamic_.assign(stintLeft_.size(), 0);
        crowdNodes_.assign(stintLeft_.size(), 0);
        for (std::size_t k = 0; k < islands.size(); ++k) {
            const Island& island = islands[k];
            if (island.needsSolver || (island.dynamicBodies > 0 && inStint(island))) continue;
            onExact_[k] = 1;
            if (island.dynamicBodies == 0) continue;
            crowdDynamic_[static_cast<std::size_t>(island.neighbourhood)] += island.dynamicBodies;
            crowdNodes_[static_cast<std::size_t>(island.neighbourhood)] += island.count;
        }
        std::int64_t dynamic = 0, nodes = 0;
        for (std::size_t k = 0; k < islands.size(); ++k) {
            if (!onExact_[k] || islands[k].dynamicBodies == 0) continue;
            const auto n = static_cast<std::size_t>(islands[k].neighbourhood);
            if (affordableEvents(crowdDynamic_[n], crowdNodes_[n] + shared) < kFewestEvents) {
                onExact_[k] = 0;
                continue;
            }
            dynamic += islands[k].dynamicBodies;
            nodes += islands[k].count;
        }
        if (affordableEvents(dynamic, nodes + shared) >= kFewestEvents) return;
        // Their union costs too much: the most crowded neighbourhoods go to the solver first (ties:
        // the lowest), until what is left can be afforded.
        crowds_.clear();
        for (std::size_t k = 0; k < islands.size(); ++k)
            if (onExact_[k] && islands[k].dynamicBodies > 0 &&
                std::find(crowds_.begin(), crowds_.end(), islands[k].neighbourhood) == crowds_.end())
                crowds_.push_back(islands[k].neighbourhood);
        std::sort(crowds_.begin(), crowds_.end(), [&](int x, int y) {
            const std::int64_t cx = crowdDynamic_[static_cast<std::size_t>(x)],
                               cy = crowdDynamic_[static_cast<std::size_t>(y)];
            return cx > cy || (cx == cy && x < y);
        });
        for (const int crowd : crowds_) {
            dynamic -= crowdDynamic_[static_cast<std::size_t>(crowd)];
            nodes -= crowdNodes_[static_cast<std::size_t>(crowd)];
            for (std::size_t k = 0; k < islands.size(); ++k)
                if (islands[k].neighbourhood == crowd && islands[k].dynamicBodies > 0) onExact_[k] = 0;
            if (affordableEvents(dynamic, nodes + shared) >= kFewestEvents) return;
        }
    }

    // Dynamic bodies in the islands on exact (`exact`) or on the solver.
    std::int64_t dynamicBodiesOn(bool exact) const {
        std::int64_t count = 0;
        const auto islands = islands_.islands();
        for (std::size_t k = 0; k < islands.size(); ++k)
            if ((onExact_[k] != 0) == exact) count += islands[k].dynamicBodies;
        return count;
    }

    bool allOnExact() const {
        return std::all_of(onExact_.begin(), onExact_.end(), [](std::uint8_t e) { return e != 0; });
    }

    // Per node: 1 when its island is on exact (`exact`) or on the solver.
    void markChosen(std::size_t nodeCount, bool exact) {
        chosen_.assign(nodeCount, 0);
        const auto islands = islands_.islands();
        for (std::size_t k = 0; k < islands.size(); ++k)
            if ((onExact_[k] != 0) == exact)
                for (int n : islands_.members(islands[k])) chosen_[static_cast<std::size_t>(n)] = 1;
    }

    // Runs exact on the islands chosen for it; true when it ran on only some of the bodies (the
    // solver then runs on the rest against the segments as they were before exact moved them).
    bool runExact(StepContext& ctx, double dt) {
        for (int trial = 0; trial < kExactTrials; ++trial) {
            const std::int64_t dynamic = dynamicBodiesOn(true);
            if (dynamic == 0) return false;
            const bool whole = allOnExact();
            markChosen(stintLeft_.size(), true);
            // Exact moves every body it is given: the solver's sleepers among them wake first.
            for (std::size_t i = 0; i < ctx.circles.size(); ++i)
                if (chosen_[i] && ctx.circles[i].sleep.asleep) ctx.circles[i].sleep = SleepState{};
            for (std::size_t b = 0; b < ctx.bodies.size(); ++b)
                if (chosen_[ctx.circles.size() + b] && ctx.bodies[b].sleep.asleep) ctx.bodies[b].sleep = SleepState{};
            const int blamed = tryExact(ctx, dt, whole);
            if (blamed < 0) {
                ctx.stats.exactBodySteps += dynamic;
                for (std::size_t n = 0; n < chosen_.size(); ++n)
                    if (chosen_[n]) stintLength_[n] = kFirstStint;
                return !whole;
            }
            // The blamed island serves a stint on the solver; the others may try once more.
            for (int n : islands_.members(islands_.islands()[static_cast<std::size_t>(blamed)])) {
                stintLeft_[static_cast<std::size_t>(n)] = stintLength_[static_cast<std::size_t>(n)];
                stintLength_[static_cast<std::size_t>(n)] = std::min(2 * stintLength_[static_cast<std::size_t>(n)],
                                                                     kLongestStint);
            }
            onExact_[static_cast<std::size_t>(blamed)] = 0;
        }
        for (std::size_t k = 0; k < onExact_.size(); ++k)
            if (islands_.islands()[k].dynamicBodies > 0) onExact_[k] = 0;
        return false;
    }

    // Exact under the affordable event cap on the chosen bodies (all of them when `whole`): -1
    // when it held, else (with everything put back as it was) the island with the most impacts.
    int tryExact(StepContext& ctx, double dt, bool whole) {
        segmentsBefore_.assign(ctx.segments.begin(), ctx.segments.end());
        const std::size_t impactsBefore = ctx.impacts.size();
        const StepStats statsBefore = ctx.stats;
        if (whole) {
            circlesBefore_.assign(ctx.circles.begin(), ctx.circles.end());
            bodiesBefore_.assign(ctx.bodies.begin(), ctx.bodies.end()); // lecture 3's blocks move under exact too
        } else {
            exactSubset_.gather(ctx, chosen_);
        }
        WorldDef trialDef = ctx.def;
        const std::int64_t shapes = whole ? static_cast<std::int64_t>(ctx.circles.size() + ctx.segments.size() +
                                                                      ctx.bodies.size())
                                          : static_cast<std::int64_t>(exactSubset_.circleIndices().size() +
                                                                      ctx.segments.size() +
                                                                      exactSubset_.bodyIndices().size());
        const std::int64_t affordable = affordableEvents(dynamicBodiesOn(true), shapes);
        trialDef.maxEventsPerStep = static_cast<int>(std::min<std::int64_t>(ctx.def.maxEventsPerStep, affordable));
        // A spring whose circle an impact knocked off its closed form (exact_springs.hpp) fails the
        // trial as a cap does: exact has put its bodies back.
        bool springLost = false;
        int lostNode = -1;
        try {
            if (whole) {
                StepContext trial{trialDef,         ctx.circles, ctx.segments, ctx.bodies, ctx.time,
                                  ctx.restingSpeed, ctx.impacts, ctx.stats,    ctx.pivots, ctx.ropes};
                trial.sleep = ctx.sleep;
                trial.joints = ctx.joints;
                trial.magnets = ctx.magnets;
                exact_->step(trial, dt);
            } else {
                StepContext trial = exactSubset_.context(ctx, trialDef);
                exact_->step(trial, dt);
            }
        } catch (const SpringNotExact& lost) {
            springLost = true;
            lostNode = lost.circle < 0 || whole ? lost.circle
                                                : exactSubset_.circleIndices()[static_cast<std::size_t>(lost.circle)];
        }
        const bool held = !springLost && ctx.stats.capsHit == statsBefore.capsHit;
        if (held && whole) return -1;
        if (held) {
            // Exact's results stay in the subset until the solver has stepped (runSolver); the
            // solver meets the segments where they were at the start of the step.
            exactSubset_.remapImpacts(ctx, impactsBefore);
            segmentsAfterExact_.assign(ctx.segments.begin(), ctx.segments.end());
            std::copy(segmentsBefore_.begin(), segmentsBefore_.end(), ctx.segments.begin());
            return -1;
        }
        // The subset's copies are dropped; a whole-world trial is put back.
        if (!whole) exactSubset_.remapImpacts(ctx, impactsBefore);
        const int blamed = lostNode >= 0 && islands_.islandOf(lostNode) >= 0 ? islands_.islandOf(lostNode)
                                                                             : mostImpacts(ctx, impactsBefore);
        if (whole) {
            std::copy(circlesBefore_.begin(), circlesBefore_.end(), ctx.circles.begin());
            std::copy(bodiesBefore_.begin(), bodiesBefore_.end(), ctx.bodies.begin());
        }
        std::copy(segmentsBefore_.begin(), segmentsBefore_.end(), ctx.segments.begin());
        ctx.impacts.resize(impactsBefore);
        ctx.stats = statsBefore;
        return blamed;
    }

    // The exact island with the most impacts since `from` (ties: the lowest), or the first exact
    // island with dynamic bodies when none was recorded.
    int mostImpacts(const StepContext& ctx, std::size_t from) {
        const auto islands = islands_.islands();
        impactCounts_.assign(islands.size(), 0);
        for (std::size_t n = from; n < ctx.impacts.size(); ++n) {
            const Impact& impact = ctx.impacts[n];
            const int node = impact.circle >= 0 ? impact.circle
                             : impact.body >= 0 ? static_cast<int>(ctx.circles.size()) + impact.body
                                                : -1;
            if (node < 0) continue;
            const int island = islands_.islandOf(node);
            if (island >= 0) ++impactCounts_[static_cast<std::size_t>(island)];
        }
        int best = -1;
        for (std::size_t k = 0; k < islands.size(); ++k) {
            if (!onExact_[k] || islands[k].dynamicBodies == 0) continue;
            if (best < 0 || impactCounts_[k] > impactCounts_[static_cast<std::size_t>(best)])
                best = static_cast<int>(k);
        }
        return best;
    }

    // Runs the solver on the islands not on exact. It always steps the world itself, so its
    // warm-start cache and sleeping islands keep naming bodies by their world index from step to
    // step whichever islands exact takes: exact's bodies are shown to it as fixed where they
    // started (none is within reach of a solver island this step), then given exact's results.
    void runSolver(StepContext& ctx, double dt, bool exactOnSubset, bool ranSolverBefore,
                   std::int64_t dynamicOnSolver) {
        if (allOnExact()) return;
        // A solver that sat out some steps starts afresh: its warm-start impulses belong to
        // contacts that have since moved.
        if (!ranSolverBefore || !solver_) solver_ = makeSolverMethod();
        usedSolver_ = true;
        ++ctx.stats.autoSolverSteps;
        ctx.stats.solverBodySteps += dynamicOnSolver;
        if (!exactOnSubset) {
            solver_->step(ctx, dt);
            return;
        }
        for (const int i : exactSubset_.circleIndices()) {
            Circle& c = ctx.circles[static_cast<std::size_t>(i)];
            if (c.motion != Motion::dynamic) continue;
            c.motion = Motion::fixed;
            c.velocity = {};
            c.angularVelocity = 0.0;
            c.inverseMass = c.inverseInertia = 0.0;
        }
        for (const int b : exactSubset_.bodyIndices()) {
            RigidBody& body = ctx.bodies[static_cast<std::size_t>(b)];
            body.motion = Motion::fixed;
            body.velocity = {};
            body.angularVelocity = 0.0;
            body.inverseMass = body.inverseInertia = 0.0;
        }
        solver_->step(ctx, dt);
        // Exact's bodies, and its motion of the shared ones (kinematic circles and segments).
        exactSubset_.scatter(ctx, true, ctx.impacts.size());
        exactSubset_.carryAngles(ctx, true, dt);
        std::copy(segmentsAfterExact_.begin(), segmentsAfterExact_.end(), ctx.segments.begin());
    }

    std::unique_ptr<StepMethod> exact_;
    std::unique_ptr<StepMethod> solver_;
    bool usedSolver_ = false;
    int solverOnlyFor_ = 0; // steps the whole world stays the solver's without an island pass
    int recheck_ = kFirstRecheck;
    std::size_t circleCount_ = 0;
    AutoIslands islands_;
    StepSubset exactSubset_;
    std::vector<std::uint8_t> onExact_;                   // per island
    std::vector<std::uint8_t> chosen_;                    // per node, for a subset
    std::vector<int> stintLeft_;                          // per node: steps it has yet to spend on the solver
    std::vector<int> stintLength_;                        // per node: the stint it serves if exact fails on it again
    std::vector<std::int64_t> crowdDynamic_, crowdNodes_; // per neighbourhood (its lowest node)
    std::vector<int> crowds_;                             // neighbourhoods on exact, most crowded first
    std::vector<int> impactCounts_;                       // per island, for the blame after a failed trial
    std::vector<Circle> circlesBefore_;
    std::vector<Segment> segmentsBefore_, segmentsAfterExact_;
    std::vector<RigidBody> bodiesBefore_;
};

} // namespace

std::unique_ptr<StepMethod> makeAutoMethod() { return std::make_unique<AutoMethod>(); }

} // namespace rube
