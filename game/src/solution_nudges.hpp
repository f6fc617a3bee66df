#pragma once
/// How a solution holds when its parts are placed a little off: each placement moved one step of the
/// placement grid (5 cm) either way along x and y, one at a time, and whether the goal is still
/// reached. A solution that works on one grid point only asks the player to find that point, and any
/// change to the engine may tip it over: the level tests hold every shipped solution script to all
/// four moves of each part, and the editor says on saving whether a new level's solution does.

#include "placement.hpp"
#include "script_file.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace rube::game {

/// One placement moved one grid step, and what came of it.
struct PlacementNudge {
    std::size_t placement = 0; ///< which placement of the script, in order
    Vec2 step;                 ///< the move: (+-kPlacementGrid, 0) or (0, +-kPlacementGrid) (placement.hpp)
    bool refused = false;      ///< the player could not play it: the placement rules refuse the part there (out of
                               ///< its zone, onto a part), or an action of the script cannot be taken
    bool reached = false;      ///< the goal was reached within the steps given
};

/// Each placement of `script` moved by each of the four grid steps, one move at a time, in order
/// (right, left, up, down), each run to the goal or `steps` as `rube solve` runs a candidate
/// (runCandidate, solve_search.hpp), without stopping when the machine comes to rest.
std::vector<PlacementNudge> nudgePlacements(const SceneDesc& level, const ScriptDesc& script, std::int64_t steps);

/// The grid step as the messages say it: "5 cm".
std::string gridStepWords();

/// "heavy moved 5 cm left": a move said as the editor's bar says it.
std::string describeNudge(const ScriptDesc& script, const PlacementNudge& nudge);

} // namespace rube::game
