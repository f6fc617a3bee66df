#pragma once
/// Level: what a level file adds to a scene — items of a kind, the inventory, placement zones and
/// the goal. One format, one parser: a physics scene is a level without any of these.

#include "scene_errors.hpp"

#include "rube/physics/world.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rube::game {

/// The kinds of item, in the order their names are listed in messages.
enum class ItemKind : std::uint8_t { heavy, bouncy, steel, balloon, plank, ramp, bumper, cannon, bomb, target, bucket, switchItem, magnet, fan, rocket };

/// How a bomb goes off.
enum class Trigger : std::uint8_t { timer, impact, switchHit };

/// One item: a fixed part of the level, or one the player placed. Angles are radians here
/// (files write degrees); sizes are the kind's defaults unless the file set them.
struct ItemDesc {
    std::string name;            ///< unique among the level's names; may be empty for balls and planks
    ItemKind kind = ItemKind::heavy;
    Vec2 position;               ///< centre; a bucket's is the middle of its floor
    double angle = 0.0;          ///< planks and ramps: tilt; cannons: aim; fans: the way they blow; rockets: the way they push (radians, counter-clockwise from +x)
    double size = 0.0;           ///< radius of balls, bumpers, targets, switches, bombs, magnets; length of planks; width of buckets and fans
    double height = 0.0;         ///< bucket walls, m
    Vec2 velocity;               ///< balls: initial velocity, m/s
    double speed = 0.0;          ///< cannon: muzzle speed; fan: air speed, m/s
    ItemKind ammo = ItemKind::heavy; ///< cannon: the ball kind it shoots
    std::optional<double> fireAt;    ///< cannon: fires by itself at this time, s
    double blastRadius = 0.0;    ///< bomb: bodies whose centre is closer are pushed, m
    double strength = 0.0;       ///< bomb: impulse at the centre, N s; magnet: pull at 1 m, N m^2
    double reach = 0.0;          ///< magnet: no pull this far or farther; fan: length of its air column, m
    bool on = true;              ///< magnet, fan: working from the start (a switch flips it); rocket: lit at the start (else a switch or click lights it)
    double thrust = 0.0;         ///< rocket: the thruster's constant force along `angle`, N
    double burn = 0.0;           ///< rocket: how long the thruster burns once lit, s
    Trigger trigger = Trigger::impact; ///< bomb: what sets it off
    double fuse = 0.0;           ///< bomb with a timer: seconds from the start
    std::string triggers;        ///< switch: the name of the cannon or bomb it sets off, the fan or magnet it flips, or the [[rope]] it cuts
    int path = -1;               ///< target: index of the [[path]] it follows, or -1 (still)
    SourcePlace place;           ///< where the file wrote it, for messages about it
};

/// A rectangle where the player may place items.
struct Zone {
    Aabb box;          ///< the area: a placed item must lie wholly inside it
    SourcePlace place; ///< where the file wrote it
};

/// What wins the level.
enum class GoalKind : std::uint8_t { targetHit, ballInBucket, allTargets };

/// The goal: its text for the HUD, the condition and an optional time limit.
struct Goal {
    std::string text;              ///< what the player is told
    GoalKind kind = GoalKind::targetHit;
    std::string item;              ///< the target (targetHit) or bucket (ballInBucket)
    std::optional<double> timeLimit; ///< seconds; the goal counts only when reached by then
};

/// Everything a level adds to a scene.
struct LevelDesc {
    std::vector<ItemDesc> items;                 ///< fixed parts, in file order
    std::map<std::string, int, std::less<>> inventory; ///< placeable kind name -> how many
    std::vector<Zone> zones;                     ///< where placements may go
    std::optional<Goal> goal;                    ///< absent for plain physics scenes
    /// True when the file used any level feature, so `rube run` plays it as a level.
    bool isLevel() const { return goal.has_value() || !items.empty() || !inventory.empty() || !zones.empty(); }
    /// The index of the item called `name`, or -1.
    int find(std::string_view name) const;
};

/// The kind's name as files spell it: "heavy", ..., "switch".
std::string_view itemKindName(ItemKind kind);
/// "" when `name` is an item of one of `kinds`, else the one-line error for naming it through `key`
/// ("target 'T' is a bomb, not a target", or "unknown target 'U'" + `where` + a hint): the one
/// wording for every reference, from a level's goal and switches or from a script.
std::string itemReferenceError(const LevelDesc& level, std::string_view key, std::string_view name,
                               std::initializer_list<ItemKind> kinds, std::string_view where = "");
/// Every kind, in the order of the enum.
inline constexpr ItemKind kAllItemKinds[] = {ItemKind::heavy, ItemKind::bouncy, ItemKind::steel, ItemKind::balloon,
                                             ItemKind::plank, ItemKind::ramp,   ItemKind::bumper, ItemKind::cannon,
                                             ItemKind::bomb,  ItemKind::target, ItemKind::bucket, ItemKind::switchItem,
                                             ItemKind::magnet, ItemKind::fan, ItemKind::rocket};
/// True for the kinds that are one dynamic ball.
bool isBall(ItemKind kind);
/// True for the kinds a player may place from the inventory.
bool isPlaceable(ItemKind kind);
/// An item of `kind` at `position` with every size and property at the kind's default.
ItemDesc defaultItem(ItemKind kind, Vec2 position);

/// The physics bodies one item adds: nothing for a cannon, one circle for balls, bumpers, bombs,
/// targets, switches, magnets and rockets, one segment for planks, ramps and a fan's housing, three segments
/// for a bucket; and the field of a magnet, a fan or a rocket.
struct ItemBodies {
    std::vector<CircleDef> circles;   ///< in order
    std::vector<SegmentDef> segments; ///< in order
    std::optional<Magnet> magnet;     ///< a magnet's pull
    std::optional<Wind> wind;         ///< a fan's air column
    std::optional<Thruster> thruster; ///< a rocket's thruster (its circle index is set when it joins a World)
};
/// The bodies of `item`.
ItemBodies itemBodies(const ItemDesc& item);
/// The box around everything `item` occupies, for placement checks.
Aabb itemExtent(const ItemDesc& item);

} // namespace rube::game
