// `rube run`: load, check the options, step the world, write the trace, print the summary.
#include "run_command.hpp"

#include "scene_file.hpp"
#include "trace_writer.hpp"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <ostream>

namespace rube::game {

namespace {

// Set by Ctrl-C; the step loop stops at the next step and the trace is discarded, never half-written.
volatile std::sig_atomic_t gInterrupted = 0;
extern "C" void onInterrupt(int) { gInterrupted = 1; }

// Installs the Ctrl-C handler for the length of a run and puts the previous one back afterwards.
class InterruptGuard {
public:
    InterruptGuard() : previous_(std::signal(SIGINT, onInterrupt)) { gInterrupted = 0; }
    ~InterruptGuard() { std::signal(SIGINT, previous_); }
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

private:
    void (*previous_)(int);
};

std::string validMethodNames() {
    std::string names;
    for (Method m : kAllMethods) names += (names.empty() ? "" : ", ") + std::string(methodName(m));
    return names;
}

std::string hex16(std::uint64_t value) {
    char buffer[17];
    std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(value));
    return buffer;
}

void printSummary(std::ostream& out, const SceneDesc& scene, const World& world, double wallSeconds,
                  const RunOptions& options, const TraceWriter& trace) {
    const StepStats& s = world.stats();
    char seconds[64];
    out << "scene:            " << scene.name << '\n';
    out << "method:           " << methodName(world.def().method) << '\n';
    out << "steps:            " << s.steps << '\n';
    std::snprintf(seconds, sizeof seconds, "%.6g s", world.time());
    out << "simulated time:   " << seconds << '\n';
    std::snprintf(seconds, sizeof seconds, "%.4g s (physics only)", wallSeconds);
    out << "wall time:        " << seconds << '\n';
    out << "impacts:          " << s.impacts << '\n';
    out << "resting contacts: " << s.restingContacts << '\n';
    out << "caps hit:         " << s.capsHit << '\n';
    out << "escapes:          " << s.escapes << '\n';
    out << "state hash:       " << hex16(stateHash(world)) << '\n';
    if (!options.trace.empty()) out << "trace:            " << options.trace << " (" << trace.rows() << " rows)\n";
}

} // namespace

int runScene(const RunOptions& options, std::ostream& out, std::ostream& err) {
    std::optional<Method> method;
    if (!options.method.empty()) {
        method = methodFromName(options.method);
        if (!method) {
            err << "rube run: unknown method '" << options.method << "' (valid methods: " << validMethodNames() << ")\n";
            return 2;
        }
    }
    const SceneLoad load = loadSceneFile(options.scene);
    if (!load.ok()) {
        // One line: the first error. `rube check` lists them all.
        err << load.errors.front().format() << '\n';
        return 2;
    }
    const SceneDesc& scene = *load.scene;
    if (!options.noRender)
        err << "rube run: note: rendering is not built yet, running headless as with --no-render\n";

    TraceWriter trace;
    std::string error;
    if (!options.trace.empty() && !trace.open(options.trace, error)) {
        err << error << '\n';
        return 2;
    }
    World world = buildWorld(scene);
    if (method) world.setMethod(*method);
    const std::int64_t steps = options.steps.value_or(scene.defaultSteps());

    InterruptGuard guard;
    trace.writeState(world); // step 0: the initial state
    // The wall clock lives outside the simulation: it measures, and never feeds back into, the physics.
    std::chrono::steady_clock::duration physicsTime{};
    for (std::int64_t i = 0; i < steps && !gInterrupted; ++i) {
        const auto start = std::chrono::steady_clock::now();
        world.step();
        physicsTime += std::chrono::steady_clock::now() - start;
        trace.writeState(world);
    }
    if (gInterrupted) {
        trace.discard();
        err << "rube run: interrupted after " << world.stats().steps << " steps; no trace written\n";
        return 1;
    }
    if (!options.trace.empty() && !trace.commit(error)) {
        err << error << '\n';
        return 1;
    }
    printSummary(out, scene, world, std::chrono::duration<double>(physicsTime).count(), options, trace);
    if (world.stats().nonFinite) err << "rube run: warning: a body's position or velocity became NaN or infinite\n";
    return 0;
}

} // namespace rube::game
