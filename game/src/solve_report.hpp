#pragma once
/// What `rube solve` reports: the solutions grouped by the parts and clicks they use, the shortcuts
/// (a group using fewer parts than the level's intended script, or parts or clicks it does not),
/// the solve fraction, the most robust solution; as text and as JSON, and read back for --merge.

#include "solve_search.hpp"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rube::game {

/// What a script uses: its placed parts by kind, and the fixed parts it acts on ("fire gun").
struct PartsUsed {
    std::map<std::string, int> parts; ///< kind name -> how many
    std::set<std::string> acts;       ///< "aim gun", "fire gun", "detonate tnt", "toggle button"
    /// "ramp", "heavy x2 + ramp; aim gun, fire gun", or "nothing".
    std::string label() const;
    int partCount() const;
};

/// What `script` uses.
PartsUsed partsUsed(const ScriptDesc& script);

/// Why a solution using `used` is a shortcut of the intended `intended`, or "" when it is not.
std::string shortcutReason(const PartsUsed& used, const PartsUsed& intended);

/// The solutions that use the same parts and clicks.
struct SolutionGroup {
    std::string uses; ///< PartsUsed::label()
    std::size_t solutions = 0;
    std::uint64_t first = 0; ///< the number of its first solution
    std::string shortcut;    ///< why it is a shortcut, or ""
};

/// A search's result read as a report.
struct SolveReport {
    SearchResult result;
    std::optional<PartsUsed> intended;     ///< the level's NAME.solution.toml, when it has one
    std::vector<std::string> uses;         ///< each solution's label, in the order of result.solutions
    std::vector<SolutionGroup> groups;     ///< by label
    std::optional<std::size_t> mostRobust; ///< index into result.solutions
    double solveFraction = 0.0;            ///< SearchResult::solveFraction()
    bool exhaustive = false;               ///< every candidate of the space was run
    std::size_t shortcuts() const;
};

/// Groups, shortcuts and the most robust solution of `result`: the one with the largest share of
/// grid neighbours that also solve; ties go to fewer parts, then to the lower number.
SolveReport makeReport(const SearchResult& result, const SearchSpace& space, const std::optional<PartsUsed>& intended);

/// The report as JSON: the same for the same level, space, budget, seed and slice, byte for byte.
std::string reportJson(const SolveReport& report, const SearchSpace& space);

/// The report as the lines `rube solve` prints.
std::string reportText(const SolveReport& report, const SearchSpace& space);

/// Reads a result back from reportJson() text; nothing, with `error` set, when it is not one.
std::optional<SearchResult> readResultJson(std::string_view text, std::string& error);

/// Joins the slices of one search (same level, space, budget and seed; each slice of N once) into
/// the result one run would have given; nothing, with `error` set, when they do not fit together.
std::optional<SearchResult> mergeResults(std::vector<SearchResult> slices, std::string& error);

/// The parts subset `subset` of `space` places, as PartsUsed::label() words them.
std::string subsetLabel(const SearchSpace& space, int subset);

/// The script a solution is written as: its placements and actions, and the expectation that the
/// goal is reached before the step after the one it was reached in.
ScriptDesc solutionScript(const SearchSpace& space, const SearchResult& result, const FoundSolution& solution);

} // namespace rube::game
