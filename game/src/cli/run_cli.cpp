// `rube run SCENE`: its options, and the checks between them that CLI11 is not told of.
#include "command_line.hpp"

#include "run_command.hpp"

#include "rube/render/render_context.hpp"
#include "rube/render/video_writer.hpp"

#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include <unistd.h>

namespace rube::game::cli {

namespace {

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
    "  dynamic body per step. Step 0 is the initial state, so N steps give N + 1 rows per\n"
    "  body. body is a circle's index ([[circle]]s in file order, then [[circle_grid]]s row\n"
    "  by row from the bottom), or b0, b1, ... for the boxes and capsules after the circles\n"
    "  (every [[box]], then every [[capsule]], in file order; radius empty). Numbers are\n"
    "  printed with %.17g, so traces compare byte for byte.\n"
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

// `rube run SCENE`: the options, and the checks between them that CLI11 is not told of.
class RunCommand final : public Subcommand {
public:
    explicit RunCommand(CLI::App& app);
    bool chosen() const override { return static_cast<bool>(*command_); }
    ExitCode run() override;

private:
    CLI::App* command_ = nullptr;
    RunOptions options_;
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
    options_.gl = *render::glBackendFromName(gl_); // the validator has accepted it, or it is the default
    if (*stepsOption_) options_.steps = steps_;
    if (*framesOption_) options_.frames = frames_;
    options_.everyGiven = static_cast<bool>(*everyOption_);
    options_.sizeGiven = static_cast<bool>(*sizeOption_);
    options_.size = *parseFrameSize(size_); // the validator has accepted it, or it is the default
    if (*videoOption_) {
        const std::string why = render::videoSizeProblem(*render::videoFormatOf(options_.video), options_.size);
        if (!why.empty()) return usageError("--video " + options_.video + ": " + why, "rube run --help");
    }
    options_.progress = ::isatty(STDERR_FILENO) == 1;
    return runScene(options_, std::cout, std::cerr);
}

} // namespace

std::unique_ptr<Subcommand> addRunCommand(CLI::App& app) { return std::make_unique<RunCommand>(app); }

} // namespace rube::game::cli
