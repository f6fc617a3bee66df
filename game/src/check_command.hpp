#pragma once
/// `rube check`: validate scene files without running them.

#include "exit_codes.hpp"

#include <iosfwd>
#include <span>
#include <string>

namespace rube::game {

/// Prints `FILE: ok` to `out` for each good file and every error of a bad one to `err`, one
/// line each as `file:line:col: message`; returns ok when every file is good, else badInput.
ExitCode checkScenes(std::span<const std::string> files, std::ostream& out, std::ostream& err);

} // namespace rube::game
