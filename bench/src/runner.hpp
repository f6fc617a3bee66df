#pragma once
/// The runner: one scene on one engine at one time step, timed and measured in separate runs.

#include "scene.hpp"

#include <string>
#include <vector>

namespace bench {

/// How hard to try: repeats of the timed run and a wall-clock guard per run.
struct RunOptions {
    SceneSize size;
    int minRepeats = 3;         ///< timed runs always made, unless one run is slower than slowRun
    int maxRepeats = 5;         ///< the timed run is repeated up to this many times; the median is kept
    double repeatBudget = 3.0;  ///< seconds: no repeats past minRepeats once the runs would take this long
    double slowRun = 4.0;       ///< seconds: a run this slow is timed slowRunRepeats times, not minRepeats
    int slowRunRepeats = 1;     ///< timed runs of a configuration slower than slowRun (--min-repeats)
    double runTimeLimit = 8.0;  ///< seconds: a measurement run past this is abandoned (flagged "timeout")
    bool rubeSleep = true;      ///< see WorldSpec
    bool chipmunkSleep = false; ///< see WorldSpec
    int rubeWorkers = 1;        ///< see WorldSpec (the peers run on one thread whatever it says)
};

/// One CSV row: what one scene cost and how wrong it was on one engine at one time step.
struct Row {
    std::string scene, engine, errorName, error2Name;
    bool peer = false;
    double timeStep = 0.0;
    int bodies = 0, steps = 0, repeats = 0;
    double msPerStep = 0.0, usPerBodyStep = 0.0, msPerSimSecond = 0.0;
    /// The same median clock over the last simulated second's steps alone: what a scene costs once
    /// it has settled (asleep, where the engine sleeps), beside msPerStep's whole run.
    double msPerStepLastSecond = 0.0;
    /// The process's processor time per step (every thread's, std::clock), median over the same runs:
    /// with workers, what the threads cost together beside msPerStep's wall clock.
    double cpuMsPerStep = 0.0;
    int workers = 1; ///< rube's WorldDef::workers (1 for the peers)
    Metrics metrics;
    std::int64_t capsHit = 0;
    int escapes = 0;
    bool nonFinite = false, timeout = false;
    bool lacksJoint = false; ///< the engine (or method) does not have a joint the scene needs: not run, no row
};

/// Runs `scene` on `engine`: first a measurement run (the probe sees every step), then the
/// timed runs, which are the bare step loop with steady_clock around it and nothing else. One row
/// per count of `workerCounts` (rube's WorldDef::workers; options.rubeWorkers is not read), whose
/// timed runs take turns; a peer gives one row. No rows when the engine lacks the scene's joint.
std::vector<Row> runScene(const Scene& scene, const Engine& engine, double timeStep, const RunOptions& options,
                          const std::vector<int>& workerCounts);

} // namespace bench
