#pragma once
/// `rube check`: validate scene files without running them.

#include <iosfwd>
#include <span>
#include <string>

namespace rube::game {

/// Prints `FILE: ok` to `out` for each good file and every error of a bad one to `err`, one
/// line each as `file:line:col: message`; returns 0 when every file is good, else 2.
int checkScenes(std::span<const std::string> files, std::ostream& out, std::ostream& err);

} // namespace rube::game
