#pragma once
/// `rube edit [LEVEL]`: a level made (none given) or changed in a window; see edit_session.hpp.

#include "exit_codes.hpp"

#include "rube/render/camera.hpp"

#include <iosfwd>
#include <string>

namespace rube::game {

/// What `rube edit` was asked to do.
struct EditOptions {
    std::string level;                 ///< the level to change; empty: a new one
    std::string out;                   ///< --out: where Ctrl+S saves (default: LEVEL, else new-level.toml)
    render::FrameSize size{1280, 720}; ///< --size of the level area
};

/// Edits in a window until Escape or the window closes. Returns ok, failed when no window could be
/// opened, badInput for the level, its solution script or the --out path.
ExitCode editInWindow(const EditOptions& options, std::ostream& out, std::ostream& err);

} // namespace rube::game
