#pragma once
/// The search of `rube solve`: candidates of a SearchSpace checked by the placement rules and run
/// headless, on N threads, over one slice of N; and the robustness of each solution found.

#include "solve_space.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rube::game {

/// What one run of a candidate came to.
struct RunOutcome {
    bool valid = false;               ///< every placement passed the rules and every action could be taken
    std::optional<std::int64_t> goal; ///< the step the goal was reached in
    std::int64_t steps = 0;           ///< steps run (fewer than the limit when it stopped early)
};

/// How long nothing must move before a run is given up, s: longer than a bucket's rest (0.5 s), so a
/// ball lying still in the goal's bucket is judged before the run stops.
inline constexpr double kQuietSeconds = 1.0;
/// Below this speed (m/s, and rad/s for spin) a body counts as not moving.
inline constexpr double kQuietSpeed = 0.01;

/// Runs `script`'s placements and actions on `level` as `rube run --script` does, for at most
/// `steps` steps, stopping at the goal, or once nothing has moved for kQuietSeconds while no action
/// is left to take, no part waits on a timer, no path moves and no thruster burns. With `stopWhenQuiet`
/// false it always runs to the goal or the limit (the tests compare the two).
RunOutcome runCandidate(const SceneDesc& level, const ScriptDesc& script, std::int64_t steps,
                        bool stopWhenQuiet = true);

/// What to search and how.
struct SolveOptions {
    SpaceOptions space;
    std::uint64_t budget = 2000; ///< runs: the whole space when it is no larger, else this many (see SearchPlan)
    std::uint64_t seed = 1;      ///< the random search's seed
    int jobs = 1;                ///< threads
    int shardIndex = 0;          ///< this slice: candidates whose number is shardIndex modulo shardCount
    int shardCount = 1;
};

/// How a budget is spent: every subset of the inventory gets an equal share, so a subset of few
/// parts (where shortcuts hide) is never starved by the many candidates of a large one. A subset no
/// larger than its share is searched whole, and what it leaves is shared among the rest; the
/// others get random draws. Candidates are numbered subset by subset.
struct SearchPlan {
    std::vector<std::uint64_t> tries; ///< candidates searched in each subset
    std::vector<bool> whole;          ///< each subset: searched whole, else drawn at random
    std::uint64_t total = 0;          ///< candidates in all
    /// True when every subset is searched whole: the search is exhaustive.
    bool exhaustive() const;
    /// The subset candidate `number` is in.
    int subsetOf(std::uint64_t number) const;
    /// Candidate `number` of the search: in a whole subset, its index there; else a draw seeded with (seed, number).
    Candidate candidate(const SearchSpace& space, std::uint64_t seed, std::uint64_t number) const;
};

/// The plan for `budget` runs over `space`.
SearchPlan planSearch(const SearchSpace& space, std::uint64_t budget);

/// A solution: the candidate's number (its index in the space, or its draw), its goal step, and
/// how many of its grid neighbours also solve.
struct FoundSolution {
    std::uint64_t number = 0;
    std::int64_t goalStep = 0;
    int neighboursSolving = 0;
    int neighbours = 0;
};

/// What became of one subset's candidates.
struct SubsetTally {
    std::uint64_t tried = 0;  ///< candidates run
    std::uint64_t valid = 0;  ///< those the placement rules allowed (and whose aims could be taken)
    std::uint64_t solved = 0; ///< those that reached the goal
};

/// The outcome of a search, or of one slice of it.
struct SearchResult {
    std::string level;       ///< the level's name
    std::uint64_t space = 0; ///< candidates in the space (saturated at 2^62)
    std::uint64_t budget = 0;
    std::uint64_t seed = 0;
    int shardIndex = 0, shardCount = 1;
    std::vector<SubsetTally> subsets;     ///< by subset of the space
    std::vector<FoundSolution> solutions; ///< by number
    std::uint64_t runs =
        0; ///< headless runs made (a refused candidate makes none), neighbours included; not in the JSON
    /// Candidates run, and those allowed, over all subsets.
    std::uint64_t tried() const;
    std::uint64_t valid() const;
    /// The share of the space's valid candidates that solve, estimated subset by subset and weighted
    /// by their sizes: sum w_s solved_s / tried_s over sum w_s valid_s / tried_s; when every subset
    /// is searched whole this is exactly solutions / valid candidates. 0 when none is valid.
    double solveFraction(const SearchSpace& space) const;
};

/// Progress: candidates done of the slice's total, solutions so far, seconds since the start.
using SearchProgress =
    std::function<void(std::uint64_t done, std::uint64_t total, std::uint64_t solved, double seconds)>;

/// The candidate with number `number` of `result`'s search.
Candidate candidateOf(const SearchSpace& space, const SearchResult& result, std::uint64_t number);

/// Searches one slice of the space. The result depends on the level, the space, the budget, the
/// seed and the slice, never on `jobs` or the progress callback (called about 5 times a second).
SearchResult searchLevel(const SceneDesc& level, const SearchSpace& space, const SolveOptions& options,
                         const SearchProgress& progress = {});

} // namespace rube::game
