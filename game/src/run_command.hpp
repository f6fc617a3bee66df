#pragma once
/// `rube run`: simulate a scene headless, print a summary, optionally write the trace.

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>

namespace rube::game {

/// What `rube run` was asked to do.
struct RunOptions {
    std::string scene;                ///< the scene file
    bool noRender = false;            ///< --no-render: headless on purpose (the only mode until a renderer exists)
    std::optional<std::int64_t> steps; ///< --steps, else the scene's duration, else 600
    std::string trace;                ///< --trace file, empty for none
    std::string method;               ///< --method, empty for the scene's own
};

/// Runs a scene and returns the exit status: 0 done, 1 the run failed (the trace could not be
/// written, or it was interrupted), 2 bad input (unreadable scene, unknown method, trace not creatable).
int runScene(const RunOptions& options, std::ostream& out, std::ostream& err);

} // namespace rube::game
