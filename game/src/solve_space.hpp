#pragma once
/// The search space of `rube solve`: everything a player can do in a level, as a finite grid.
/// For each inventory kind, positions on a grid in the placement zones and (for parts that turn)
/// angles; for each fixed part a click acts on (cannons, bombs, switches, fans, magnets, rockets),
/// the step it is acted on (or never) and, for a cannon, its aim; and every subset of the
/// inventory up to its counts. A candidate is one choice on every axis of one subset.

#include "script_file.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rube::game {

/// How finely the space is cut.
struct SpaceOptions {
    std::optional<double> step; ///< grid step in the zones, m; else a quarter of each part's size
    double angleStep = 15.0;    ///< degrees between the angles a turning part is tried at
    double aimStep = 5.0;       ///< degrees between a cannon's aims
    double actionEvery = 0.5;   ///< seconds between the steps a click may be tried at
};

/// A grid point of a zone: which zone, and its column and row.
struct GridPoint {
    int zone = 0;
    int column = 0;
    int row = 0;
};

/// One placeable kind of the inventory, with the grid it is tried on.
struct KindAxis {
    ItemKind kind = nullptr;
    int count = 0;                   ///< the inventory's count: subsets use 0 .. count of it
    double step = 0.0;               ///< grid step, m
    std::vector<GridPoint> points;   ///< every grid point of every zone, zone by zone, row by row
    std::vector<Vec2> positions;     ///< the centre each point puts the part at
    std::vector<int> columns, rows;  ///< each zone's grid size
    std::vector<double> angles{0.0}; ///< degrees; {0} for a part that does not turn
    bool turnsAround = false;        ///< the angles go all the way round (a neighbour of the last is the first)
};

/// A cannon's aim: kept as the level has it, turned to an angle, or aimed at an item on an arc.
struct AimChoice {
    std::optional<double> angle; ///< degrees
    std::string target;          ///< an item to aim at (its name), on the high arc when `highArc`
    bool highArc = false;
};

/// One fixed part a click acts on.
struct ActorAxis {
    std::string item; ///< its name
    ActionKind verb = ActionKind::fire;
    std::vector<AimChoice> aims;      ///< cannons: {keep, angles..., targets...}; else empty
    std::vector<std::int64_t> clickSteps; ///< -1 (never) first, then the steps it may be acted on at
};

/// One candidate: a subset of the inventory and a choice (a digit) on each of its axes.
struct Candidate {
    int subset = 0;
    std::vector<std::uint32_t> digits;
    bool operator==(const Candidate&) const = default;
    bool operator<(const Candidate& other) const {
        return subset != other.subset ? subset < other.subset : digits < other.digits;
    }
};

/// The space of one level.
class SearchSpace {
public:
    SearchSpace(const SceneDesc& level, const SpaceOptions& options);

    const std::vector<KindAxis>& kinds() const { return kinds_; }
    const std::vector<ActorAxis>& actors() const { return actors_; }
    /// The steps a run takes: the goal's time limit, else the level's duration.
    std::int64_t steps() const { return steps_; }
    /// The number of candidates, saturated at 2^62.
    std::uint64_t size() const { return total_; }
    /// The number of subsets of the inventory (the first places nothing).
    int subsetCount() const { return static_cast<int>(subsets_.size()); }
    /// The number of candidates of subset `subset`, saturated at 2^62.
    std::uint64_t subsetSize(int subset) const { return subsetSizes_[static_cast<std::size_t>(subset)]; }
    /// The same as a double, not saturated: the subset's weight in the space.
    double subsetWeight(int subset) const { return subsetWeights_[static_cast<std::size_t>(subset)]; }
    /// Candidate `index` of the whole space in a fixed order (subsets, then digits, last fastest).
    Candidate at(std::uint64_t index) const;
    /// Candidate `index` of subset `subset`, in the same order.
    Candidate at(int subset, std::uint64_t index) const;
    /// A candidate of subset `subset` drawn at random: every digit uniformly, from a generator seeded
    /// with (seed, number) alone, so any slice of a search draws the same.
    Candidate sample(int subset, std::uint64_t seed, std::uint64_t number) const;
    /// The candidates one grid step away on one axis (positions by a column or row in the same zone).
    std::vector<Candidate> neighbours(const Candidate& candidate) const;
    /// The script a candidate plays: its placements, then its actions in step order.
    ScriptDesc script(const Candidate& candidate) const;
    /// How many of each kind subset `subset` places, in the order of kinds().
    const std::vector<int>& subsetCounts(int subset) const { return subsets_[static_cast<std::size_t>(subset)]; }
    /// A candidate as text, for caches and messages: "s2:4,0,17".
    static std::string key(const Candidate& candidate);

private:
    std::vector<std::uint32_t> radices(int subset) const;

    std::string levelName_;
    std::vector<KindAxis> kinds_;
    std::vector<ActorAxis> actors_;
    std::vector<std::vector<int>> subsets_;
    std::vector<std::uint64_t> subsetSizes_;
    std::vector<double> subsetWeights_; // sizes as doubles, unsaturated
    std::uint64_t total_ = 0;
    std::int64_t steps_ = 0;
};

} // namespace rube::game
