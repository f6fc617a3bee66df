#pragma once
/// `rube run`: simulate a scene, print a summary, optionally write the trace and PNG frames.

#include "exit_codes.hpp"

#include "rube/render/camera.hpp"
#include "rube/render/render_context.hpp"

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>

namespace rube {
class World;
}

namespace rube::game {

/// The method's name for a summary; for auto, also how its steps were shared:
/// "auto (exact 590 steps, solver 10; body-steps exact 1180, solver 20, exact share 98.3 %)".
std::string methodDescription(const World& world);

/// Why the run's physics cannot be trusted (a state went NaN or infinite, a body was isolated), as
/// one line after "rube run: ", or "" when every state stayed finite (issue 27: such a run exits 1).
std::string unstableStateMessage(const World& world);

/// What `rube run` was asked to do.
struct RunOptions {
    std::string scene;       ///< the scene file
    std::string script;      ///< --script: a level's scripted playthrough, empty for none
    bool everyGiven = false; ///< --every was given (it then overrides a script's capture)
    bool sizeGiven = false;  ///< --size was given (it then overrides a script's capture)
    bool noRender = false;   ///< --no-render: headless on purpose, no GL context at all
    std::optional<std::int64_t>
        steps;          ///< --steps, else (frames - 1) x every with --frames, else the scene's duration, else 600
    std::string trace;  ///< --trace file, empty for none
    std::string method; ///< --method, empty for the scene's own
    std::string out;    ///< --out folder for frame_00000.png, ...; empty for no frames
    std::string video;  ///< --video FILE (.mp4, .webm, .gif) through ffmpeg; empty for none
    render::GlBackend gl = render::GlBackend::automatic; ///< --gl: the offscreen back end that draws the frames
    std::int64_t every = 1;                              ///< --every: steps between frames
    std::optional<std::int64_t> frames;                  ///< --frames: how many frames at most, frame 0 included
    render::FrameSize size{1280, 720};                   ///< --size, pixels
    bool trails = false;                                 ///< --trails: each dynamic body's recent path
    bool debugImpacts = false;                           ///< --debug-impacts: points of impact and collision normals
    bool labels = false;                                 ///< --labels: levels' item names beside the items
    bool zones = false;                                  ///< --zones: levels' placement zones
    bool progress = false;                               ///< show a progress line on `err` (only when it is a terminal)
};

/// Whether the run draws frames at all (--out or --video).
inline bool drawsFrames(const RunOptions& options) { return !options.out.empty() || !options.video.empty(); }

/// The largest frame side --size accepts, in pixels: 8192 x 8192 RGBA is already 256 MB.
inline constexpr int kMaxFrameSide = 8192;

/// Runs a scene and returns the exit status: ok, failed (the trace or a frame could not be written,
/// no GL context, a state went non-finite, or it was interrupted), badInput (unreadable scene,
/// unknown method, trace or frame folder not creatable).
ExitCode runScene(const RunOptions& options, std::ostream& out, std::ostream& err);

} // namespace rube::game
