#pragma once
/// `rube play LEVEL`: the level in a GLFW window, played by hand with the mouse and keys; what the
/// player does can be recorded as a script that `rube run` replays off-screen to the same frames.

#include "exit_codes.hpp"

#include "rube/render/camera.hpp"

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>

namespace rube::game {

/// What `rube play` was asked to do.
struct PlayOptions {
    std::string level;                       ///< the level file; empty: the list of the index's levels
    std::string index = "levels/index.toml"; ///< --index: the levels' order, for the list and N
    std::string script;                    ///< --script: start from its placements and aims
    std::string record;                    ///< --record: write the session as a script here when it ends
    render::FrameSize size{1280, 720};     ///< --size of the level area (the bar adds its height)
    bool runAtOnce = false;                ///< --run: start the machine without waiting for Space
    std::optional<std::int64_t> quitAfter; ///< --quit-after N: close when the machine has taken N steps
    int stepsPerFrame = 0;                 ///< --steps-per-frame K: fixed pace; 0 follows real time
    bool vsync = true;                     ///< false with --no-vsync: draw as fast as possible
};

/// True when there is a display to open a window on (DISPLAY or WAYLAND_DISPLAY is set).
bool hasDisplay();

/// Plays a level in a window, or with no level the list of the index's levels, until it is closed
/// (or Escape, or --quit-after), then writes the recording of the last level played and prints a
/// summary of each. A level solved is kept in the progress file (progress.hpp). Returns ok when
/// done, failed when the last run ended without its goal, no window could be opened (the message
/// names the ways on without a display) or the recording not written, badInput for the level, the
/// index, the script or the record path.
ExitCode playInWindow(const PlayOptions& options, std::ostream& out, std::ostream& err);

} // namespace rube::game
