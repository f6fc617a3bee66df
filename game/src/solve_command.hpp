#pragma once
/// `rube solve LEVEL`: search what the player can do in a level, report the solutions, the
/// shortcuts, the solve fraction and the most robust solution; write JSON and solution scripts.

#include "exit_codes.hpp"
#include "solve_search.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace rube::game {

/// What `rube solve` was asked to do.
struct SolveCommandOptions {
    std::string level;              ///< the level file
    SolveOptions search;            ///< the space, budget, seed, jobs and slice
    std::string json;               ///< --json FILE, empty for none
    std::string scripts;            ///< --scripts DIR: every solution as DIR/LEVEL-NUMBER.solution.toml
    std::vector<std::string> merge; ///< --merge: slices' JSON to join instead of searching
    bool progress = false;          ///< a progress line on `err` (only when it is a terminal)
};

/// Runs `rube solve`: ok when a solution was found, failed when none was (or a file could not be
/// written), badInput for a bad level, option or slice file.
ExitCode solveCommand(const SolveCommandOptions& options, std::ostream& out, std::ostream& err);

} // namespace rube::game
