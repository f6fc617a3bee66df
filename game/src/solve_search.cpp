// The search: candidates run on worker threads, each result stored at the candidate's own place,
// so the outcome is the same on any number of threads; then the neighbours of every solution.
#include "solve_search.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>
#include <unordered_map>

namespace rube::game {

namespace {

// True when nothing in the run moves or will move by itself: every dynamic circle and body slower
// than kQuietSpeed (spin too, as the speed of its rim), no thruster still to burn, no part waiting.
bool stillness(const LevelRun& run) {
    const World& world = run.world();
    for (const Circle& c : world.circles())
        if (c.motion == Motion::dynamic &&
            (c.velocity.length() > kQuietSpeed || std::abs(c.angularVelocity) * c.radius > kQuietSpeed))
            return false;
    for (const RigidBody& b : world.bodies())
        if (b.motion == Motion::dynamic &&
            (b.velocity.length() > kQuietSpeed || std::abs(b.angularVelocity) * b.halfExtents.length() > kQuietSpeed))
            return false;
    for (const Thruster& t : world.fields().thrusters)
        if (t.end > world.time()) return false;
    for (std::size_t i = 0; i < run.items().size(); ++i)
        if (run.items()[i].kind->waits(run.items()[i], run.states()[i])) return false;
    return true;
}

// Calls work(i) for i in [0, count) on `jobs` threads, handing out small chunks in order; the
// calling thread reports progress while they work.
template <class Work>
void parallelFor(std::uint64_t count, int jobs, Work work, const std::function<void(std::uint64_t)>& tick) {
    constexpr std::uint64_t kChunk = 4;
    std::atomic<std::uint64_t> next{0}, done{0};
    const auto worker = [&] {
        for (;;) {
            const std::uint64_t first = next.fetch_add(kChunk);
            if (first >= count) return;
            const std::uint64_t last = std::min(count, first + kChunk);
            for (std::uint64_t i = first; i < last; ++i) work(i);
            done += last - first;
        }
    };
    std::vector<std::thread> threads;
    for (int j = 0; j < std::max(1, jobs); ++j) threads.emplace_back(worker);
    if (tick)
        while (done.load() < count) {
            tick(done.load());
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
        }
    for (std::thread& t : threads) t.join();
    if (tick) tick(count);
}

} // namespace

RunOutcome runCandidate(const SceneDesc& level, const ScriptDesc& script, std::int64_t steps, bool stopWhenQuiet) {
    RunOutcome out;
    if (checkPlacements(level, script.placements)) return out;
    LevelRun run(level, script.placements);
    out.valid = true;
    const std::int64_t quietSteps = static_cast<std::int64_t>(std::ceil(kQuietSeconds / level.world.timeStep));
    const bool mayStop = stopWhenQuiet && run.world().paths().empty();
    std::int64_t quiet = 0;
    std::size_t next = 0;
    // The loop of `rube run` (playLevel): the actions of step i are taken before step i + 1.
    for (std::int64_t i = 0; !run.goalStep() && i < steps; ++i) {
        for (; next < script.actions.size() && script.actions[next].step == i; ++next)
            if (!takeAction(script.actions[next], run).empty()) {
                out.valid = false; // an aim that cannot reach: the player could not have done it
                return out;
            }
        run.step();
        if (!mayStop || next < script.actions.size()) continue;
        quiet = stillness(run) ? quiet + 1 : 0;
        if (quiet >= quietSteps) break;
    }
    out.goal = run.goalStep();
    out.steps = run.steps();
    return out;
}

bool SearchPlan::exhaustive() const {
    return std::all_of(whole.begin(), whole.end(), [](bool w) { return w; });
}

int SearchPlan::subsetOf(std::uint64_t number) const {
    std::size_t s = 0;
    while (s + 1 < tries.size() && number >= tries[s]) number -= tries[s++];
    return static_cast<int>(s);
}

Candidate SearchPlan::candidate(const SearchSpace& space, std::uint64_t seed, std::uint64_t number) const {
    std::uint64_t index = number;
    std::size_t s = 0;
    while (s + 1 < tries.size() && index >= tries[s]) index -= tries[s++];
    return whole[s] ? space.at(static_cast<int>(s), index) : space.sample(static_cast<int>(s), seed, number);
}

SearchPlan planSearch(const SearchSpace& space, std::uint64_t budget) {
    const std::size_t n = static_cast<std::size_t>(space.subsetCount());
    SearchPlan plan;
    plan.tries.assign(n, 0);
    plan.whole.assign(n, false);
    // Water-filling: subsets no larger than an equal share of what is left are searched whole.
    std::uint64_t left = budget;
    std::size_t open = n;
    for (bool changed = true; changed && open > 0;) {
        changed = false;
        const std::uint64_t share = left / open;
        for (std::size_t s = 0; s < n; ++s)
            if (!plan.whole[s] && space.subsetSize(static_cast<int>(s)) <= share) {
                plan.whole[s] = true;
                plan.tries[s] = space.subsetSize(static_cast<int>(s));
                left -= plan.tries[s];
                --open;
                changed = true;
            }
    }
    if (open > 0) {
        const std::uint64_t share = left / open;
        std::uint64_t extra = left % open; // the first subsets drawn from get one more each
        for (std::size_t s = 0; s < n; ++s)
            if (!plan.whole[s]) {
                plan.tries[s] = share + (extra > 0 ? (--extra, 1) : 0);
                plan.whole[s] = plan.tries[s] == space.subsetSize(static_cast<int>(s)); // one more made it whole
            }
    }
    for (const std::uint64_t t : plan.tries) plan.total += t;
    return plan;
}

std::uint64_t SearchResult::tried() const {
    std::uint64_t n = 0;
    for (const SubsetTally& t : subsets) n += t.tried;
    return n;
}

std::uint64_t SearchResult::valid() const {
    std::uint64_t n = 0;
    for (const SubsetTally& t : subsets) n += t.valid;
    return n;
}

double SearchResult::solveFraction(const SearchSpace& space) const {
    double solving = 0.0, allowed = 0.0;
    for (std::size_t s = 0; s < subsets.size(); ++s) {
        if (subsets[s].tried == 0) continue;
        const double weight = space.subsetWeight(static_cast<int>(s)) / static_cast<double>(subsets[s].tried);
        solving += weight * static_cast<double>(subsets[s].solved);
        allowed += weight * static_cast<double>(subsets[s].valid);
    }
    return allowed > 0.0 ? solving / allowed : 0.0;
}

Candidate candidateOf(const SearchSpace& space, const SearchResult& result, std::uint64_t number) {
    return planSearch(space, result.budget).candidate(space, result.seed, number);
}

SearchResult searchLevel(const SceneDesc& level, const SearchSpace& space, const SolveOptions& options,
                         const SearchProgress& progress) {
    SearchResult result;
    result.level = level.name;
    result.space = space.size();
    result.budget = options.budget;
    result.seed = options.seed;
    result.shardIndex = options.shardIndex;
    result.shardCount = options.shardCount;
    const SearchPlan plan = planSearch(space, options.budget);
    const std::uint64_t total = plan.total;
    const auto shard = static_cast<std::uint64_t>(options.shardIndex);
    const auto shards = static_cast<std::uint64_t>(options.shardCount);
    const std::uint64_t count = total > shard ? (total - shard + shards - 1) / shards : 0;
    const auto numberOf = [&](std::uint64_t i) { return shard + i * shards; };

    const auto start = std::chrono::steady_clock::now();
    const auto seconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    std::vector<RunOutcome> outcomes(count);
    std::vector<std::string> keys(count);
    std::atomic<std::uint64_t> solved{0};
    const auto tick = [&](std::uint64_t done) {
        if (progress) progress(done, count, solved.load(), seconds());
    };
    parallelFor(
        count, options.jobs,
        [&](std::uint64_t i) {
            const Candidate c = plan.candidate(space, options.seed, numberOf(i));
            keys[i] = SearchSpace::key(c);
            outcomes[i] = runCandidate(level, space.script(c), space.steps());
            if (outcomes[i].goal) ++solved;
        },
        progress ? std::function<void(std::uint64_t)>(tick) : nullptr);
    result.subsets.assign(static_cast<std::size_t>(space.subsetCount()), {});

    // Robustness: each solution's grid neighbours, run unless this slice ran them already.
    std::unordered_map<std::string, bool> known;
    for (std::uint64_t i = 0; i < count; ++i) {
        SubsetTally& tally = result.subsets[static_cast<std::size_t>(plan.subsetOf(numberOf(i)))];
        ++tally.tried;
        if (outcomes[i].valid) ++tally.valid, ++result.runs;
        if (outcomes[i].goal) ++tally.solved;
        known.emplace(keys[i], outcomes[i].goal.has_value());
        if (outcomes[i].goal) result.solutions.push_back({numberOf(i), *outcomes[i].goal, 0, 0});
    }
    std::vector<std::vector<Candidate>> around;
    std::vector<Candidate> toRun;
    std::unordered_map<std::string, std::size_t> queued;
    for (const FoundSolution& s : result.solutions) {
        around.push_back(space.neighbours(plan.candidate(space, options.seed, s.number)));
        for (const Candidate& n : around.back()) {
            const std::string key = SearchSpace::key(n);
            if (!known.contains(key) && queued.emplace(key, toRun.size()).second) toRun.push_back(n);
        }
    }
    std::vector<char> neighbourSolves(toRun.size(), 0), neighbourRan(toRun.size(), 0);
    parallelFor(
        toRun.size(), options.jobs,
        [&](std::uint64_t i) {
            const RunOutcome outcome = runCandidate(level, space.script(toRun[i]), space.steps());
            neighbourSolves[i] = outcome.goal.has_value();
            neighbourRan[i] = outcome.valid;
        },
        nullptr);
    for (const char ran : neighbourRan) result.runs += ran != 0;
    for (std::size_t s = 0; s < result.solutions.size(); ++s)
        for (const Candidate& n : around[s]) {
            const std::string key = SearchSpace::key(n);
            const auto hit = known.find(key);
            const bool solves = hit != known.end() ? hit->second : neighbourSolves[queued.at(key)] != 0;
            ++result.solutions[s].neighbours;
            if (solves) ++result.solutions[s].neighboursSolving;
        }
    return result;
}

} // namespace rube::game
