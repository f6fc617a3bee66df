#pragma once
/// Level: what a level file adds to a scene — items (each of a kind, see part_kind.hpp), the inventory, placement zones
/// and the goal. One format, one parser: a physics scene is a level without any of these.

#include "part_kind.hpp"
#include "scene_errors.hpp"

#include "rube/physics/world.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rube::game {

/// A rectangle where the player may place items.
struct Zone {
    Aabb box;          ///< the area: a placed item must lie wholly inside it
    SourcePlace place; ///< where the file wrote it
};

/// What wins the level.
enum class GoalKind : std::uint8_t { targetHit, ballInBucket, allTargets, reachArea };

/// The goal's condition as files spell it: "target-hit", "ball-in-bucket", "all-targets", "reach-area".
std::string_view conditionName(GoalKind kind);

/// The goal: its text for the HUD, the condition and an optional time limit.
struct Goal {
    std::string text; ///< what the player is told
    GoalKind kind = GoalKind::targetHit;
    std::string item; ///< the target (targetHit), bucket (ballInBucket) or ball (reachArea; "": any ball)
    Aabb area;        ///< reachArea: where the ball's centre must come
    std::optional<double> timeLimit; ///< seconds; the goal counts only when reached by then
};

/// A hint the play window shows on H, one after another.
struct Hint {
    std::string text;  ///< one or two short sentences
    SourcePlace place; ///< where the file wrote it
};

/// Everything a level adds to a scene.
struct LevelDesc {
    std::vector<ItemDesc> items;                       ///< fixed parts, in file order
    std::map<std::string, int, std::less<>> inventory; ///< placeable kind name -> how many
    std::vector<Zone> zones;                           ///< where placements may go
    std::optional<Goal> goal;                          ///< absent for plain physics scenes
    std::vector<Hint> hints;                           ///< [[hint]]s in file order
    /// `clicks`: the fixed parts a click may act on while the machine runs (fire a cannon, set off a
    /// bomb, flip a switch, fan, magnet or rocket), by name; absent, every one. A designer closes a
    /// shortcut with it, as with a part limit: `clicks = []` leaves the machine to do the work.
    std::optional<std::vector<std::string>> clicks;
    /// True when a click may act on the item called `name` (the level's `clicks` allow it).
    bool clickable(std::string_view name) const;
    /// True when the file used any level feature, so `rube run` plays it as a level.
    bool isLevel() const { return goal.has_value() || !items.empty() || !inventory.empty() || !zones.empty(); }
    /// The index of the item called `name`, or -1.
    int find(std::string_view name) const;
};

/// The kind's name as files spell it: "heavy", ..., "switch".
inline std::string_view itemKindName(ItemKind kind) { return kind->name(); }
/// "" when `name` is an item of a kind that plays `role`, else the one-line error for naming it
/// through `key` ("target 'T' is a bomb, not a target", or "unknown target 'U'" + `where` + a hint):
/// the one wording for every reference, from a level's goal and switches or from a script. With
/// `ropeNames` (a switch's `triggers`), the level's named ropes are listed among what would do.
std::string itemReferenceError(const LevelDesc& level, std::string_view key, std::string_view name, PartRole role,
                               std::string_view where = "", const std::vector<std::string>* ropeNames = nullptr);
/// An item of `kind` at `position` with every size and property at the kind's default.
inline ItemDesc defaultItem(ItemKind kind, Vec2 position) { return kind->make(position); }
/// The bodies of `item`.
inline ItemBodies itemBodies(const ItemDesc& item) { return item.kind->bodies(item); }
/// The box around everything `item` occupies, for placement checks.
inline Aabb itemExtent(const ItemDesc& item) { return item.kind->extent(item); }

} // namespace rube::game
