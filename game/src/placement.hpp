#pragma once
/// Placement: the player's items put into a level before it runs, and the rules that refuse them.

#include "scene.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rube::game {

/// The placement grid of the play window and the editor: a placed or dragged part snaps to
/// multiples of 1 / kPlacementGridPerMetre (5 cm), so scripts read as round numbers.
inline constexpr double kPlacementGridPerMetre = 20.0;
inline constexpr double kPlacementGrid = 1.0 / kPlacementGridPerMetre; ///< m

/// One item the player places from the inventory.
struct Placement {
    ItemKind kind = nullptr;            ///< must be in the level's inventory
    Vec2 position;                      ///< centre
    double angle = 0.0;                 ///< radians; planks, ramps and fans turn
    std::string name;                   ///< optional, so scripts can refer to it later
    SourcePlace place;                  ///< where the script wrote it
    double angleDegrees = 0.0;          ///< `angle` in degrees as the script wrote it, so a recorded
                                        ///< session writes back exactly what it read
    std::optional<PartParams> params{}; ///< the kind's own parameters a script gave (a plank's length,
                                        ///< a bomb's trigger); none: the kind's defaults
    std::vector<std::pair<std::string, std::string>>
        ownKeys{}; ///< those keys and their values as TOML
                   ///< text, in file order, so a script writes back what it read
};

/// A placement that was refused: which rule, and the words of the message.
struct PlacementRefusal {
    std::size_t index = 0; ///< which placement, in order
    std::string message;   ///< "placement refused: plank at [1, 2] overlaps the fixed segment 3 (...)"
    std::string brief;     ///< the same for the play window's bar, short and rounded to centimetres:
                           ///< "plank at [1, 2]: overlaps the fixed segment 3"
};

/// Checks every placement in order against the level's rules: the kind is in the inventory and
/// its count is not used up, the item lies wholly inside a placement zone, and it overlaps no
/// fixed part and no earlier placement. Returns the first refusal, or nothing when all are fine.
std::optional<PlacementRefusal> checkPlacements(const SceneDesc& scene, const std::vector<Placement>& placements);

/// Every refusal of checkPlacements(), not just the first, so `rube check` lists them all; a refused
/// placement takes no room, so one mistake does not make later placements overlap it.
std::vector<PlacementRefusal> placementRefusals(const SceneDesc& scene, const std::vector<Placement>& placements);

/// The pairs of fixed items (indices into level.items) whose bodies overlap: a lint, since the
/// physics pushes them apart on the first step and the level does not start as drawn.
std::vector<std::pair<std::size_t, std::size_t>> overlappingItems(const SceneDesc& scene);

/// The item a placement puts into the level: the kind's defaults, or the parameters the script gave, at the placement's
/// pose.
ItemDesc placedItem(const Placement& placement);

} // namespace rube::game
