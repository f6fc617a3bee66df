// `rube check FILE...`: the files, the level scripts are checked against, and --strict.
#include "command_line.hpp"

#include "check_command.hpp"

#include <iostream>

namespace rube::game::cli {

namespace {

constexpr const char* kCheckFooter =
    "Every error is one line, file:line:col: message, so editors can jump to it. Unknown keys are\n"
    "errors (a typo must not silently become a default) and come with the closest known key.\n"
    "Scripts: a file named NAME.solution.toml (the intended solution), NAME.solution.WORD.toml (another)\n"
    "  or NAME.wrong.WORD.toml (a wrong attempt the level tests require to fail), or holding level, steps,\n"
    "  [capture], [[place]], [[action]] or [[expect]], is a script. It is checked against its level (--level\n"
    "  LEVEL, else NAME.toml beside it): every placement allowed, every item an action or\n"
    "  expectation names exists and is of the right kind, actions in step order. An old key gets\n"
    "  its new name: 'frame' is now 'step', 'before_frame' is now 'before_step'.\n"
    "Levels are also linted, as 'file:line:col: warning: message': no [goal]; a zone, or a\n"
    "  reach-area goal's area, outside the [view] or the world's bounds; an inventory without a\n"
    "  zone or zones without an inventory;\n"
    "  fixed items overlapping; and, run headless, a goal reached with nothing placed, or a\n"
    "  NAME.solution.toml beside the level that does not reach the goal.\n"
    "Exit status: 0 when every file is ok (warnings allowed unless --strict), 2 otherwise.";

// `rube check FILE...`: the files, the level scripts are checked against, and --strict.
class CheckCommand final : public Subcommand {
public:
    explicit CheckCommand(CLI::App& app);
    bool chosen() const override { return static_cast<bool>(*command_); }
    ExitCode run() override { return checkFiles(options_, std::cout, std::cerr); }

private:
    CLI::App* command_ = nullptr;
    CheckOptions options_;
};

CheckCommand::CheckCommand(CLI::App& app) {
    command_ = app.add_subcommand(
        "check", "Validate scene, level and script files and lint levels; every error as file:line:col: message");
    command_->footer(kCheckFooter);
    command_->add_option("files", options_.files, "Scene, level and script files (.toml) to validate")
        ->required()
        ->type_name("FILE");
    command_
        ->add_option("--level", options_.level,
                     "The level the scripts given are checked against (default: NAME.toml beside NAME.*.toml)")
        ->type_name("LEVEL");
    command_->add_flag("--strict", options_.strict, "Treat warnings as errors (exit 2); CI checks levels/ with it");
}

} // namespace

std::unique_ptr<Subcommand> addCheckCommand(CLI::App& app) { return std::make_unique<CheckCommand>(app); }

} // namespace rube::game::cli
