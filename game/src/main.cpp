// The `rube` command: one class per subcommand sets up its options and runs it; main() only
// parses the command line and hands over to the subcommand chosen.
#include "check_command.hpp"
#include "edit_window.hpp"
#include "exit_codes.hpp"
#include "items_command.hpp"
#include "play_window.hpp"
#include "run_command.hpp"
#include "solve_command.hpp"

#include "rube/render/video_writer.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

namespace {

using rube::game::ExitCode;

constexpr const char* kRunFooter =
    "Prints: scene, method, steps, simulated time, wall time of the physics alone, impacts,\n"
    "  resting contacts, caps hit (steps that reached max_events_per_step), escapes (bodies that\n"
    "  left the bounds) and the state hash: equal hashes mean bit-identical final states.\n"
    "Steps: --steps N; else (N - 1) x K with --frames N; else the scene's [world] duration /\n"
    "  time_step rounded up; else 600.\n"
    "Methods: discrete (fixed step, pushes overlaps apart; tunnels when speed x dt > 2r),\n"
    "  turn-based (bodies move one by one until their first impact; order matters),\n"
    "  exact (earliest time of impact over all pairs, one at a time),\n"
    "  solver (substepped contact solver, for piles and resting contact),\n"
    "  auto (the cheapest that holds, step by step: exact while it can afford the scene's\n"
    "  impacts, the solver for piles, crowds and friction; the default for levels).\n"
    "Trace: CSV with the header step,time,body,x,y,vx,vy,angle,omega,radius; one row per\n"
    "  dynamic circle per step. Step 0 is the initial state, so N steps give N + 1 rows per\n"
    "  body. body is the circle's index: [[circle]]s in file order, then [[circle_grid]]s row\n"
    "  by row from the bottom. Numbers are printed with %.17g, so traces compare byte for byte.\n"
    "  angle and omega are 0 until bodies rotate. The trace is written to a temporary file and\n"
    "  renamed at the end: a failed or interrupted run leaves no trace file.\n"
    "Frames: with --out DIR, DIR/frame_00000.png is the initial state and frame n shows the\n"
    "  world after n x K steps (--every K, default 1), five digits as ffmpeg's frame_%05d.png\n"
    "  reads them. --frames N stops after N frames, frame 0 included (default: steps / K + 1);\n"
    "  without --steps the run then lasts (N - 1) x K steps. DIR is created if missing, and\n"
    "  frames of an earlier run in it (frame_NNNNN.png, nothing else) are removed first. PNGs\n"
    "  are encoded on a second thread while the next frame is simulated and drawn; the summary\n"
    "  adds the frame count, size, mean bytes per frame and frames per second. A progress line\n"
    "  is shown only when stderr is a terminal.\n"
    "Picture: the camera is fixed for the run: the scene's [view] if it has one, else its\n"
    "  [world] bounds, else every body at the start with a margin. Dynamic balls are white,\n"
    "  kinematic bodies light grey, static ones dark grey; the top line shows scene, step,\n"
    "  simulated time and method. A step is one step of the simulation, a frame one picture\n"
    "  written (every K steps): frame n shows step n x K.\n"
    "Levels: the summary and DIR/summary.json give the goal's step, time, position, what reached\n"
    "  it and the frame that shows it, and every event by step; --labels writes item names and\n"
    "  --zones draws the placement zones. A level's trace has the header\n"
    "  step,time,body,item,x,y,vx,vy,angle,omega,radius: every dynamic body (circles c<slot>,\n"
    "  boxes and capsules b<slot>, radius empty) with its item's name. --steps or --frames that\n"
    "  stop the run before the level's time limit report an unmet expectation as 'not reached in\n"
    "  time' (still exit 1); --method, --trails and --debug-impacts are for physics scenes only.\n"
    "Video: --video FILE.mp4 (H.264), .webm (VP9) or .gif (one palette made from the frames)\n"
    "  pipes the frames --out would write, as raw RGB, to ffmpeg (apt-get install ffmpeg), at\n"
    "  1 / (time step x K) frames a second: real time. The video appears under its name only\n"
    "  when ffmpeg has finished; an interrupted or failed run leaves none. Or from PNGs:\n"
    "  ffmpeg -framerate 60 -i out/frame_%05d.png -pix_fmt yuv420p out.mp4\n"
    "GL: --gl egl draws with EGL without a window system, --gl osmesa with Mesa's OSMesa (gone\n"
    "  from Mesa 25.1), --gl auto (default) with EGL where it starts, else OSMesa; both are\n"
    "  Mesa's llvmpipe on the CPU. The summary's gl: line names the one that drew.\n"
    "Without --out or --video and without --no-render, the run is headless with a note on stderr;\n"
    "  --no-render never starts a GL context.\n"
    "A bad scene is reported by its first error only; 'rube check' lists them all.\n"
    "Exit status: 0 done, 1 the run failed (trace, frame or video not written, ffmpeg failed or\n"
    "  missing, no GL context, interrupted), 2 bad input (scene, options, trace, frame folder or\n"
    "  video not creatable).";

constexpr const char* kCheckFooter =
    "Every error is one line, file:line:col: message, so editors can jump to it. Unknown keys are\n"
    "errors (a typo must not silently become a default) and come with the closest known key.\n"
    "Scripts: a file named NAME.solution.toml, or holding level, steps, [capture], [[place]],\n"
    "  [[action]] or [[expect]], is a solution script. It is checked against its level (--level\n"
    "  LEVEL, else NAME.toml beside it): every placement allowed, every item an action or\n"
    "  expectation names exists and is of the right kind, actions in step order. An old key gets\n"
    "  its new name: 'frame' is now 'step', 'before_frame' is now 'before_step'.\n"
    "Levels are also linted, as 'file:line:col: warning: message': no [goal]; a zone outside the\n"
    "  [view] or the world's bounds; an inventory without a zone or zones without an inventory;\n"
    "  fixed items overlapping; and, run headless, a goal reached with nothing placed, or a\n"
    "  NAME.solution.toml beside the level that does not reach the goal.\n"
    "Exit status: 0 when every file is ok (warnings allowed unless --strict), 2 otherwise.";

constexpr const char* kPlayFooter =
    "The window shows the level as 'rube run' draws it, with the inventory bar below.\n"
    "Levels: with no LEVEL, a list of the levels of levels/index.toml (--index FILE) in order, with\n"
    "  those solved marked; Enter or a click plays one, Esc in a level goes back to the list. Solved\n"
    "  levels are kept in $XDG_DATA_HOME/rube/solved.txt (else ~/.local/share/rube/solved.txt).\n"
    "Editing: drag an item from the bar into a green placement zone; it turns red, with the reason\n"
    "  on the bar, where it may not go. Wheel or [ ] turns planks, ramps and fans by 15 degrees;\n"
    "  drag a placed item to move it, right-click or Delete removes it (or drop it on the bar).\n"
    "  Drag from a cannon to aim it (the predicted arc follows); the wheel over it turns 1 degree.\n"
    "  Ctrl+Z undoes an edit, Ctrl+Y redoes it (100 deep); G turns the 5 cm grid off (1 mm) and on;\n"
    "  the bar's top right shows the cursor's coordinates. H shows the level's next hint.\n"
    "Keys: Space runs the machine, R resets to editing with placements kept, P pauses, S slow\n"
    "  motion (a tenth of real time), D toggles trails, C clears them, Esc quits.\n"
    "Running: click a cannon to fire it, a bomb to set it off, a switch, fan or magnet to flip it.\n"
    "  Past the goal's time_limit without the goal the HUD and bar say TIME UP; R retries. After the\n"
    "  goal, N goes to the next level and W plays the intended solution (NAME.solution.toml).\n"
    "Recording: --record FILE writes the placements, the aims (step-0 actions), the actions taken\n"
    "  while running (at their step numbers) and, if the goal was reached, an expectation that it\n"
    "  is reached again; 'rube run LEVEL --script FILE --out DIR' replays it off-screen, step for\n"
    "  step. The script records the last level's session as it ends: after R, the edits.\n"
    "--quit-after N closes the window when the machine has taken N steps, whatever the frame rate.\n"
    "Without a display, play says so: use 'rube run' or 'xvfb-run rube play LEVEL'.\n"
    "Exit status: 0 done, 1 the last run ended without its goal (as 'rube run') or no window could\n"
    "  be opened, 2 bad input (level, index, script, --record path).";

constexpr const char* kMainFooter =
    "Scene files are TOML: see levels/physics/ for examples and game/scene-format.md for every key.\n"
    "Run 'rube run --help', 'rube play --help', 'rube check --help', 'rube items --help' or\n"
    "  'rube solve --help' for a command's options.\n"
    "Exit status: 0 ok, 1 a run failed, 2 bad input or usage (every message is one line on stderr).";

constexpr const char* kSolveFooter =
    "The space: for each inventory part, its centre on a grid in every placement zone (a step of a\n"
    "  quarter of the part's size, or --step), its angle every --angle-step degrees if it turns (a\n"
    "  board over half a turn, a fan or rocket over a whole one); every subset of the inventory up\n"
    "  to its counts, none included; for each fixed part a click acts on (that the level's clicks\n"
    "  allow), the step it is clicked at\n"
    "  (never, or every --action-every seconds up to the time limit) and, for a cannon, its aim (as\n"
    "  the level has it, every --aim-step degrees, or at each target on the low or high arc).\n"
    "Each candidate is checked by the placement rules of the window and of scripts, then run headless\n"
    "  as 'rube run --script' runs it, to the goal's time limit, stopping at the goal or once nothing\n"
    "  has moved for 1 s with no click, timer, path or thruster still to come.\n"
    "Search: every candidate when the space holds at most --budget. Else each subset of the inventory\n"
    "  gets an equal share of the budget (one smaller than its share is searched whole, and leaves\n"
    "  the rest to the others), and a larger one that many candidates drawn at random from --seed:\n"
    "  the same level, options, budget and seed give the same result and byte-identical --json.\n"
    "Report: the solutions grouped by the parts and clicks they use; a group is a shortcut when it\n"
    "  uses fewer parts than the level's NAME.solution.toml, or parts or clicks it does not; the\n"
    "  solve fraction (solutions over candidates the rules allow, a sampled subset weighted by its\n"
    "  size); the most robust solution, whose\n"
    "  grid neighbours (one step on one axis) most often solve too. --scripts DIR writes every\n"
    "  solution as DIR/LEVEL-NUMBER.solution.toml, which 'rube run LEVEL --script' replays to the\n"
    "  same goal step.\n"
    "Parallel: --jobs N runs N threads, with the same result as one. --shard I/N searches the\n"
    "  candidates whose number is I modulo N; 'rube solve LEVEL --merge A.json B.json ...' (with the\n"
    "  same space options) joins the slices' --json into what one run gives.\n"
    "Progress (candidates, solutions, rate, time left) is shown on stderr only when it is a terminal.\n"
    "Exit status: 0 a solution was found, 1 none was (or a file could not be written), 2 bad input.";

// Usage errors are one line on stderr, pointing at the help that explains the option.
ExitCode usageError(const std::string& message, const std::string& help) {
    std::cerr << "rube: " << message << " (see '" << help << "')\n";
    return ExitCode::badInput;
}

// CLI11 messages are one line already; this keeps them so if a future version adds a line break.
std::string oneLine(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    return text;
}

// CLI11's own range check prints the largest double in full; this says what a step count is.
std::string stepCount(const std::string& text) {
    std::int64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || value < 0)
        return "expected a whole number of steps, 0 or more, got '" + text + "'";
    // A run longer than this is a typo, not a plan: it would not end this year.
    if (value > 1'000'000'000) return "expected at most 1000000000 steps, got '" + text + "'";
    return {};
}

// A whole number from 1 to a billion, for --every and --frames; `what` names the unit.
CLI::Validator countFromOne(std::string what) {
    return CLI::Validator(
        [what](const std::string& text) -> std::string {
            std::int64_t value = 0;
            const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (error != std::errc{} || end != text.data() + text.size() || value < 1 || value > 1'000'000'000)
                return "expected a whole number of " + what + " from 1 to 1000000000, got '" + text + "'";
            return {};
        },
        "");
}

// "WxH" with both sides from 1 to kMaxFrameSide; nothing when `text` is not that.
std::optional<rube::render::FrameSize> parseFrameSize(const std::string& text) {
    const auto side = [](const char* begin, const char* end) -> std::optional<int> {
        int value = 0;
        const auto [stop, error] = std::from_chars(begin, end, value);
        if (error != std::errc{} || stop != end || value < 1 || value > rube::game::kMaxFrameSide) return std::nullopt;
        return value;
    };
    const auto x = text.find('x');
    if (x == std::string::npos) return std::nullopt;
    const auto width = side(text.data(), text.data() + x);
    const auto height = side(text.data() + x + 1, text.data() + text.size());
    if (!width || !height) return std::nullopt;
    return rube::render::FrameSize{*width, *height};
}

std::string frameSizeError(const std::string& text) {
    if (parseFrameSize(text)) return {};
    return "expected WxH in pixels, each from 1 to " + std::to_string(rube::game::kMaxFrameSide) + ", got '" + text +
           "'";
}

std::string videoFileError(const std::string& text) {
    if (rube::render::videoFormatOf(text)) return {};
    return "expected a file ending in .mp4, .webm or .gif, got '" + text + "'";
}

std::string glBackendError(const std::string& text) {
    if (rube::render::glBackendFromName(text)) return {};
    return "expected auto, egl or osmesa, got '" + text + "'";
}

// CLI11 keeps pointers to the fields it fills, so a command is made in place and never copied.
class Command {
public:
    Command() = default;
    Command(const Command&) = delete;
    Command& operator=(const Command&) = delete;
};

// `rube run SCENE`: the options, and the checks between them that CLI11 is not told of.
class RunCommand : Command {
public:
    explicit RunCommand(CLI::App& app);
    bool chosen() const { return static_cast<bool>(*command_); }
    ExitCode run();

private:
    CLI::App* command_ = nullptr;
    rube::game::RunOptions options_;
    std::int64_t steps_ = 0;
    std::int64_t frames_ = 0;
    std::string size_ = "1280x720";
    std::string gl_ = "auto";
    CLI::Option* stepsOption_ = nullptr;
    CLI::Option* outOption_ = nullptr;
    CLI::Option* videoOption_ = nullptr;
    CLI::Option* everyOption_ = nullptr;
    CLI::Option* framesOption_ = nullptr;
    CLI::Option* sizeOption_ = nullptr;
    std::vector<CLI::Option*> needOut_; // the options that only mean something with --out or --video
};

RunCommand::RunCommand(CLI::App& app) {
    command_ = app.add_subcommand(
        "run", "Simulate a scene and print a summary; optionally write PNG frames, a video and a CSV trace");
    command_->footer(kRunFooter);
    command_->add_option("scene", options_.scene, "The scene file (.toml) to simulate")->required()->type_name("SCENE");
    command_
        ->add_option("--script", options_.script,
                     "Play a level with this script (levels/NAME.solution.toml): placements, actions, expectations")
        ->type_name("FILE");
    command_->add_flag("--no-render", options_.noRender,
                       "Run headless: no GL context and no frames (summary and --trace)");
    stepsOption_ = command_->add_option("--steps", steps_, "Number of time steps to simulate (0 or more)")
                       ->type_name("N")
                       ->check(CLI::Validator(stepCount, ""));
    command_->add_option("--trace", options_.trace, "Write every dynamic body's state at every step to this CSV file")
        ->type_name("FILE");
    command_
        ->add_option("--method", options_.method,
                     "Time-step method, overriding the scene's: discrete, turn-based, exact, solver or auto")
        ->type_name("NAME");
    // --out and the options that only mean something with it are checked after parsing, not
    // with CLI11's needs/excludes, which would print "Needs: --out" beside every one in --help.
    outOption_ = command_
                     ->add_option("--out", options_.out,
                                  "Write PNG frames DIR/frame_00000.png, frame_00001.png, ... (created if missing)")
                     ->type_name("DIR");
    videoOption_ = command_
                       ->add_option("--video", options_.video,
                                    "Write the frames as a video through ffmpeg: FILE.mp4, FILE.webm or FILE.gif")
                       ->type_name("FILE")
                       ->check(CLI::Validator(videoFileError, ""));
    everyOption_ = command_->add_option("--every", options_.every, "Steps between frames (default 1: every step)")
                       ->type_name("K")
                       ->check(countFromOne("steps"));
    framesOption_ = command_
                        ->add_option("--frames", frames_, "Frames to write, frame 0 included (default: steps / K + 1)")
                        ->type_name("N")
                        ->check(countFromOne("frames"));
    sizeOption_ = command_->add_option("--size", size_, "Frame size in pixels, each side 1 to 8192 (default 1280x720)")
                      ->type_name("WxH")
                      ->check(CLI::Validator(frameSizeError, ""));
    needOut_ = {
        everyOption_,
        framesOption_,
        sizeOption_,
        command_->add_flag("--trails", options_.trails,
                           "Draw each dynamic ball's path over the last 2 s (debug key D)"),
        command_->add_flag("--debug-impacts", options_.debugImpacts,
                           "Mark points of impact with rings and collision normals with arrows (for 0.25 s)"),
        command_->add_flag("--labels", options_.labels, "Levels: write each named item's name beside it"),
        command_->add_flag("--zones", options_.zones, "Levels: draw the placement zones, as the play window does"),
        command_
            ->add_option("--gl", gl_, "Offscreen GL: egl, osmesa or auto (default: EGL where it starts, else OSMesa)")
            ->type_name("NAME")
            ->check(CLI::Validator(glBackendError, "")),
    };
}

ExitCode RunCommand::run() {
    if (*outOption_ && options_.noRender) return usageError("--no-render excludes --out", "rube run --help");
    if (*videoOption_ && options_.noRender) return usageError("--no-render excludes --video", "rube run --help");
    if (*outOption_ && options_.out.empty()) return usageError("--out: expected a folder, got ''", "rube run --help");
    for (const CLI::Option* option : needOut_) {
        if (*option && !*outOption_ && !*videoOption_)
            return usageError(option->get_name() + " requires --out or --video", "rube run --help");
    }
    options_.gl = *rube::render::glBackendFromName(gl_); // the validator has accepted it, or it is the default
    if (*stepsOption_) options_.steps = steps_;
    if (*framesOption_) options_.frames = frames_;
    options_.everyGiven = static_cast<bool>(*everyOption_);
    options_.sizeGiven = static_cast<bool>(*sizeOption_);
    options_.size = *parseFrameSize(size_); // the validator has accepted it, or it is the default
    if (*videoOption_) {
        const std::string why = rube::render::videoSizeProblem(*rube::render::videoFormatOf(options_.video),
                                                               options_.size);
        if (!why.empty()) return usageError("--video " + options_.video + ": " + why, "rube run --help");
    }
    options_.progress = ::isatty(STDERR_FILENO) == 1;
    return rube::game::runScene(options_, std::cout, std::cerr);
}

// `rube play LEVEL`: the window's options.
class PlayCommand : Command {
public:
    explicit PlayCommand(CLI::App& app);
    bool chosen() const { return static_cast<bool>(*command_); }
    ExitCode run();

private:
    CLI::App* command_ = nullptr;
    rube::game::PlayOptions options_;
    std::string size_ = "1280x720";
    std::int64_t quitAfter_ = 0;
    bool noVsync_ = false;
    CLI::Option* sizeOption_ = nullptr;
    CLI::Option* quitAfterOption_ = nullptr;
};

PlayCommand::PlayCommand(CLI::App& app) {
    command_ = app.add_subcommand("play",
                                  "Play a level in a window with the mouse and keys; optionally record it as a script");
    command_->footer(kPlayFooter);
    command_->add_option("level", options_.level, "The level file (.toml) to play; none: the list of levels")
        ->type_name("LEVEL");
    command_
        ->add_option("--index", options_.index,
                     "The levels in order, for the list and N (default levels/index.toml, from where rube runs)")
        ->type_name("FILE");
    command_
        ->add_option("--script", options_.script,
                     "Start from this script: its placements and aims; its other actions play as the machine runs")
        ->type_name("FILE");
    command_
        ->add_option("--record", options_.record,
                     "When the session ends, write it as a script that 'rube run --script' replays")
        ->type_name("FILE");
    sizeOption_ = command_->add_option("--size", size_, "Level area in pixels, as rube run's frames (default 1280x720)")
                      ->type_name("WxH")
                      ->check(CLI::Validator(frameSizeError, ""));
    command_->add_flag("--run", options_.runAtOnce, "Start the machine at once, as if Space were pressed");
    quitAfterOption_ = command_
                           ->add_option("--quit-after", quitAfter_,
                                        "Close the window once the machine has taken N steps")
                           ->type_name("N")
                           ->check(countFromOne("steps"));
    command_
        ->add_option("--steps-per-frame", options_.stepsPerFrame,
                     "Take K steps per frame drawn instead of following real time")
        ->type_name("K")
        ->check(countFromOne("steps"));
    command_->add_flag("--no-vsync", noVsync_,
                       "Draw as fast as possible instead of at the display's refresh (for measuring)");
}

ExitCode PlayCommand::run() {
    if (*quitAfterOption_) options_.quitAfter = quitAfter_;
    if (*sizeOption_) options_.size = *parseFrameSize(size_); // the validator has accepted it
    options_.vsync = !noVsync_;
    return rube::game::playInWindow(options_, std::cout, std::cerr);
}

// `rube edit [LEVEL]`: the editor's options.
class EditCommand : Command {
public:
    explicit EditCommand(CLI::App& app);
    bool chosen() const { return static_cast<bool>(*command_); }
    ExitCode run();

private:
    CLI::App* command_ = nullptr;
    rube::game::EditOptions options_;
    std::string size_ = "1280x720";
    CLI::Option* sizeOption_ = nullptr;
};

EditCommand::EditCommand(CLI::App& app) {
    command_ = app.add_subcommand("edit", "Make a level (or change LEVEL) in a window, and save it with its solution");
    command_->footer("A click places the kind shown on the bar (Tab picks the next; every kind, without limit) or\n"
                     "  picks up a part to move it; [ ] or the wheel turns it by 15 degrees; right-click or Delete\n"
                     "  removes a part or a zone. Z switches to zones: a drag draws a placement zone, a drag from a\n"
                     "  zone's corner resizes it. P marks the part under the cursor as the player's: it is saved as\n"
                     "  a placement of NAME.solution.toml and counted into the inventory (P again makes it fixed);\n"
                     "  I and K add and take a spare of the kind shown. T makes the target or bucket under the\n"
                     "  cursor the goal (10 s; T again on its target: every target); Up and Down change the time\n"
                     "  limit by 1 s; O types the goal's text. V fits the view to the parts and zones; C shows\n"
                     "  three times as much around it (the wheel zooms) and a drag there draws the view (C again:\n"
                     "  no change). E over a part types its own keys (those 'rube items' lists for its kind; a\n"
                     "  player's part keeps them in its [[place]]; Tab: the next key, Enter sets them, nothing\n"
                     "  typed: the default), checked by the level reader. L on a switch links it to the next part\n"
                     "  it can trigger. H types a hint; J picks the level's hints in turn: Enter changes the one\n"
                     "  shown, Delete removes it. Text is typed in the bar: Enter keeps it, Esc drops it. Space\n"
                     "  tries the level as 'rube play' would, R or Esc comes back. Ctrl+Z and Ctrl+Y undo and redo;\n"
                     "  Ctrl+S saves the level and NAME.solution.toml beside it, with the goal's step as the\n"
                     "  solution's expectation. Esc quits (without saving).\n"
                     "Exit status: 0 done, 1 no window could be opened, 2 bad input (level, its solution, --out).");
    command_->add_option("level", options_.level, "The level file (.toml) to change; none: a new level")
        ->type_name("LEVEL");
    command_->add_option("--out", options_.out, "Save to FILE (default: LEVEL, else new-level.toml)")
        ->type_name("FILE");
    sizeOption_ = command_->add_option("--size", size_, "Level area in pixels (default 1280x720)")
                      ->type_name("WxH")
                      ->check(CLI::Validator(frameSizeError, ""));
}

ExitCode EditCommand::run() {
    if (*sizeOption_) options_.size = *parseFrameSize(size_); // the validator has accepted it
    return rube::game::editInWindow(options_, std::cout, std::cerr);
}

// `rube check FILE...`: the files, the level scripts are checked against, and --strict.
class CheckCommand : Command {
public:
    explicit CheckCommand(CLI::App& app);
    bool chosen() const { return static_cast<bool>(*command_); }
    ExitCode run() const { return rube::game::checkFiles(options_, std::cout, std::cerr); }

private:
    CLI::App* command_ = nullptr;
    rube::game::CheckOptions options_;
};

CheckCommand::CheckCommand(CLI::App& app) {
    command_ = app.add_subcommand(
        "check", "Validate scene, level and script files and lint levels; every error as file:line:col: message");
    command_->footer(kCheckFooter);
    command_->add_option("files", options_.files, "Scene, level and solution script files (.toml) to validate")
        ->required()
        ->type_name("FILE");
    command_
        ->add_option("--level", options_.level,
                     "The level the scripts given are checked against (default: NAME.toml beside NAME.solution.toml)")
        ->type_name("LEVEL");
    command_->add_flag("--strict", options_.strict, "Treat warnings as errors (exit 2); CI checks levels/ with it");
}

// `rube items [--sheet DIR]`: the catalogue of part kinds, or their pictures.
class ItemsCommand : Command {
public:
    explicit ItemsCommand(CLI::App& app);
    bool chosen() const { return static_cast<bool>(*command_); }
    ExitCode run();

private:
    CLI::App* command_ = nullptr;
    rube::game::ItemsOptions options_;
    std::string size_ = "320x240";
    CLI::Option* sheetOption_ = nullptr;
    CLI::Option* sizeOption_ = nullptr;
};

ItemsCommand::ItemsCommand(CLI::App& app) {
    command_ = app.add_subcommand("items",
                                  "List every part kind with its keys, defaults, units and meaning; or draw them");
    command_->footer("The same catalogue, with pictures, is game/items.md. Every picture is one kind's default\n"
                     "  item drawn as 'rube run' draws levels, with its name, its inventory icon in the top right\n"
                     "  corner and a 1 m bar (each picture is framed to its part). A progress line is shown only\n"
                     "  when stderr is a terminal. Regenerate the committed pictures with\n"
                     "  rube items --sheet game/items.\n"
                     "Exit status: 0 done, 1 no GL context, 2 bad usage or a folder that cannot be written.");
    sheetOption_ = command_
                       ->add_option("--sheet", options_.sheet,
                                    "Draw one labelled PNG per kind into DIR/<kind>.png (created if missing)")
                       ->type_name("DIR");
    sizeOption_ = command_->add_option("--size", size_, "Each picture's size in pixels (default 320x240)")
                      ->type_name("WxH")
                      ->check(CLI::Validator(frameSizeError, ""));
}

ExitCode ItemsCommand::run() {
    if (*sheetOption_ && options_.sheet.empty())
        return usageError("--sheet: expected a folder, got ''", "rube items --help");
    if (*sizeOption_ && !*sheetOption_) return usageError("--size requires --sheet", "rube items --help");
    options_.size = *parseFrameSize(size_); // the validator has accepted it, or it is the default
    options_.progress = ::isatty(STDERR_FILENO) == 1;
    return rube::game::listItems(options_, std::cout, std::cerr);
}

// `rube solve LEVEL`: the search's options.
class SolveCommand : Command {
public:
    explicit SolveCommand(CLI::App& app);
    bool chosen() const { return static_cast<bool>(*command_); }
    rube::game::ExitCode run();

private:
    CLI::App* command_ = nullptr;
    rube::game::SolveCommandOptions options_;
    std::string shard_;
    double step_ = 0.0;
    CLI::Option* stepOption_ = nullptr;
    CLI::Option* shardOption_ = nullptr;
};

// "I/N" with 0 <= I < N; "" when it is, else why not.
std::string shardError(const std::string& text) {
    const auto slash = text.find('/');
    int index = -1, count = 0;
    if (slash != std::string::npos) {
        const auto [a, ea] = std::from_chars(text.data(), text.data() + slash, index);
        const auto [b, eb] = std::from_chars(text.data() + slash + 1, text.data() + text.size(), count);
        if (ea == std::errc{} && a == text.data() + slash && eb == std::errc{} && b == text.data() + text.size() &&
            count >= 1 && count <= 1'000'000 && index >= 0 && index < count)
            return {};
    }
    return "expected I/N with 0 <= I < N (the I-th of N slices, counted from 0), got '" + text + "'";
}

SolveCommand::SolveCommand(CLI::App& app) {
    command_ = app.add_subcommand(
        "solve", "Search a level's placements and clicks: solutions, shortcuts, solve fraction, most robust");
    command_->footer(kSolveFooter);
    command_->add_option("level", options_.level, "The level file (.toml) to search")->required()->type_name("LEVEL");
    command_
        ->add_option("--budget", options_.search.budget,
                     "Runs: the whole space if it is no larger, else this many, shared equally among the inventory "
                     "subsets (default 2000)")
        ->type_name("RUNS")
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1'000'000'000}));
    command_->add_option("--seed", options_.search.seed, "Seed of the random search (default 1)")->type_name("N");
    command_->add_option("--jobs", options_.search.jobs, "Threads (default 1); the result is the same on any number")
        ->type_name("N")
        ->check(CLI::Range(1, 256));
    shardOption_ = command_->add_option("--shard", shard_, "Search only slice I of N (candidates numbered I mod N)")
                       ->type_name("I/N")
                       ->check(CLI::Validator(shardError, ""));
    command_->add_option("--merge", options_.merge, "Join these slices' --json results instead of searching")
        ->type_name("FILE")
        ->expected(1, -1);
    command_->add_option("--json", options_.json, "Write the result as JSON to FILE")->type_name("FILE");
    command_->add_option("--scripts", options_.scripts, "Write every solution as DIR/LEVEL-NUMBER.solution.toml")
        ->type_name("DIR");
    stepOption_ = command_
                      ->add_option("--step", step_,
                                   "Grid step in the zones, m (default: a quarter of each part's size)")
                      ->type_name("M")
                      ->check(CLI::Range(1e-3, 100.0));
    command_
        ->add_option("--angle-step", options_.search.space.angleStep,
                     "Degrees between a turning part's angles (default 15)")
        ->type_name("DEG")
        ->check(CLI::Range(0.1, 180.0));
    command_->add_option("--aim-step", options_.search.space.aimStep, "Degrees between a cannon's aims (default 5)")
        ->type_name("DEG")
        ->check(CLI::Range(0.1, 180.0));
    command_
        ->add_option("--action-every", options_.search.space.actionEvery,
                     "Seconds between the steps a click is tried at (default 0.5)")
        ->type_name("S")
        ->check(CLI::Range(1e-3, 1000.0));
}

rube::game::ExitCode SolveCommand::run() {
    if (*shardOption_) {
        if (!options_.merge.empty()) return usageError("--shard excludes --merge", "rube solve --help");
        const auto slash = shard_.find('/');
        options_.search.shardIndex = std::stoi(shard_.substr(0, slash));
        options_.search.shardCount = std::stoi(shard_.substr(slash + 1));
    }
    if (*stepOption_) options_.search.space.step = step_;
    // A merge takes the budget and seed from the slices and runs nothing: these would be ignored.
    for (const char* name : {"--budget", "--seed", "--jobs"})
        if (!options_.merge.empty() && command_->count(name) > 0)
            return usageError(std::string("--merge excludes ") + name + " (the slices hold the search's own)",
                              "rube solve --help");
    options_.progress = ::isatty(STDERR_FILENO) == 1;
    return rube::game::solveCommand(options_, std::cout, std::cerr);
}

// Parses the command line into the commands' fields. Returns the status to exit with when there
// is nothing to run (--help, --version, a usage error), nothing when a command is to run.
std::optional<ExitCode> parseCommandLine(CLI::App& app, int argc, char** argv) {
    // CLI11 would call a misspelt command a missing one ("A subcommand is required").
    if (argc > 1 && argv[1][0] != '-') {
        const auto commands = std::as_const(app).get_subcommands([](const CLI::App*) { return true; });
        if (std::none_of(commands.begin(), commands.end(), [&](const CLI::App* c) { return c->check_name(argv[1]); })) {
            std::cerr << "rube: unknown command '" << argv[1]
                      << "': the commands are run, play, edit, check, items and solve (see 'rube --help')\n";
            return ExitCode::badInput;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help and --version come here too, with CLI11's exit code 0: let CLI11 print them.
        if (e.get_exit_code() == 0) {
            app.exit(e);
            return ExitCode::ok;
        }
        // CLI11's own codes for parse errors (105, 106, ...) are all bad usage here. Point at the
        // help of the command that was being parsed, where the options are explained.
        const auto chosen = app.get_subcommands();
        const std::string help = chosen.empty() ? "rube --help" : "rube " + chosen.front()->get_name() + " --help";
        return usageError(oneLine(e.what()), help);
    }
    return std::nullopt;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"rube: a greybox physics puzzle game of the Incredible Machine kind.\n"
                 "Runs physics scenes, renders them to PNG frames, plays levels in a window and checks scene files.",
                 "rube"};
    app.footer(kMainFooter);
    app.set_version_flag("--version", "rube " RUBE_VERSION);
    app.require_subcommand(1);
    app.get_formatter()->column_width(26);
    RunCommand run(app);
    CheckCommand check(app);
    PlayCommand play(app);
    EditCommand edit(app);
    ItemsCommand items(app);
    SolveCommand solve(app);

    if (const std::optional<ExitCode> done = parseCommandLine(app, argc, argv)) return rube::game::exitStatus(*done);
    if (run.chosen()) return rube::game::exitStatus(run.run());
    if (play.chosen()) return rube::game::exitStatus(play.run());
    if (edit.chosen()) return rube::game::exitStatus(edit.run());
    if (items.chosen()) return rube::game::exitStatus(items.run());
    if (solve.chosen()) return rube::game::exitStatus(solve.run());
    return rube::game::exitStatus(check.run());
}
