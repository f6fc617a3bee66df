#pragma once
/// `rube run LEVEL [--script FILE]`: plays a level, with a script's placements and actions or as
/// it stands, renders the frames and writes DIR/summary.json of what happened.

#include "run_command.hpp"
#include "scene.hpp"

#include <iosfwd>

namespace rube::game {

/// Plays `level` as `options` say (options.script may be empty) and returns the exit status:
/// ok when the goal was reached and every expectation met, failed when it was not or one failed
/// (each is named on `err`), badInput for the script, a placement or the output folder.
ExitCode playLevel(const RunOptions& options, const SceneDesc& level, std::ostream& out, std::ostream& err);

} // namespace rube::game
