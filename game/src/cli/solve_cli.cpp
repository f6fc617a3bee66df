// `rube solve LEVEL`: the search's options.
#include "command_line.hpp"

#include "solve_command.hpp"

#include <charconv>
#include <cstdint>
#include <iostream>
#include <string>

#include <unistd.h>

namespace rube::game::cli {

namespace {

constexpr const char* kSolveFooter =
    "The space: for each inventory part, its centre on a grid in every placement zone (a step of a\n"
    "  quarter of the part's size, or --step), its angle every --angle-step degrees if it turns (a\n"
    "  board over half a turn, a fan or rocket over a whole one); every subset of the inventory up\n"
    "  to its counts, none included; for each fixed part a click acts on (that the level's clicks\n"
    "  allow), the step it is clicked at\n"
    "  (never, or every --action-every seconds up to the time limit) and, for a cannon, its aim (as\n"
    "  the level has it, every --aim-step degrees, or at each target on the low or high arc).\n"
    "Each candidate is checked by the placement rules of the window and of scripts, then run headless\n"
    "  as 'rube run --script' runs it, to the goal's time limit, stopping at the goal or once nothing\n"
    "  has moved for 1 s with no click, timer, path or thruster still to come.\n"
    "Search: every candidate when the space holds at most --budget. Else each subset of the inventory\n"
    "  gets an equal share of the budget (one smaller than its share is searched whole, and leaves\n"
    "  the rest to the others), and a larger one that many candidates drawn at random from --seed:\n"
    "  the same level, options, budget and seed give the same result and byte-identical --json.\n"
    "Report: the solutions grouped by the parts and clicks they use; a group is a shortcut when it\n"
    "  uses fewer parts than the level's NAME.solution.toml, or parts or clicks it does not; the\n"
    "  solve fraction (solutions over candidates the rules allow, a sampled subset weighted by its\n"
    "  size); the most robust solution, whose\n"
    "  grid neighbours (one step on one axis) most often solve too. --scripts DIR writes every\n"
    "  solution as DIR/LEVEL-NUMBER.solution.toml, which 'rube run LEVEL --script' replays to the\n"
    "  same goal step.\n"
    "Parallel: --jobs N runs N threads, with the same result as one. --shard I/N searches the\n"
    "  candidates whose number is I modulo N; 'rube solve LEVEL --merge A.json B.json ...' (with the\n"
    "  same space options) joins the slices' --json into what one run gives.\n"
    "Progress (candidates, solutions, rate, time left) is shown on stderr only when it is a terminal.\n"
    "Exit status: 0 a solution was found, 1 none was (or a file could not be written), 2 bad input.";

// `rube solve LEVEL`: the search's options.
class SolveCommand final : public Subcommand {
public:
    explicit SolveCommand(CLI::App& app);
    bool chosen() const override { return static_cast<bool>(*command_); }
    ExitCode run() override;

private:
    CLI::App* command_ = nullptr;
    SolveCommandOptions options_;
    std::string shard_;
    double step_ = 0.0;
    CLI::Option* stepOption_ = nullptr;
    CLI::Option* shardOption_ = nullptr;
};

// "I/N" with 0 <= I < N; "" when it is, else why not.
std::string shardError(const std::string& text) {
    const auto slash = text.find('/');
    int index = -1, count = 0;
    if (slash != std::string::npos) {
        const auto [a, ea] = std::from_chars(text.data(), text.data() + slash, index);
        const auto [b, eb] = std::from_chars(text.data() + slash + 1, text.data() + text.size(), count);
        if (ea == std::errc{} && a == text.data() + slash && eb == std::errc{} && b == text.data() + text.size() &&
            count >= 1 && count <= 1'000'000 && index >= 0 && index < count)
            return {};
    }
    return "expected I/N with 0 <= I < N (the I-th of N slices, counted from 0), got '" + text + "'";
}

SolveCommand::SolveCommand(CLI::App& app) {
    command_ = app.add_subcommand(
        "solve", "Search a level's placements and clicks: solutions, shortcuts, solve fraction, most robust");
    command_->footer(kSolveFooter);
    command_->add_option("level", options_.level, "The level file (.toml) to search")->required()->type_name("LEVEL");
    command_
        ->add_option("--budget", options_.search.budget,
                     "Runs: the whole space if it is no larger, else this many, shared equally among the inventory "
                     "subsets (default 2000)")
        ->type_name("RUNS")
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1'000'000'000}));
    command_->add_option("--seed", options_.search.seed, "Seed of the random search (default 1)")->type_name("N");
    command_->add_option("--jobs", options_.search.jobs, "Threads (default 1); the result is the same on any number")
        ->type_name("N")
        ->check(CLI::Range(1, 256));
    shardOption_ = command_->add_option("--shard", shard_, "Search only slice I of N (candidates numbered I mod N)")
                       ->type_name("I/N")
                       ->check(CLI::Validator(shardError, ""));
    command_->add_option("--merge", options_.merge, "Join these slices' --json results instead of searching")
        ->type_name("FILE")
        ->expected(1, -1);
    command_->add_option("--json", options_.json, "Write the result as JSON to FILE")->type_name("FILE");
    command_->add_option("--scripts", options_.scripts, "Write every solution as DIR/LEVEL-NUMBER.solution.toml")
        ->type_name("DIR");
    stepOption_ = command_
                      ->add_option("--step", step_,
                                   "Grid step in the zones, m (default: a quarter of each part's size)")
                      ->type_name("M")
                      ->check(CLI::Range(1e-3, 100.0));
    command_
        ->add_option("--angle-step", options_.search.space.angleStep,
                     "Degrees between a turning part's angles (default 15)")
        ->type_name("DEG")
        ->check(CLI::Range(0.1, 180.0));
    command_->add_option("--aim-step", options_.search.space.aimStep, "Degrees between a cannon's aims (default 5)")
        ->type_name("DEG")
        ->check(CLI::Range(0.1, 180.0));
    command_
        ->add_option("--action-every", options_.search.space.actionEvery,
                     "Seconds between the steps a click is tried at (default 0.5)")
        ->type_name("S")
        ->check(CLI::Range(1e-3, 1000.0));
}

ExitCode SolveCommand::run() {
    if (*shardOption_) {
        if (!options_.merge.empty()) return usageError("--shard excludes --merge", "rube solve --help");
        const auto slash = shard_.find('/');
        options_.search.shardIndex = std::stoi(shard_.substr(0, slash));
        options_.search.shardCount = std::stoi(shard_.substr(slash + 1));
    }
    if (*stepOption_) options_.search.space.step = step_;
    // A merge takes the budget and seed from the slices and runs nothing: these would be ignored.
    for (const char* name : {"--budget", "--seed", "--jobs"})
        if (!options_.merge.empty() && command_->count(name) > 0)
            return usageError(std::string("--merge excludes ") + name + " (the slices hold the search's own)",
                              "rube solve --help");
    options_.progress = ::isatty(STDERR_FILENO) == 1;
    return solveCommand(options_, std::cout, std::cerr);
}

} // namespace

std::unique_ptr<Subcommand> addSolveCommand(CLI::App& app) { return std::make_unique<SolveCommand>(app); }

} // namespace rube::game::cli
