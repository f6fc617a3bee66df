// `rube solve`: load the level and its intended script, search or merge, report, write.
#include "solve_command.hpp"

#include "scene_errors.hpp"
#include "scene_file.hpp"
#include "solve_report.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <ostream>

namespace rube::game {

namespace {

// The level's NAME.solution.toml beside it, if it has one that reads: what the designer meant.
std::optional<PartsUsed> intendedSolution(const std::filesystem::path& levelFile, const SceneDesc& level) {
    std::filesystem::path script = levelFile;
    script.replace_extension(".solution.toml");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(script, ec)) return std::nullopt;
    const ScriptLoad load = loadScriptFile(script, level);
    if (!load.script) return std::nullopt;
    return partsUsed(*load.script);
}

void showProgress(std::ostream& err, std::uint64_t done, std::uint64_t total, std::uint64_t solved, double seconds) {
    const double rate = seconds > 0 ? static_cast<double>(done) / seconds : 0.0;
    const double left = rate > 0 ? static_cast<double>(total - done) / rate : 0.0;
    char text[160];
    std::snprintf(text, sizeof text, "\r%llu of %llu candidates, %llu solutions, %.0f runs/s, %.0f s left   ",
                  static_cast<unsigned long long>(done), static_cast<unsigned long long>(total),
                  static_cast<unsigned long long>(solved), rate, left);
    err << text << std::flush;
}

ExitCode writeScripts(const std::string& folder, const SearchSpace& space, const SearchResult& result,
                      std::ostream& err) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) {
        err << "rube solve: cannot create " << folder << ": " << ec.message() << '\n';
        return ExitCode::failed;
    }
    for (const FoundSolution& s : result.solutions) {
        const std::string header = "# Found by rube solve: candidate #" + std::to_string(s.number) +
                                   " of a search with budget " + std::to_string(result.budget) + " and seed " +
                                   std::to_string(result.seed) + "; the goal is reached at step " +
                                   std::to_string(s.goalStep) + ".\n";
        const std::filesystem::path file = std::filesystem::path(folder) /
                                           (result.level + "-" + std::to_string(s.number) + ".solution.toml");
        std::string reason;
        if (!writeTextFileAtomically(file, writeScript(solutionScript(space, result, s), header), reason)) {
            err << "rube solve: cannot write " << file.string() << ": " << reason << '\n';
            return ExitCode::failed;
        }
    }
    return ExitCode::ok;
}

} // namespace

ExitCode solveCommand(const SolveCommandOptions& options, std::ostream& out, std::ostream& err) {
    const SceneLoad load = loadSceneFile(options.level);
    if (!load.ok()) {
        err << load.errors.front().format() << '\n';
        return ExitCode::badInput;
    }
    const SceneDesc& level = *load.scene;
    if (!level.level.goal) {
        err << "rube solve: " << options.level << " has no [goal]: there is nothing to solve\n";
        return ExitCode::badInput;
    }
    // A --json the search could not write is refused before the search, not after it.
    if (!options.json.empty()) {
        const std::filesystem::path parent = std::filesystem::absolute(options.json).parent_path();
        std::error_code ec;
        if (!std::filesystem::is_directory(parent, ec)) {
            err << "rube solve: --json " << options.json << ": no folder " << parent.string() << '\n';
            return ExitCode::badInput;
        }
    }
    const SearchSpace space(level, options.search.space);
    const auto start = std::chrono::steady_clock::now();
    SearchResult result;
    if (!options.merge.empty()) {
        std::vector<SearchResult> slices;
        for (const std::string& file : options.merge) {
            SceneError error;
            const std::optional<std::string> text = readTextFile(file, error);
            if (!text) {
                err << error.format() << '\n';
                return ExitCode::badInput;
            }
            std::string why;
            std::optional<SearchResult> slice = readResultJson(*text, why);
            if (!slice) {
                // A syntax error comes with its line:col, a result missing its fields without.
                const bool placed = !why.empty() && why.front() >= '0' && why.front() <= '9';
                err << file << (placed ? ":" : ": ") << why << '\n';
                return ExitCode::badInput;
            }
            if (slice->level != level.name || slice->space != space.size()) {
                err << "rube solve: " << file << " is a search of '" << slice->level << "' in a space of "
                    << slice->space << " candidates, not of " << options.level << " with these options ("
                    << space.size() << ")\n";
                return ExitCode::badInput;
            }
            slices.push_back(std::move(*slice));
        }
        std::string why;
        std::optional<SearchResult> merged = mergeResults(std::move(slices), why);
        if (!merged) {
            err << "rube solve: --merge: " << why << '\n';
            return ExitCode::badInput;
        }
        result = std::move(*merged);
    } else {
        SearchProgress progress;
        if (options.progress)
            progress = [&err](std::uint64_t done, std::uint64_t total, std::uint64_t solved, double seconds) {
                showProgress(err, done, total, solved, seconds);
            };
        result = searchLevel(level, space, options.search, progress);
        if (options.progress) err << "\r\033[K" << std::flush;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const SolveReport report = makeReport(result, space, intendedSolution(options.level, level));
    out << reportText(report, space);
    if (options.merge.empty()) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "%llu headless runs (neighbours included; refused candidates make none) in %.3g s: %.0f runs/s "
                      "on %d %s\n",
                      static_cast<unsigned long long>(result.runs), seconds,
                      seconds > 0 ? static_cast<double>(result.runs) / seconds : 0.0, options.search.jobs,
                      options.search.jobs == 1 ? "thread" : "threads");
        out << "runs:             " << text;
    }
    if (!options.json.empty()) {
        std::string reason;
        if (!writeTextFileAtomically(options.json, reportJson(report, space), reason)) {
            err << "rube solve: cannot write " << options.json << ": " << reason << '\n';
            return ExitCode::failed;
        }
    }
    if (!options.scripts.empty())
        if (const ExitCode status = writeScripts(options.scripts, space, result, err); status != ExitCode::ok)
            return status;
    return result.solutions.empty() ? ExitCode::failed : ExitCode::ok;
}

} // namespace rube::game
