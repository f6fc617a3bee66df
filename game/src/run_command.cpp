// `rube run`: load, check the options, step the world, write the trace and the frames, print the summary.
#include "run_command.hpp"

#include "scene_reading.hpp"

#include "frame_recorder.hpp"
#include "method_budget.hpp"
#include "play_command.hpp"
#include "run_interrupt.hpp"
#include "scene_file.hpp"
#include "scene_framing.hpp"
#include "scene_reading.hpp"
#include "scene_view.hpp"
#include "trace_writer.hpp"

#include <chrono>
#include <cstdio>
#include <limits>
#include <memory>
#include <ostream>

namespace rube::game {

namespace {

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

// Everything a run with --out or --video needs besides the world: the target, the recorder,
// the view and one draw list reused for every frame.
struct Recording {
    RecordingTarget target;
    std::unique_ptr<FrameRecorder> recorder;
    std::unique_ptr<SceneView> view;
    render::DrawList list;
    std::int64_t total = 0; // frames the run will write
    std::int64_t done = 0;  // frames queued so far; the next frame's number
};

void printSummary(std::ostream& out, const SceneDesc& scene, const World& world, double physicsSeconds,
                  const RunOptions& options, const TraceWriter& trace, const RecordingStats* frames,
                  const RecordingTarget& target) {
    const StepStats& s = world.stats();
    char text[160];
    out << "scene:            " << scene.name << '\n';
    out << "method:           " << methodDescription(world) << '\n';
    out << "steps:            " << s.steps << '\n';
    std::snprintf(text, sizeof text, "%.6g s", world.time());
    out << "simulated time:   " << text << '\n';
    std::snprintf(text, sizeof text, "%.4g s (physics only)", physicsSeconds);
    out << "wall time:        " << text << '\n';
    out << "impacts:          " << s.impacts << '\n';
    out << "resting contacts: " << s.restingContacts << '\n';
    out << "caps hit:         " << s.capsHit << '\n';
    out << "escapes:          " << s.escapes << '\n';
    out << "speed clamps:     " << s.speedClamps << '\n';
    out << "isolated bodies:  " << s.isolatedBodies << '\n';
    out << "state hash:       " << hex16(stateHash(world)) << '\n';
    if (!options.trace.empty()) out << "trace:            " << options.trace << " (" << trace.rows() << " rows)\n";
    if (frames && !options.out.empty()) {
        std::snprintf(text, sizeof text, "%lld of %dx%d, %.0f bytes per frame on average",
                      static_cast<long long>(frames->frames), options.size.width, options.size.height,
                      frames->bytesPerFrame());
        out << "frames:           " << text << ", in " << options.out << '\n';
    }
    if (frames) {
        const std::int64_t drawn = std::max(frames->frames, frames->videoFrames);
        const double frameRate = frames->wallSeconds > 0.0 ? static_cast<double>(drawn) / frames->wallSeconds : 0.0;
        std::snprintf(text, sizeof text, "%.1f fps (wall clock: simulate, render and write)", frameRate);
        out << "frame rate:       " << text << '\n';
        out << recordingSummary(target, *frames);
    }
}

// The option given that a level's run has no use for, or "": a level runs by its own [world]
// method, and is drawn as the game draws it (LevelView), without trails or impact marks.
std::string unusedByLevels(const RunOptions& options) {
    if (!options.method.empty()) return "--method";
    if (options.trails) return "--trails";
    if (options.debugImpacts) return "--debug-impacts";
    return "";
}

// The most steps one run may take, however they are asked for.
constexpr std::int64_t kMaxRunSteps = 1'000'000'000;

// Steps the run takes: --steps; else enough for --frames; else the scene's duration.
std::int64_t stepsOf(const RunOptions& options, const SceneDesc& scene) {
    if (options.steps) return *options.steps;
    if (options.frames) return (*options.frames - 1) * options.every;
    return scene.defaultSteps();
}

} // namespace

std::string unstableStateMessage(const World& world) {
    const StepStats& s = world.stats();
    if (!s.nonFinite && s.isolatedBodies == 0) return "";
    std::string text = "a body's state became NaN or infinite";
    if (s.isolatedBodies > 0)
        text += ": " + std::to_string(s.isolatedBodies) + (s.isolatedBodies == 1 ? " body" : " bodies") +
                " frozen, the first " + (s.firstIsolatedKind == Other::body ? "rigid body " : "circle ") +
                std::to_string(s.firstIsolatedSlot);
    return text + "; the run's results are not physical";
}

std::string methodDescription(const World& world) {
    std::string text(methodName(world.def().method));
    if (world.def().method != Method::automatic) return text;
    const StepStats& stats = world.stats();
    const std::int64_t solver = stats.autoSolverSteps;
    const std::int64_t bodySteps = stats.exactBodySteps + stats.solverBodySteps;
    char share[32] = "-";
    if (bodySteps > 0)
        std::snprintf(share, sizeof share, "%.1f %%",
                      100.0 * static_cast<double>(stats.exactBodySteps) / static_cast<double>(bodySteps));
    return text + " (exact " + std::to_string(stats.steps - solver) + " steps, solver " + std::to_string(solver) +
           "; body-steps exact " + std::to_string(stats.exactBodySteps) + ", solver " +
           std::to_string(stats.solverBodySteps) + ", exact share " + share + ")";
}

ExitCode runScene(const RunOptions& options, std::ostream& out, std::ostream& err) {
    std::optional<Method> method;
    if (!options.method.empty()) {
        method = methodFromName(options.method);
        if (!method) {
            err << "rube run: unknown method '" << options.method << "' (valid methods: " << validMethodNames()
                << ")\n";
            return ExitCode::badInput;
        }
    }
    const SceneLoad load = loadSceneFile(options.scene);
    if (!load.ok()) {
        // One line: the first error. `rube check` lists them all.
        err << load.errors.front().format() << '\n';
        return ExitCode::badInput;
    }
    const SceneDesc& scene = *load.scene;
    // A level (or any scene given a script) is played by the game's rules; a physics scene just runs.
    const bool asLevel = scene.level.isLevel() || !options.script.empty();
    if (const std::string option = unusedByLevels(options); asLevel && !option.empty()) {
        err << "rube run: " << option << " is for physics scenes, and " << options.scene
            << (scene.level.isLevel() ? " is a level" : " is played as a level with --script")
            << ": a level runs by its own [world] method and is drawn as the game draws it\n";
        return ExitCode::badInput;
    }
    if (!asLevel && (options.labels || options.zones)) {
        err << "rube run: " << (options.labels ? "--labels" : "--zones") << " is for levels, and " << options.scene
            << " is a physics scene: it has no items or placement zones\n";
        return ExitCode::badInput;
    }
    if (std::string why; method && !methodMovesRotating(scene, *method, why)) {
        if (!why.empty())
            err << "rube run: --method " << options.method << ": " << options.scene << ": " << why << '\n';
        else
            err << "rube run: --method " << options.method << " cannot move the turning boxes, capsules "
                << (scene.joints.empty() ? "or pivots" : "pivots or joints") << " of " << options.scene
                << ": use auto or solver\n";
        return ExitCode::badInput;
    }
    if (const std::string why = methodBudgetRefusal(scene, method.value_or(scene.world.method)); !why.empty()) {
        err << "rube run: " << options.scene << ": " << why << '\n';
        return ExitCode::badInput;
    }
    if (asLevel) return playLevel(options, scene, out, err);
    // --steps is capped by its validator and a scene's duration when read; only --frames x --every is left.
    if (const std::int64_t steps = stepsOf(options, scene); steps > kMaxRunSteps) {
        err << "rube run: --frames " << *options.frames << " with --every " << options.every << " makes " << steps
            << " steps, more than the " << kMaxRunSteps << " a run may take" << '\n';
        return ExitCode::badInput;
    }
    const bool recording = drawsFrames(options);
    if (!recording && !options.noRender)
        err << "rube run: note: no frames written without --out DIR or --video FILE (--no-render runs headless without "
               "this note)\n";

    InterruptGuard guard; // from before the trace's temporary exists, so a SIGTERM cannot leave it behind
    TraceWriter trace;
    std::string error;
    if (!options.trace.empty() && !trace.open(options.trace, error)) {
        err << error << '\n';
        return ExitCode::badInput;
    }
    World world = buildWorld(scene);
    if (method) world.setMethod(*method);
    const std::int64_t steps = stepsOf(options, scene);
    const std::int64_t every = options.every < 1 ? 1 : options.every;

    // The folder is checked before GL starts, and both before the first step: a bad --out
    // writes nothing (the trace's temporary file goes with `trace`).
    Recording frames;
    if (recording) {
        ExitCode status = ExitCode::ok;
        frames.target = {options.out, options.video, options.size, options.gl,
                         1.0 / (scene.world.timeStep * static_cast<double>(every))};
        frames.recorder = openFrameRecorder(frames.target, err, "rube run", status);
        if (!frames.recorder) return status;
        ViewOptions viewOptions;
        viewOptions.trails = options.trails;
        viewOptions.impacts = options.debugImpacts;
        frames.view = std::make_unique<SceneView>(
            scene.name, world, sceneCamera(frameScene(scene, world), options.size), options.size, viewOptions);
        frames.total = std::min(options.frames.value_or(std::numeric_limits<std::int64_t>::max()), steps / every + 1);
    }
    auto progress = std::make_unique<ProgressLine>(err, recording && options.progress, frames.total);
    const auto recordFrame = [&] {
        frames.view->draw(world, frames.list);
        frames.recorder->record(frames.list, frames.view->camera(), frames.done);
        ++frames.done;
        progress->update(frames.done, frames.recorder->elapsedSeconds());
    };

    trace.writeState(world); // step 0: the initial state
    // The wall clock lives outside the simulation: it measures, and never feeds back into, the physics.
    std::chrono::steady_clock::duration physicsTime{};
    RecordingStats recorded;
    try {
        if (recording) recordFrame(); // frame 0: the initial state
        for (std::int64_t i = 0; i < steps && !interrupted(); ++i) {
            const auto start = std::chrono::steady_clock::now();
            world.step();
            physicsTime += std::chrono::steady_clock::now() - start;
            trace.writeState(world);
            if (frames.done < frames.total) {
                frames.view->afterStep(world);
                if ((i + 1) % every == 0) recordFrame();
            }
        }
        if (recording) recorded = frames.recorder->finish();
    } catch (const std::exception& e) {
        progress.reset();
        trace.discard();
        err << "rube run: " << e.what() << (options.trace.empty() ? "" : "; no trace written") << '\n';
        return ExitCode::failed;
    }
    progress.reset(); // wipes the progress line before anything else is printed
    if (interrupted()) {
        trace.discard();
        RunOptions shown = options;
        shown.trace.clear(); // the summary must not name a trace that was discarded
        printSummary(out, scene, world, std::chrono::duration<double>(physicsTime).count(), shown, trace,
                     recording ? &recorded : nullptr, frames.target);
        out << "interrupted:      by " << interruptingSignal() << " after " << world.stats().steps << " steps\n";
        err << "rube run: interrupted by " << interruptingSignal() << " after " << world.stats().steps
            << " steps; no trace written";
        // The frames already written stay: each is whole (written under a temporary name, then renamed).
        if (!options.out.empty()) err << "; " << recorded.frames << " frames written";
        if (!options.video.empty()) err << "; no video written";
        err << '\n';
        return ExitCode::failed;
    }
    if (!options.trace.empty() && !trace.commit(error)) {
        err << error << '\n';
        return ExitCode::failed;
    }
    printSummary(out, scene, world, std::chrono::duration<double>(physicsTime).count(), options, trace,
                 recording ? &recorded : nullptr, frames.target);
    // Issue 27: a run whose physics went non-finite fails, whatever else it wrote.
    if (const std::string why = unstableStateMessage(world); !why.empty()) {
        err << "rube run: " << why << '\n';
        return ExitCode::failed;
    }
    return ExitCode::ok;
}

} // namespace rube::game
