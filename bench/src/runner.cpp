// The runner. Measuring and timing are separate runs of the same deterministic scene, so no
// measurement (overlap sweeps, energy, reference distances) ever lands inside the timed loop.

#include "runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <vector>

namespace bench {
namespace {

using Clock = std::chrono::steady_clock;

std::unique_ptr<Sim> buildSim(const Scene& scene, const Engine& engine, double timeStep, const RunOptions& options) {
    auto sim = engine.make({scene.gravity, timeStep, options.rubeSleep, options.chipmunkSleep, options.rubeWorkers});
    scene.build(*sim, options.size);
    return sim;
}

bool inside(const Scene& scene, Vec2 p) {
    return p.x >= scene.boundsMin.x && p.x <= scene.boundsMax.x && p.y >= scene.boundsMin.y && p.y <= scene.boundsMax.y;
}

// The measurement run: the probe and the stability flags look at the world after every step.
void measure(const Scene& scene, const Engine& engine, double timeStep, const RunOptions& options, Row& row) {
    auto sim = buildSim(scene, engine, timeStep, options);
    if (sim->lacksJoint()) {
        row.lacksJoint = true; // not this engine's: no row
        return;
    }
    auto probe = scene.probe(options.size, timeStep);
    row.bodies = sim->ballCount() + sim->boxCount(); // known even if the run times out
    std::vector<std::uint8_t> escaped(static_cast<std::size_t>(sim->ballCount()), 0);
    const auto start = Clock::now();
    for (int step = 1; step <= row.steps; ++step) {
        sim->step();
        probe->observe(*sim, step, step * timeStep);
        for (int i = 0; i < sim->ballCount(); ++i) {
            const BallState b = sim->ball(i);
            if (!rube::isFinite(b.position) || !rube::isFinite(b.velocity)) row.nonFinite = true;
            else if (!escaped[static_cast<std::size_t>(i)] && !inside(scene, b.position)) {
                escaped[static_cast<std::size_t>(i)] = 1;
                ++row.escapes;
            }
        }
        for (int i = 0; i < sim->boxCount(); ++i) {
            const BoxState b = sim->box(i);
            if (!rube::isFinite(b.position) || !rube::isFinite(b.velocity) || !std::isfinite(b.angle))
                row.nonFinite = true;
        }
        if (std::chrono::duration<double>(Clock::now() - start).count() > options.runTimeLimit) {
            row.timeout = true; // an engine stuck on this scene must not stall the whole bench
            return;
        }
    }
    row.metrics = probe->finish(*sim);
    row.capsHit = sim->capsHit();
}

struct Timing {
    double seconds = 0.0;     // the whole step loop
    double lastSeconds = 0.0; // its last `lastSteps` steps
    double cpuSeconds = 0.0;  // the whole step loop's processor time, every thread's
};

// One timed run: building the world is outside the clock, the step loop is all that is inside it
// (read once more before the last second's steps: one clock read in the loop, not one a step).
Timing timedRun(const Scene& scene, const Engine& engine, double timeStep, const RunOptions& options, int steps,
                int lastSteps) {
    auto sim = buildSim(scene, engine, timeStep, options);
    const std::clock_t cpuStart = std::clock();
    const auto start = Clock::now();
    for (int step = 0; step < steps - lastSteps; ++step) sim->step();
    const auto split = Clock::now();
    for (int step = steps - lastSteps; step < steps; ++step) sim->step();
    const auto stop = Clock::now();
    const std::clock_t cpuStop = std::clock();
    return {std::chrono::duration<double>(stop - start).count(), std::chrono::duration<double>(stop - split).count(),
            static_cast<double>(cpuStop - cpuStart) / CLOCKS_PER_SEC};
}

double median(std::vector<double> values) {
    // The median: one run disturbed by another process's compile does not move it.
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

} // namespace

std::vector<Row> runScene(const Scene& scene, const Engine& engine, double timeStep, const RunOptions& options,
                          const std::vector<int>& workerCounts) {
    const bool peer = engine.kind == EngineKind::peer;
    const std::vector<int> counts = peer || workerCounts.empty() ? std::vector<int>{1} : workerCounts;
    std::vector<Row> rows(counts.size());
    std::vector<RunOptions> countOptions(counts.size(), options);
    for (std::size_t w = 0; w < counts.size(); ++w) {
        Row& row = rows[w];
        row.scene = scene.name;
        row.engine = engine.name;
        row.peer = peer;
        row.workers = peer ? 1 : counts[w];
        countOptions[w].rubeWorkers = row.workers;
        row.errorName = scene.errorName;
        row.error2Name = scene.error2Name;
        row.timeStep = timeStep;
        row.steps = std::max(1, static_cast<int>(std::lround(scene.duration(options.size) / timeStep)));
        // Every worker count is measured on its own: the counts must give the same world, and a
        // measurement shared among them would hide it if one did not.
        RunOptions measured = countOptions[w];
        measured.runTimeLimit = std::max(options.runTimeLimit, scene.runTimeLimit);
        measure(scene, engine, timeStep, measured, row);
        if (row.lacksJoint) return {};
    }

    // The timed runs go round the worker counts (1, 2, 1, 2, ...), so that each count's median sees
    // the same spells of a busy machine and their ratio means what it says.
    const int lastSteps = std::min(rows[0].steps, std::max(1, static_cast<int>(std::lround(1.0 / timeStep))));
    std::vector<std::vector<double>> seconds(counts.size()), lastSeconds(counts.size()), cpuSeconds(counts.size());
    const auto round = [&] {
        for (std::size_t w = 0; w < counts.size(); ++w) {
            if (rows[w].timeout) continue;
            const Timing t = timedRun(scene, engine, timeStep, countOptions[w], rows[w].steps, lastSteps);
            seconds[w].push_back(t.seconds);
            lastSeconds[w].push_back(t.lastSeconds);
            cpuSeconds[w].push_back(t.cpuSeconds);
        }
    };
    if (std::all_of(rows.begin(), rows.end(), [](const Row& r) { return r.timeout; })) return rows;
    round();
    // Repeats are decided on the slowest count's first run.
    double first = 0.0;
    for (const std::vector<double>& s : seconds)
        if (!s.empty()) first = std::max(first, s.front());
    int rounds = 1;
    const auto more = [&] {
        if (rounds >= options.maxRepeats) return false;
        if (first > options.slowRun) return rounds < options.slowRunRepeats;
        return rounds < options.minRepeats || first * (rounds + 1) <= options.repeatBudget;
    };
    for (; more(); ++rounds) round();
    for (std::size_t w = 0; w < counts.size(); ++w) {
        Row& row = rows[w];
        if (row.timeout) continue;
        const double whole = median(seconds[w]);
        row.repeats = static_cast<int>(seconds[w].size());
        row.msPerStep = 1e3 * whole / row.steps;
        row.msPerStepLastSecond = 1e3 * median(lastSeconds[w]) / lastSteps;
        row.cpuMsPerStep = 1e3 * median(cpuSeconds[w]) / row.steps;
        row.usPerBodyStep = row.bodies > 0 ? 1e6 * whole / (static_cast<double>(row.steps) * row.bodies) : 0.0;
        row.msPerSimSecond = row.msPerStep / timeStep;
    }
    return rows;
}

} // namespace bench
