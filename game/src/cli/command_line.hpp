#pragma once
/// The `rube` command line: what every subcommand's options share (the usage error's one line, the
/// validators of counts, frame sizes, videos and GL back ends) and the subcommands themselves, one
/// file each (run_cli.cpp, play_cli.cpp, ...), which main.cpp makes and hands the parsed line to.

#include "exit_codes.hpp"

#include "rube/render/camera.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <optional>
#include <string>

namespace rube::game::cli {

/// Prints `rube: MESSAGE (see 'HELP')` on stderr and returns badInput: a usage error is one line,
/// pointing at the help that explains the option.
ExitCode usageError(const std::string& message, const std::string& help);

/// `text` with its line breaks made spaces (CLI11's messages are one line; a future one may not be).
std::string oneLine(std::string text);

/// "" when `text` is a whole number of steps from 0 to a billion, else why not (for --steps).
std::string stepCount(const std::string& text);

/// A validator of a whole number from 1 to a billion (--every, --frames); `what` names the unit.
CLI::Validator countFromOne(std::string what);

/// "WxH" with both sides from 1 to kMaxFrameSide; nothing when `text` is not that.
std::optional<render::FrameSize> parseFrameSize(const std::string& text);

/// "" when `text` is a frame size parseFrameSize() reads, else why not.
std::string frameSizeError(const std::string& text);

/// "" when `text` names a video file rube can write (.mp4, .webm, .gif), else why not.
std::string videoFileError(const std::string& text);

/// "" when `text` names an offscreen GL back end (auto, egl, osmesa), else why not.
std::string glBackendError(const std::string& text);

/// One subcommand: its options, added to the app when it is made, and what it does once chosen.
/// CLI11 keeps pointers to the fields it fills, so a command is made in place and never copied.
class Subcommand {
public:
    Subcommand() = default;
    Subcommand(const Subcommand&) = delete;
    Subcommand& operator=(const Subcommand&) = delete;
    virtual ~Subcommand() = default;
    /// True when the command line chose this subcommand.
    virtual bool chosen() const = 0;
    /// Runs it with the options parsed, after the checks between them that CLI11 is not told of.
    virtual ExitCode run() = 0;
};

/// `rube run SCENE` (run_cli.cpp).
std::unique_ptr<Subcommand> addRunCommand(CLI::App& app);
/// `rube check FILE...` (check_cli.cpp).
std::unique_ptr<Subcommand> addCheckCommand(CLI::App& app);
/// `rube play [LEVEL]` (play_cli.cpp).
std::unique_ptr<Subcommand> addPlayCommand(CLI::App& app);
/// `rube edit [LEVEL]` (edit_cli.cpp).
std::unique_ptr<Subcommand> addEditCommand(CLI::App& app);
/// `rube items [--sheet DIR]` (items_cli.cpp).
std::unique_ptr<Subcommand> addItemsCommand(CLI::App& app);
/// `rube solve LEVEL` (solve_cli.cpp).
std::unique_ptr<Subcommand> addSolveCommand(CLI::App& app);

} // namespace rube::game::cli
