// The `rube` command: parses the command line and hands over to `run` or `check`.
#include "check_command.hpp"
#include "run_command.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <iostream>

namespace {

// Exit status for bad input or usage; CLI11's own parse-error codes (105, 106, ...) are mapped to it.
constexpr int kBadInput = 2;

constexpr const char* kRunFooter =
    "Prints: scene, method, steps, simulated time, wall time of the physics alone, impacts,\n"
    "  resting contacts, caps hit (steps that reached max_events_per_step), escapes (bodies that\n"
    "  left the bounds) and the state hash: equal hashes mean bit-identical final states.\n"
    "Steps: --steps N, else the scene's [world] duration / time_step rounded up, else 600.\n"
    "Methods: discrete (fixed step, pushes overlaps apart; tunnels when speed x dt > 2r),\n"
    "  turn-based (bodies move one by one until their first impact; order matters),\n"
    "  exact (earliest time of impact over all pairs, one at a time),\n"
    "  solver (substepped contact solver, for piles and resting contact).\n"
    "Trace: CSV with the header step,time,body,x,y,vx,vy,angle,omega,radius; one row per\n"
    "  dynamic circle per step. Step 0 is the initial state, so N steps give N + 1 rows per\n"
    "  body. body is the circle's index: [[circle]]s in file order, then [[circle_grid]]s row\n"
    "  by row from the bottom. Numbers are printed with %.17g, so traces compare byte for byte.\n"
    "  angle and omega are 0 until bodies rotate. The trace is written to a temporary file and\n"
    "  renamed at the end: a failed or interrupted run leaves no trace file.\n"
    "A bad scene is reported by its first error only; 'rube check' lists them all.\n"
    "Rendering is not built yet: without --no-render the run is headless anyway, with a note.\n"
    "Exit status: 0 done, 1 the run failed (trace not written, interrupted), 2 bad input.";

constexpr const char* kCheckFooter =
    "Every error is one line, file:line:col: message, so editors can jump to it. Unknown keys are\n"
    "errors (a typo must not silently become a default) and come with the closest known key.\n"
    "Exit status: 0 when every file is ok, 2 otherwise.";

constexpr const char* kMainFooter =
    "Scene files are TOML: see levels/physics/ for examples and game/scene-format.md for every key.\n"
    "Run 'rube run --help' or 'rube check --help' for a command's options.\n"
    "Exit status: 0 ok, 1 a run failed, 2 bad input or usage (every message is one line on stderr).";

// CLI11 messages are one line already; this keeps them so if a future version adds a line break.
std::string oneLine(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    return text;
}

// CLI11's own range check prints the largest double in full; this says what a step count is.
std::string stepCount(const std::string& text) {
    std::int64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || value < 0)
        return "expected a whole number of steps, 0 or more, got '" + text + "'";
    return {};
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"rube: a greybox physics puzzle game of the Incredible Machine kind.\n"
                 "Runs physics scenes headless and checks scene files.",
                 "rube"};
    app.footer(kMainFooter);
    app.set_version_flag("--version", "rube " RUBE_VERSION);
    app.require_subcommand(1);
    app.get_formatter()->column_width(26);

    rube::game::RunOptions run;
    std::int64_t steps = 0;
    CLI::App* runCommand = app.add_subcommand("run", "Simulate a scene and print a summary; optionally write a CSV trace");
    runCommand->footer(kRunFooter);
    runCommand->add_option("scene", run.scene, "The scene file (.toml) to simulate")->required()->type_name("SCENE");
    runCommand->add_flag("--no-render", run.noRender, "Run headless, without a window (the only mode for now)");
    CLI::Option* stepsOption = runCommand->add_option("--steps", steps, "Number of time steps to simulate (0 or more)")
                                   ->type_name("N")
                                   ->check(CLI::Validator(stepCount, ""));
    runCommand->add_option("--trace", run.trace, "Write every dynamic body's state at every step to this CSV file")
        ->type_name("FILE");
    runCommand->add_option("--method", run.method,
                           "Time-step method, overriding the scene's: discrete, turn-based, exact or solver")
        ->type_name("NAME");

    std::vector<std::string> files;
    CLI::App* checkCommand = app.add_subcommand("check", "Validate scene files and report every error as file:line:col: message");
    checkCommand->footer(kCheckFooter);
    checkCommand->add_option("files", files, "Scene files (.toml) to validate")->required()->type_name("FILE");

    // CLI11 would call a misspelt command a missing one ("A subcommand is required").
    if (argc > 1 && argv[1][0] != '-' && !runCommand->check_name(argv[1]) && !checkCommand->check_name(argv[1])) {
        std::cerr << "rube: unknown command '" << argv[1] << "': the commands are run and check (see 'rube --help')\n";
        return kBadInput;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help and --version come here too, with exit code 0: let CLI11 print them.
        if (e.get_exit_code() == 0) return app.exit(e);
        // Point at the help of the command that was being parsed, where the options are explained.
        const auto chosen = app.get_subcommands();
        const std::string help = chosen.empty() ? "rube --help" : "rube " + chosen.front()->get_name() + " --help";
        std::cerr << "rube: " << oneLine(e.what()) << " (see '" << help << "')\n";
        return kBadInput;
    }

    if (*runCommand) {
        if (*stepsOption) run.steps = steps;
        return rube::game::runScene(run, std::cout, std::cerr);
    }
    return rube::game::checkScenes(files, std::cout, std::cerr);
}
