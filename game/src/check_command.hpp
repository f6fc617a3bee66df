#pragma once
/// `rube check`: validate scene, level and script files without running them, and lint levels.

#include "exit_codes.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace rube::game {

/// What `rube check` was asked to do.
struct CheckOptions {
    std::vector<std::string> files; ///< scenes, levels and solution scripts, in any mix
    std::string level;              ///< --level: the level every script given is checked against
    bool strict = false;            ///< --strict: a warning fails the check as an error does
};

/// True when `text`, read from `file`, is a solution script rather than a scene: it is named
/// NAME.solution.toml, NAME.solution.WORD.toml or NAME.wrong.WORD.toml (level_folder.hpp), or its top level holds a key only scripts have (level, steps, [capture],
/// [[place]], [[action]], [[expect]]).
bool looksLikeScript(const std::string& file, const std::string& text);

/// Prints `FILE: ok` (or `FILE: ok, N warnings`) to `out` for each good file and every error and
/// warning to `err`, one line each as `file:line:col: message` (warnings as `file:line:col: warning:
/// message`). A script is checked against its level: --level, else NAME.toml beside the script.
/// Returns ok when every file is good (and, with strict, has no warning), else badInput.
ExitCode checkFiles(const CheckOptions& options, std::ostream& out, std::ostream& err);

} // namespace rube::game
