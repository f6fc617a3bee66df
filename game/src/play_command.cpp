// `rube run` for levels: load the script, take its actions frame by frame, record frames, then
// judge the goal and the expectations and write the summary (JSON) of what happened.
#include "play_command.hpp"

#include "frame_recorder.hpp"
#include "json_reader.hpp"
#include "level_view.hpp"
#include "run_interrupt.hpp"
#include "scene_errors.hpp"
#include "scene_framing.hpp"
#include "script_file.hpp"
#include "trace_writer.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <ostream>
#include <sstream>

namespace rube::game {

namespace {

// After the goal the run goes on this long, so the frames show what reaching it looked like.
constexpr double kAfterGoalSeconds = 0.5;

const char* eventName(EventKind kind) {
    switch (kind) {
    case EventKind::hit: return "hit";
    case EventKind::shot: return "shot";
    case EventKind::explosion: return "explosion";
    case EventKind::goal: return "goal";
    }
    return "";
}

std::string jsonNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

// The summary: every event with its frame, time and position, and how each expectation fared;
// whether a signal cut the run short (`signal` empty when none did).
std::string summaryJson(const LevelRun& run, const SceneDesc& level,
                        const std::vector<std::pair<std::string, bool>>& expectations, const std::string& signal) {
    std::ostringstream json;
    json << "{\n  \"level\": " << jsonString(level.name) << ",\n  \"steps\": " << run.frame()
         << ",\n  \"interrupted\": " << (signal.empty() ? "false" : "true,\n  \"signal\": " + jsonString(signal))
         << ",\n  \"goal_reached\": " << (run.goalFrame() ? "true" : "false")
         << ",\n  \"goal_frame\": " << (run.goalFrame() ? std::to_string(*run.goalFrame()) : "null")
         << ",\n  \"speed_clamps\": " << run.world().stats().speedClamps
         << ",\n  \"isolated_bodies\": " << run.world().stats().isolatedBodies
         << ",\n  \"non_finite\": " << (run.world().stats().nonFinite ? "true" : "false") << ",\n  \"events\": [";
    bool first = true;
    for (const GameEvent& e : run.events()) {
        json << (first ? "\n" : ",\n") << "    {\"kind\": \"" << eventName(e.kind) << "\", \"frame\": " << e.frame
             << ", \"time\": " << jsonNumber(e.time) << ", \"item\": " << jsonString(e.item) << ", \"position\": ["
             << jsonNumber(e.position.x) << ", " << jsonNumber(e.position.y) << "]";
        if (e.kind == EventKind::explosion) json << ", \"bodies\": " << e.count;
        json << "}";
        first = false;
    }
    json << (first ? "" : "\n  ") << "],\n  \"expectations\": [";
    first = true;
    for (const auto& [text, met] : expectations) {
        json << (first ? "\n" : ",\n") << "    {\"expect\": " << jsonString(text)
             << ", \"met\": " << (met ? "true" : "false") << "}";
        first = false;
    }
    json << (first ? "" : "\n  ") << "]\n}\n";
    return json.str();
}

bool met(const Expectation& e, const LevelRun& run) {
    for (const GameEvent& event : run.events())
        if (event.kind == e.kind && (e.kind == EventKind::goal || event.item == e.item) && event.frame < e.beforeFrame)
            return true;
    return false;
}

} // namespace

std::string takeAction(const Action& a, LevelRun& run) {
    const int item = run.find(a.item);
    switch (a.kind) {
    case ActionKind::rotate: run.aim(item, *a.angle); return "";
    case ActionKind::aim:
        if (a.angle) run.aim(item, *a.angle);
        else if (a.point) return run.aimAtPoint(item, *a.point, a.highArc);
        else return run.aimAtItem(item, run.find(a.target), a.highArc);
        return "";
    case ActionKind::fire: run.fire(item); return "";
    case ActionKind::detonate: run.detonate(item); return "";
    case ActionKind::toggle: run.toggle(item); return "";
    case ActionKind::fireWhen: return run.fireWhen(item, run.find(a.target));
    case ActionKind::cut: run.cutRope(a.item); return "";
    }
    return "";
}

ExitCode playLevel(const RunOptions& options, const SceneDesc& level, std::ostream& out, std::ostream& err) {
    ScriptDesc script;
    if (!options.script.empty()) {
        ScriptLoad load = loadScriptFile(options.script, level);
        if (!load.script) {
            err << load.errors.front().format() << '\n';
            return ExitCode::badInput;
        }
        script = std::move(*load.script);
    }
    LevelRun run(level, script.placements);
    const double dt = level.world.timeStep;
    std::int64_t steps = level.defaultSteps();
    if (level.level.goal && level.level.goal->timeLimit)
        steps = static_cast<std::int64_t>(std::ceil(*level.level.goal->timeLimit / dt - 1e-9));
    if (script.steps) steps = *script.steps;
    if (options.steps) steps = *options.steps;
    const std::int64_t every = options.everyGiven ? options.every : script.every.value_or(options.every);
    const render::FrameSize size = options.sizeGiven ? options.size : script.size.value_or(options.size);

    // The trace is opened after the script is read, so a bad script is reported as such, and
    // before the frames: the temporary goes with `trace` if the folder is refused.
    TraceWriter trace;
    if (std::string error; !options.trace.empty() && !trace.open(options.trace, error)) {
        err << error << '\n';
        return ExitCode::badInput;
    }
    std::unique_ptr<FrameRecorder> recorder;
    std::unique_ptr<LevelView> view;
    render::DrawList list;
    std::int64_t framesWritten = 0;
    const RecordingTarget target{options.out, options.video, size, options.gl, 1.0 / (dt * static_cast<double>(every))};
    RecordingStats recorded;
    if (drawsFrames(options)) {
        ExitCode status = ExitCode::ok;
        recorder = openFrameRecorder(target, err, "rube run", status);
        if (!recorder) return status;
        view = std::make_unique<LevelView>(level.name, sceneCamera(frameScene(level, run.world()), size), size);
    }
    const auto record = [&] {
        if (!recorder || (options.frames && framesWritten >= *options.frames)) return;
        view->draw(run, run.frame(), list);
        recorder->record(list, view->camera(), framesWritten++);
    };

    std::vector<std::string> failures;
    std::size_t next = 0;
    InterruptGuard guard;
    const std::int64_t tail = static_cast<std::int64_t>(std::ceil(kAfterGoalSeconds / dt));
    try {
        trace.writeState(run.world()); // step 0: the initial state
        for (std::int64_t i = 0;; ++i) {
            for (; next < script.actions.size() && script.actions[next].frame == i; ++next)
                if (const std::string why = takeAction(script.actions[next], run); !why.empty())
                    failures.push_back(options.script + ":" + std::to_string(script.actions[next].place.line) + ":" +
                                       std::to_string(script.actions[next].place.column) + ": at frame " +
                                       std::to_string(i) + ": " + why);
            if (i % every == 0) record();
            if (i >= steps || (run.goalFrame() && i >= *run.goalFrame() + tail) || interrupted()) break;
            run.step();
            trace.writeState(run.world());
        }
        if (recorder) recorded = recorder->finish();
    } catch (const std::exception& e) {
        err << "rube run: " << e.what() << '\n';
        return ExitCode::failed;
    }

    std::vector<std::pair<std::string, bool>> judged;
    for (const Expectation& e : script.expectations) {
        judged.emplace_back(e.describe(), met(e, run));
        if (!judged.back().second)
            failures.push_back(options.script + ":" + std::to_string(e.place.line) + ":" +
                               std::to_string(e.place.column) + ": expectation failed: " + e.describe());
    }
    const std::string signal = interruptingSignal();
    std::string reason;
    if (!options.out.empty() && !writeTextFileAtomically(std::filesystem::path(options.out) / "summary.json",
                                                         summaryJson(run, level, judged, signal), reason)) {
        err << "rube run: cannot write " << (std::filesystem::path(options.out) / "summary.json").string() << ": "
            << reason << '\n';
        return ExitCode::failed;
    }
    // An interrupted run's trace is discarded (by `trace`), as a scene's is.
    if (signal.empty() && !options.trace.empty() && !trace.commit(reason)) {
        err << reason << '\n';
        return ExitCode::failed;
    }
    out << "level:            " << level.name << '\n';
    out << "method:           " << methodDescription(run.world()) << '\n';
    out << "steps:            " << run.frame() << '\n';
    for (const GameEvent& e : run.events())
        out << "event:            frame " << e.frame << " " << eventName(e.kind) << (e.item.empty() ? "" : " " + e.item)
            << '\n';
    // A level without a [goal] has nothing to miss: it says so and exits 0, as a physics scene does.
    const std::string goalWords = run.goalFrame()    ? "reached at frame " + std::to_string(*run.goalFrame())
                                  : level.level.goal ? std::string("not reached")
                                                     : std::string("none (the level has no [goal])");
    out << "goal:             " << goalWords << '\n';
    out << "speed clamps:     " << run.world().stats().speedClamps << '\n';
    out << "isolated bodies:  " << run.world().stats().isolatedBodies << '\n';
    if (signal.empty() && !options.trace.empty())
        out << "trace:            " << options.trace << " (" << trace.rows() << " rows)\n";
    if (recorder && !options.out.empty())
        out << "frames:           " << framesWritten << " in " << options.out << " (summary in " << options.out
            << "/summary.json)\n";
    if (recorder) out << recordingSummary(target, recorded);
    if (!signal.empty()) {
        // One line, not the expectations the cut-short run could not meet.
        out << "interrupted:      by " << signal << " at frame " << run.frame() << '\n';
        err << "rube run: interrupted by " << signal << " at frame " << run.frame()
            << (recorder && !options.out.empty() ? "; " + std::to_string(framesWritten) + " frames written"
                                                 : std::string())
            << (options.video.empty() ? "" : "; no video written") << '\n';
        return ExitCode::failed;
    }
    for (const std::string& failure : failures) err << failure << '\n';
    if (!run.goalFrame() && level.level.goal) err << "rube run: goal not reached: " << level.level.goal->text << '\n';
    // Issue 27: levels as scenes, a run whose physics went non-finite fails (it was silent).
    if (const std::string why = unstableStateMessage(run.world()); !why.empty()) {
        err << "rube run: " << why << '\n';
        return ExitCode::failed;
    }
    return failures.empty() && (run.goalFrame() || !level.level.goal) ? ExitCode::ok : ExitCode::failed;
}

} // namespace rube::game
