// The `rube` command: each subcommand (cli/*_cli.cpp) sets up its options and runs; main() only
// parses the command line and hands over to the subcommand chosen.
#include "command_line.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <utility>

namespace {

using rube::game::ExitCode;
using namespace rube::game::cli;

constexpr const char* kMainFooter =
    "Scene files are TOML: see levels/physics/ for examples and game/scene-format.md for every key.\n"
    "Run 'rube run --help', 'rube play --help', 'rube edit --help', 'rube check --help', 'rube items\n"
    "  --help' or 'rube solve --help' for a command's options.\n"
    "Exit status: 0 ok, 1 a run failed, 2 bad input or usage (every message is one line on stderr).";

// Parses the command line into the commands' fields. Returns the status to exit with when there
// is nothing to run (--help, --version, a usage error), nothing when a command is to run.
std::optional<ExitCode> parseCommandLine(CLI::App& app, int argc, char** argv) {
    // CLI11 would call a misspelt command a missing one ("A subcommand is required").
    if (argc > 1 && argv[1][0] != '-') {
        const auto commands = std::as_const(app).get_subcommands([](const CLI::App*) { return true; });
        if (std::none_of(commands.begin(), commands.end(), [&](const CLI::App* c) { return c->check_name(argv[1]); })) {
            std::cerr << "rube: unknown command '" << argv[1]
                      << "': the commands are run, play, edit, check, items and solve (see 'rube --help')\n";
            return ExitCode::badInput;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help and --version come here too, with CLI11's exit code 0: let CLI11 print them.
        if (e.get_exit_code() == 0) {
            app.exit(e);
            return ExitCode::ok;
        }
        // CLI11's own codes for parse errors (105, 106, ...) are all bad usage here. Point at the
        // help of the command that was being parsed, where the options are explained.
        const auto chosen = app.get_subcommands();
        const std::string help = chosen.empty() ? "rube --help" : "rube " + chosen.front()->get_name() + " --help";
        return usageError(oneLine(e.what()), help);
    }
    return std::nullopt;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"rube: a greybox physics puzzle game of the Incredible Machine kind.\n"
                 "Runs physics scenes, renders them to PNG frames, plays levels in a window and checks scene files.",
                 "rube"};
    app.footer(kMainFooter);
    app.set_version_flag("--version", "rube " RUBE_VERSION);
    app.require_subcommand(1);
    app.get_formatter()->column_width(26);
    // In the order `rube --help` lists them.
    std::unique_ptr<Subcommand> commands[] = {addRunCommand(app),  addCheckCommand(app), addPlayCommand(app),
                                              addEditCommand(app), addItemsCommand(app), addSolveCommand(app)};

    if (const std::optional<ExitCode> done = parseCommandLine(app, argc, argv)) return rube::game::exitStatus(*done);
    for (const std::unique_ptr<Subcommand>& command : commands)
        if (command->chosen()) return rube::game::exitStatus(command->run());
    return rube::game::exitStatus(ExitCode::badInput); // require_subcommand(1): not reached
}
