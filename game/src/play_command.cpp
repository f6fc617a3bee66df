// `rube run` for levels: load the script, take its actions step by step, record frames, then
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
#include <optional>
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

// How a run was cut short, if it was: the step limit given (--steps, --frames or the script's
// `steps`) ended it before the level would have (its time limit, else its duration), so an
// expectation still unmet may be one the run had no time for, not one it failed.
struct RunLength {
    std::int64_t steps = 0;   // steps the run may take
    std::int64_t natural = 0; // steps the level itself would take
    std::string limitedBy;    // "--steps", "--frames" or "the script's steps"; "" when not shorter than natural
};

// What became of one expectation.
enum class Judgement { met, failed, notInTime };

const char* judgementWords(Judgement j) {
    switch (j) {
    case Judgement::met: return "met";
    case Judgement::failed: return "failed";
    case Judgement::notInTime: return "not reached in time";
    }
    return "";
}

struct Judged {
    std::string text;
    Judgement judgement = Judgement::failed;
};

// What a run's summary.json says beside the run itself: how it was recorded.
struct SummaryFrames {
    std::int64_t every = 1;
    std::optional<render::FrameSize> size; // none when no frames were drawn
    std::int64_t written = 0;
    bool files = false; // PNG files in --out (a video alone has no frame files)
};

// The frame that first shows step `step`: frames are taken every `every` steps from step 0.
std::int64_t frameShowing(std::int64_t step, std::int64_t every) { return (step + every - 1) / every; }

// The summary: the run's steps and time step, its frames, the goal (step, time, the frame that
// shows it, where and by what), every event with its step, time and position, and how each
// expectation fared; whether a signal cut the run short (`signal` empty when none did).
std::string summaryJson(const LevelRun& run, const SceneDesc& level, const SummaryFrames& frames,
                        const std::vector<Judged>& expectations, const std::string& signal) {
    std::ostringstream json;
    json << "{\n  \"level\": " << jsonString(level.name) << ",\n  \"steps\": " << run.steps()
         << ",\n  \"time_step\": " << jsonNumber(level.world.timeStep)
         << ",\n  \"time\": " << jsonNumber(run.world().time()) << ",\n  \"every\": " << frames.every
         << ",\n  \"frame_size\": ";
    if (frames.size) json << "[" << frames.size->width << ", " << frames.size->height << "]";
    else json << "null";
    json << ",\n  \"frames_written\": " << frames.written
         << ",\n  \"interrupted\": " << (signal.empty() ? "false" : "true,\n  \"signal\": " + jsonString(signal))
         << ",\n  \"goal_reached\": " << (run.goalStep() ? "true" : "false") << ",\n  \"goal\": ";
    const GameEvent* goal = nullptr;
    for (const GameEvent& e : run.events())
        if (e.kind == EventKind::goal) goal = &e;
    if (goal) {
        const std::int64_t frame = frameShowing(goal->step, frames.every);
        json << "{\"step\": " << goal->step << ", \"time\": " << jsonNumber(goal->time) << ", \"frame\": "
             << (frames.files && frame < frames.written ? jsonString(frameFileName(frame)) : std::string("null"))
             << ", \"position\": [" << jsonNumber(goal->position.x) << ", " << jsonNumber(goal->position.y)
             << "], \"by\": " << jsonString(goal->by) << "}";
    } else {
        json << "null";
    }
    json << ",\n  \"speed_clamps\": " << run.world().stats().speedClamps
         << ",\n  \"isolated_bodies\": " << run.world().stats().isolatedBodies
         << ",\n  \"non_finite\": " << (run.world().stats().nonFinite ? "true" : "false") << ",\n  \"events\": [";
    bool first = true;
    for (const GameEvent& e : run.events()) {
        json << (first ? "\n" : ",\n") << "    {\"kind\": \"" << eventName(e.kind) << "\", \"step\": " << e.step
             << ", \"time\": " << jsonNumber(e.time) << ", \"item\": " << jsonString(e.item) << ", \"position\": ["
             << jsonNumber(e.position.x) << ", " << jsonNumber(e.position.y) << "]";
        if (e.kind == EventKind::hit || e.kind == EventKind::goal) json << ", \"by\": " << jsonString(e.by);
        if (e.kind == EventKind::explosion) json << ", \"bodies\": " << e.count;
        json << "}";
        first = false;
    }
    json << (first ? "" : "\n  ") << "],\n  \"expectations\": [";
    first = true;
    for (const Judged& j : expectations) {
        json << (first ? "\n" : ",\n") << "    {\"expect\": " << jsonString(j.text)
             << ", \"met\": " << (j.judgement == Judgement::met ? "true" : "false") << ", \"result\": \""
             << judgementWords(j.judgement) << "\"}";
        first = false;
    }
    json << (first ? "" : "\n  ") << "]\n}\n";
    return json.str();
}

bool met(const Expectation& e, const LevelRun& run) {
    for (const GameEvent& event : run.events())
        if (event.kind == e.kind && (e.kind == EventKind::goal || event.item == e.item) &&
            (e.by.empty() || event.by == e.by) && event.step < e.beforeStep)
            return true;
    return false;
}

// An unmet expectation is failed when the run saw every step it could be met in (or ran as long
// as the level does); not reached in time when a step limit stopped the run before that.
Judgement judge(const Expectation& e, const LevelRun& run, const RunLength& length) {
    if (met(e, run)) return Judgement::met;
    const bool sawItsSteps = run.steps() + 1 >= e.beforeStep;
    const bool stoppedByLimit = !length.limitedBy.empty() && run.steps() >= length.steps;
    return stoppedByLimit && !sawItsSteps ? Judgement::notInTime : Judgement::failed;
}

RunLength runLength(const RunOptions& options, const SceneDesc& level, const ScriptDesc& script, std::int64_t every) {
    RunLength length;
    length.natural = levelSteps(level);
    length.steps = length.natural;
    std::string by;
    if (script.steps) length.steps = *script.steps, by = "the script's steps";
    // As for a scene: --steps, else enough steps for --frames, else the level's own length.
    if (options.steps) length.steps = *options.steps, by = "--steps";
    else if (options.frames) length.steps = (*options.frames - 1) * every, by = "--frames";
    if (length.steps < length.natural) length.limitedBy = by;
    return length;
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
    const std::int64_t every = options.everyGiven ? options.every : script.every.value_or(options.every);
    const RunLength length = runLength(options, level, script, every);
    const std::int64_t steps = length.steps;
    const render::FrameSize size = options.sizeGiven ? options.size : script.size.value_or(options.size);

    // The trace is opened after the script is read, so a bad script is reported as such, and
    // before the frames: the temporary goes with `trace` if the folder is refused.
    TraceWriter trace;
    if (std::string error; !options.trace.empty() && !trace.open(options.trace, error, kLevelTraceHeader)) {
        err << error << '\n';
        return ExitCode::badInput;
    }
    // The item column: the item's name, else its kind; a shot is "<cannon> shot"; a [[circle]] its name.
    const auto itemLabel = [&](int item) {
        const ItemDesc& desc = run.items()[static_cast<std::size_t>(item)];
        return desc.name.empty() ? std::string(itemKindName(desc.kind)) : desc.name;
    };
    const auto traceName = [&](CircleId c) {
        if (run.isProjectile(c)) return run.nameOf(c) + " shot";
        if (const int item = run.itemOf(c); item >= 0) return itemLabel(item);
        return run.nameOf(c);
    };
    const auto bodyTraceName = [&](int slot) {
        if (const int item = run.itemOfBody(slot); item >= 0) return itemLabel(item);
        return run.bodyName(slot);
    };
    const auto traceState = [&] { trace.writeLevelState(run.world(), traceName, bodyTraceName); };
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
        view = std::make_unique<LevelView>(level.name, sceneCamera(frameScene(level, run.world()), size), size,
                                           LevelViewOptions{options.labels, options.zones});
    }
    const auto record = [&] {
        if (!recorder || (options.frames && framesWritten >= *options.frames)) return;
        view->draw(run, run.steps(), list);
        recorder->record(list, view->camera(), framesWritten++);
    };

    std::vector<std::string> failures;
    std::size_t next = 0;
    InterruptGuard guard;
    const std::int64_t tail = static_cast<std::int64_t>(std::ceil(kAfterGoalSeconds / dt));
    try {
        traceState(); // step 0: the initial state
        for (std::int64_t i = 0;; ++i) {
            for (; next < script.actions.size() && script.actions[next].step == i; ++next)
                if (const std::string why = takeAction(script.actions[next], run); !why.empty())
                    failures.push_back(options.script + ":" + std::to_string(script.actions[next].place.line) + ":" +
                                       std::to_string(script.actions[next].place.column) + ": at step " +
                                       std::to_string(i) + ": " + why);
            if (i % every == 0) record();
            if (i >= steps || (run.goalStep() && i >= *run.goalStep() + tail) || interrupted()) break;
            run.step();
            traceState();
        }
        if (recorder) recorded = recorder->finish();
    } catch (const std::exception& e) {
        err << "rube run: " << e.what() << '\n';
        return ExitCode::failed;
    }

    std::vector<Judged> judged;
    std::vector<std::string> notInTime;
    for (const Expectation& e : script.expectations) {
        judged.push_back({e.describe(), judge(e, run, length)});
        const std::string at = options.script + ":" + std::to_string(e.place.line) + ":" +
                               std::to_string(e.place.column);
        if (judged.back().judgement == Judgement::failed)
            failures.push_back(at + ": expectation failed: " + e.describe());
        else if (judged.back().judgement == Judgement::notInTime)
            notInTime.push_back(at + ": expectation not reached in time: " + e.describe() +
                                " (the run stopped at step " + std::to_string(run.steps()) + ", cut short by " +
                                length.limitedBy + ")");
    }
    const std::string signal = interruptingSignal();
    std::string reason;
    const SummaryFrames summaryFrames{every, recorder ? std::optional(size) : std::nullopt, framesWritten,
                                      recorder && !options.out.empty()};
    if (!options.out.empty() &&
        !writeTextFileAtomically(std::filesystem::path(options.out) / "summary.json",
                                 summaryJson(run, level, summaryFrames, judged, signal), reason)) {
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
    out << "steps:            " << run.steps() << '\n';
    char time[64];
    std::snprintf(time, sizeof time, "%.6g s (%.6g s a step)", run.world().time(), dt);
    out << "simulated time:   " << time << '\n';
    for (const GameEvent& e : run.events())
        out << "event:            step " << e.step << " " << eventName(e.kind) << (e.item.empty() ? "" : " " + e.item)
            << (e.by.empty() ? "" : " by " + e.by) << '\n';
    // A level without a [goal] has nothing to miss: it says so and exits 0, as a physics scene does.
    std::string goalWords = "none (the level has no [goal])";
    if (run.goalStep()) {
        goalWords = "reached at step " + std::to_string(*run.goalStep());
        if (recorder && !options.out.empty() && frameShowing(*run.goalStep(), every) < framesWritten)
            goalWords += " (" + frameFileName(frameShowing(*run.goalStep(), every)) + ")";
    } else if (level.level.goal) {
        goalWords = length.limitedBy.empty() || run.steps() < length.steps
                        ? "not reached"
                        : "not reached in time: the run stopped at step " + std::to_string(run.steps()) + " (" +
                              length.limitedBy + "), the level runs " + std::to_string(length.natural);
    }
    out << "goal:             " << goalWords << '\n';
    out << "speed clamps:     " << run.world().stats().speedClamps << '\n';
    out << "isolated bodies:  " << run.world().stats().isolatedBodies << '\n';
    if (signal.empty() && !options.trace.empty())
        out << "trace:            " << options.trace << " (" << trace.rows() << " rows)\n";
    if (recorder && !options.out.empty())
        out << "frames:           " << framesWritten << " of " << size.width << "x" << size.height << ", one every "
            << every << (every == 1 ? " step" : " steps") << ", in " << options.out << " (summary in " << options.out
            << "/summary.json)\n";
    if (recorder) out << recordingSummary(target, recorded);
    if (!signal.empty()) {
        // One line, not the expectations the cut-short run could not meet.
        out << "interrupted:      by " << signal << " at step " << run.steps() << '\n';
        err << "rube run: interrupted by " << signal << " at step " << run.steps()
            << (recorder && !options.out.empty() ? "; " + std::to_string(framesWritten) + " frames written"
                                                 : std::string())
            << (options.video.empty() ? "" : "; no video written") << '\n';
        return ExitCode::failed;
    }
    for (const std::string& failure : failures) err << failure << '\n';
    for (const std::string& late : notInTime) err << late << '\n';
    if (!run.goalStep() && level.level.goal)
        err << "rube run: goal not reached"
            << (length.limitedBy.empty() || run.steps() < length.steps ? "" : " in time") << ": "
            << level.level.goal->text << '\n';
    // Issue 27: levels as scenes, a run whose physics went non-finite fails (it was silent).
    if (const std::string why = unstableStateMessage(run.world()); !why.empty()) {
        err << "rube run: " << why << '\n';
        return ExitCode::failed;
    }
    // Not reached in time is not met either: the run shows no goal, so it is not a pass.
    return failures.empty() && notInTime.empty() && (run.goalStep() || !level.level.goal) ? ExitCode::ok
                                                                                          : ExitCode::failed;
}

} // namespace rube::game
