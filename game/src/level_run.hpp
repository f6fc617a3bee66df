#pragma once
/// LevelRun: a level being played. Builds the World from the level and the player's placements,
/// steps it, and turns what happens in it (impacts, timers, switches) into the game's events:
/// targets hit, cannons fired, bombs going off, and the goal reached.

#include "placement.hpp"
#include "scene.hpp"

#include "rube/physics/aim.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rube::game {

/// What kind of thing happened.
enum class EventKind : std::uint8_t { hit, shot, explosion, goal };

/// One thing that happened, for the summary and the expectations.
struct GameEvent {
    EventKind kind = EventKind::hit;
    std::int64_t step = 0; ///< steps taken when it happened (the step it happened in)
    double time = 0.0;     ///< world time, s
    std::string item;      ///< the target, switch, cannon or bomb's name
    Vec2 position;         ///< hits: the point of impact; shots: the muzzle; explosions: the centre; the goal:
                           ///< where it was reached (the hit's point, the ball resting in the bucket)
    int count = 0;         ///< explosions: bodies pushed
    std::string by;        ///< hits and the goal: what did it (LevelRun::nameOf), "" when unnamed
};

/// Which of the World's bodies is an item's, and what has happened to it.
struct ItemState {
    CircleId circle;    ///< its circle in the World: null when it has none, or no longer has one (a bomb gone off)
    BodyId body;        ///< its first rigid body in the World: null when it has none
    std::vector<JointId> joints; ///< its joints (ItemBodies::joints), in order, once every item is in the World
    std::vector<SegmentId> segments; ///< its segments (ItemBodies::segments), in order
    double aim = 0.0;   ///< cannons: the barrel's angle now, radians
    bool hit = false;   ///< targets and switches: touched by a ball
    bool pressed = false; ///< switches: toggled by a click or a script's action (drawn as one a ball pressed);
                          ///< lasers: switched an odd number of times (on unless they started on)
    bool fired = false;   ///< cannons: have shot; timers, plates, candles, detectors: have switched (once)
    std::optional<double> timedShot;   ///< cannons: a shot fireWhen() timed, waiting for this world time, s
    std::optional<double> detonatedAt; ///< bombs: when they went off, s
    std::optional<double> since;       ///< timers, candles, pressure plates, lifts: when their clock started (a
                                       ///< switch, a weight coming to rest on it), s; none while it has not
    int field = -1; ///< magnets, fans and rockets: index of their Magnet, Wind or Thruster in the World's fields
};

/// Steps a level runs when nothing says otherwise: its goal's time limit rounded up to whole steps,
/// else the scene's duration (SceneDesc::defaultSteps).
std::int64_t levelSteps(const SceneDesc& level);

/// A level in play. Placements must have passed checkPlacements().
class LevelRun {
public:
    /// The world of `scene` with `placements` added as items after the fixed ones.
    LevelRun(const SceneDesc& scene, const std::vector<Placement>& placements);

    /// Advances one step: the kinds' work before it, the physics, then timers, hits, switches and the goal.
    void step();

    /// The world as it is now.
    const World& world() const { return world_; }
    /// Every item, fixed ones first, then the placements.
    const std::vector<ItemDesc>& items() const { return items_; }
    /// The state of each item, in the order of items().
    const std::vector<ItemState>& states() const { return states_; }
    /// Everything that happened so far, in order.
    const std::vector<GameEvent>& events() const { return events_; }
    /// Steps taken so far.
    std::int64_t steps() const { return world_.stats().steps; }
    /// The step in which the goal was reached, if it has been.
    std::optional<std::int64_t> goalStep() const { return goalStep_; }
    /// True once the goal's time limit has passed without the goal: it can no longer be reached.
    bool timeUp() const;
    /// The level's goal, if it has one.
    const std::optional<Goal>& goal() const { return scene_.level.goal; }
    /// The index of the item called `name`, or -1.
    int find(std::string_view name) const;
    /// The item World circle `circle` belongs to, or -1 (shots and the scene's own circles).
    int itemOf(CircleId circle) const;
    /// True when World circle `circle` was shot from a cannon.
    bool isProjectile(CircleId circle) const;
    /// Who World circle `circle` is, as an expectation's `by` names it: its item's name, the name of
    /// the cannon that shot it, or the scene's [[circle]] name; "" when it has none.
    std::string nameOf(CircleId circle) const;
    /// The item World rigid body `slot` belongs to (a crate, a domino, a seesaw's plank), or -1 (the
    /// scene's own [[box]]es and [[capsule]]s).
    int itemOfBody(int slot) const;
    /// The name of the World's rigid body in `slot`: its item's name, or the scene's [[box]] or
    /// [[capsule]] name; "" when unnamed.
    std::string bodyName(int slot) const;
    /// The scene the level was built from.
    const SceneDesc& scene() const { return scene_; }

    /// Where an item is now (targets on a path move) and how fast it moves, m/s.
    Vec2 itemPosition(int item) const;
    /// The item's velocity now: a target on a path moves at its path's speed.
    Vec2 itemVelocity(int item) const;
    /// The launch velocity cannon `cannon` would give a shot now.
    Vec2 launchVelocity(int cannon) const;

    /// Turns a cannon's barrel to `angle` radians.
    void aim(int cannon, double angle);
    /// Aims a cannon at a fixed point on the low or high gravity arc; "" or why it cannot.
    std::string aimAtPoint(int cannon, Vec2 point, bool highArc);
    /// Aims a cannon at an item: a still one on the chosen arc, a moving one by leading it; "" or why not.
    std::string aimAtItem(int cannon, int item, bool highArc);
    /// Fires a cannon: a ball of its ammo kind leaves its pivot at its aim and muzzle speed.
    void fire(int cannon);
    /// Times a shot along the cannon's present aim to meet `target` (moving at its velocity now) and
    /// fires it at that step, or now when no wait is needed; "" or why no such shot exists.
    std::string fireWhen(int cannon, int target);
    /// Sets a bomb off now (what its kind does when triggered).
    void detonate(int bomb);
    /// Triggers an item as a switch would (its kind says what that does: a switch triggers what it
    /// names or cuts its rope, a fan or magnet turns on or off, a rocket lights).
    void toggle(int item);
    /// Cuts the [[rope]] called `name` (a cut rope stays cut; an unknown name does nothing).
    void cutRope(std::string_view name);

    /// For the kinds' own files (game/src/items), which act on the world: the world to change.
    World& partWorld() { return world_; }
    /// For the kinds' own files: the state of item `item`, to change.
    ItemState& partState(int item) { return states_[static_cast<std::size_t>(item)]; }
    /// For the kinds' own files: records that `event` happened.
    void report(GameEvent event) { events_.push_back(std::move(event)); }

private:
    void addItem(const ItemDesc& item);
    /// Adds every item's joints (ItemBodies::joints), once all items are in the World.
    void addItemJoints();
    void checkGoal();
    CircleId ballRestingIn(const ItemDesc& bucket) const;
    bool pastTimeLimit(double limit) const { return world_.time() > limit + 1e-9; }

    SceneDesc scene_;
    World world_;
    std::vector<ItemDesc> items_;
    std::vector<ItemState> states_;
    /// Each item's own bodies in the World, in ItemBodies order, until its joints are added.
    struct ItemHandles {
        std::vector<CircleId> circles;
        std::vector<BodyId> bodies;
        std::vector<ItemJoint> joints;
    };
    std::vector<ItemHandles> pendingJoints_;
    std::vector<RopeId> ropes_; // the scene's [[rope]] i (SceneDesc::ropes) -> its rope in the World
    std::vector<GameEvent> events_;
    std::optional<std::int64_t> goalStep_;
    std::int64_t bucketRestSteps_ = 0; // consecutive steps a ball has rested in the goal's bucket
};

} // namespace rube::game
