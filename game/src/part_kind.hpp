#pragma once
/// PartKind: everything the game knows about one kind of part, as a small table of behaviour the
/// callers use without knowing the kind (Chipmunk's joints work the same way). Each kind lives in
/// one file, game/src/items/<kind>.cpp, which defines its descriptor and its own parameter struct;
/// the registry (part_registry.cpp) lists every descriptor. A kind is its descriptor: ItemKind is a
/// pointer to one, so no list of kinds is written anywhere else.

#include "scene_errors.hpp"

#include "rube/physics/joint.hpp"
#include "rube/physics/rigid_body.hpp"
#include "rube/physics/world.hpp"

#include <any>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rube::render {
class DrawList;
}

namespace rube::game {

class PartKind;
class LevelRun;
class TableReader;
struct SceneReading;
struct LevelDesc;
struct ItemState;
enum class ActionKind : std::uint8_t;

/// A kind of part: a pointer to its descriptor (never null in an item).
using ItemKind = const PartKind*;

/// A part's own parameters (a rocket's thrust, a bucket's walls), held without the caller knowing
/// their type: only the kind's file, which made them, reads them (PartParams::as<RocketParams>()).
class PartParams {
public:
    PartParams() = default;
    /// Holds `params`.
    template <class P>
    explicit PartParams(P params) : value_(std::move(params)) {}
    /// The parameters as the kind's struct `P`; the kind's own file is the only caller. Asking for
    /// another kind's struct throws std::bad_any_cast: a bug, never a silent misreading.
    template <class P>
    P& as() {
        return std::any_cast<P&>(value_);
    }
    /// As above, read-only.
    template <class P>
    const P& as() const {
        return std::any_cast<const P&>(value_);
    }

private:
    std::any value_;
};

/// One item: a fixed part of the level, or one the player placed. Angles are radians here (files
/// write degrees); everything the kind alone uses is in `params`.
struct ItemDesc {
    std::string name;        ///< unique among the level's names; may be empty for balls and planks
    ItemKind kind = nullptr; ///< its descriptor
    Vec2 position;           ///< centre; a bucket's is the middle of its floor
    double angle = 0.0;      ///< planks and ramps: tilt; cannons: aim; fans and rockets: the way they push (radians)
    SourcePlace place;       ///< where the file wrote it, for messages about it
    PartParams params;       ///< the kind's own parameter struct, at its defaults unless the file set them
    std::optional<double> angleDegrees; ///< `angle` as the file wrote it (degrees), so the level writer
                                        ///< writes back exactly what it read; none when not written
    std::vector<std::string> ownLines;  ///< the kind's other keys as TOML lines ("speed = 10"), in the
                                        ///< reader's order, for the level writer
};

/// One end of an item's joint: the world, one of the item's own bodies, or another item of the
/// level by its name (that item's first rigid body, else its first circle). Named items are found
/// once every item has joined the World, so an item may name one placed or listed after it.
struct ItemJointEnd {
    /// What the end is.
    enum class To : std::uint8_t { world, circle, body, item };
    To to = To::world;
    int index = 0;    ///< circle, body: its index in the item's ItemBodies::circles or rigidBodies
    std::string item; ///< item: the other item's name
};

/// A joint an item adds (a motor's axle, a hammer's pivot, a belt between two wheels). The def's
/// anchors, axis and the like are filled by the kind; its ends and its gear's joints by the run.
struct ItemJoint {
    JointDef def;      ///< ends (a, b) and jointA, jointB are set when the item joins a World
    ItemJointEnd a, b; ///< every kind but gear
    /// gear: the two joints it couples, each an index into this item's joints, or (index -1) the
    /// first joint of the item named in gearItemA / gearItemB (a belt between two wheels).
    int gearA = -1, gearB = -1;
    std::string gearItemA, gearItemB;
    /// gear: where its ratio comes from. given: def.ratio. belt, mesh: from the rims (a circle's
    /// radius, a body's larger half extent) of the two wheels the coupled joints turn (their ends b),
    /// when the item joins the World: a belt's -r_B / r_A turns B at r_A / r_B of A the same way,
    /// meshed teeth's r_B / r_A (teeth in proportion to the rims) the opposite way.
    enum class Ratio : std::uint8_t { given, belt, mesh };
    Ratio ratio = Ratio::given;
};

/// The physics bodies one item adds (circles, segments and rigid bodies, each in order), the joints
/// between them, and the field it brings.
struct ItemBodies {
    std::vector<CircleDef> circles;        ///< in order
    std::vector<SegmentDef> segments;      ///< in order
    std::vector<RigidBodyDef> rigidBodies; ///< boxes and capsules (crates, dominoes, a hammer's head), in order
    std::vector<ItemJoint> joints;         ///< in order, added once every item is in the World
    std::optional<Magnet> magnet;     ///< a magnet's pull
    std::optional<Wind> wind;         ///< a fan's air column
    std::optional<Thruster> thruster; ///< a rocket's thruster (its circle index is set when it joins a World)
};

/// One key of a kind's [[item]] table, for the reader's list of known keys and for the docs.
struct PartKey {
    std::string_view key;   ///< as files spell it
    std::string_view value; ///< its default (or "required"), as the docs show it
    std::string_view doc;   ///< one line: what it means and its unit
};

/// The keys every [[item]] has, first in each kind's list.
inline constexpr PartKey kKindKey{"kind", "required", "the part's kind"};
/// An item's name, which goals, switches and scripts use to refer to it.
inline constexpr PartKey kNameKey{"name", "none", "unique in the file; how goals, switches and scripts refer to it"};
/// An item's position.
inline constexpr PartKey kPositionKey{"position", "required", "[x, y] m: its centre"};

/// The roles a part can play where something refers to it by name. A kind says which it plays;
/// messages list the kinds of a role in their referenceOrder().
enum class PartRole : std::uint8_t {
    fire,       ///< a script's fire, rotate, aim and fire-when, and `shot` expectations (cannons)
    detonate,   ///< a script's detonate and `explosion` expectations (bombs)
    toggle,     ///< a script's toggle (switches, fans, magnets, rockets)
    aimTarget,  ///< the target of an aim or fire-when
    hitReport,  ///< `hit` expectations: reports the first touch of a ball
    triggered,  ///< what a switch's `triggers` may name (besides a rope)
    goalTarget, ///< a goal's `target`, counted by all-targets
    goalBucket, ///< a goal's `bucket`
    goalMover,  ///< a reach-area goal's `item`: a part that moves (a ball, a crate, a domino, a rocket)
    wheel       ///< what a belt or a gear may name: its first joint is the axle it turns on
};

/// What a kind draws with, handed to PartKind::draw.
struct PartDrawing {
    const LevelRun& run;    ///< the level being played (its world, items and states)
    int item;               ///< the item's index in run.items()
    render::DrawList& list; ///< where to draw
};

/// The descriptor of a kind of part. Override what the kind does; the defaults are "nothing".
class PartKind {
public:
    virtual ~PartKind() = default;

    /// The kind's name as files spell it: "heavy", ..., "switch".
    virtual std::string_view name() const = 0;
    /// Where the kind stands in the catalogue: kinds are listed in messages and docs in this order.
    virtual int order() const = 0;
    /// Where the kind stands in lists of kinds that may be referred to ("cannon, bomb, fan, magnet or rocket").
    virtual int referenceOrder() const { return order(); }
    /// One line for the docs: what the part is.
    virtual std::string_view summary() const = 0;
    /// Its [[item]] keys, in the order "known keys" lists them: kind, name, position, then its own.
    virtual std::span<const PartKey> keys() const = 0;

    /// True for a dynamic ball (heavy, bouncy, steel, balloon): a cannon may shoot it.
    virtual bool isBall() const { return false; }
    /// True when a player may place it from the inventory.
    virtual bool placeable() const { return false; }
    /// True when a placement of it takes an angle (the player turns it).
    virtual bool turns() const { return false; }
    /// The turn after which it is the same part again, degrees: a board's ends are alike, so half a
    /// turn; a fan or rocket pushes one way, so a whole one. `rube solve` searches angles within it.
    virtual double turnPeriod() const { return 360.0; }
    /// True when the file must name it (goals and scripts point at it).
    virtual bool needsName() const { return false; }
    /// True when it plays `role`.
    virtual bool plays(PartRole role) const { return (void)role, false; }

    /// An item of this kind at `position`, every parameter at its default.
    virtual ItemDesc make(Vec2 position) const = 0;
    /// Reads the kind's own keys of an [[item]] into `item` (made by make()), reporting bad values.
    virtual void read(TableReader& table, ItemDesc& item, SceneReading& reading) const = 0;
    /// Checks, once every item is read, the names the item refers to (a switch's `triggers`).
    virtual void checkReferences(const ItemDesc& item, SceneReading& reading) const;

    /// The physics bodies and field of `item`.
    virtual ItemBodies bodies(const ItemDesc& item) const = 0;
    /// What a fixed item takes of the room placements may use: its bodies, unless it has none.
    virtual ItemBodies room(const ItemDesc& item) const { return bodies(item); }
    /// The box around everything `item` occupies, for placement checks.
    virtual Aabb extent(const ItemDesc& item) const;
    /// True when the cursor at `cursor` (with `tolerance` to spare) is on the item, which is at `at` now.
    virtual bool picked(const ItemDesc& item, Vec2 at, Vec2 cursor, double tolerance) const;
    /// The same in a level being edited, where the item stands as `level` places it: a part drawn
    /// between other items (a belt on its wheels) looks them up there. By default picked() at its position.
    virtual bool pickedInLevel(const ItemDesc& item, const LevelDesc& level, Vec2 cursor, double tolerance) const {
        return (void)level, picked(item, item.position, cursor, tolerance);
    }
    /// The kinematic [[path]] it follows, or -1.
    virtual int path(const ItemDesc& item) const { return (void)item, -1; }
    /// True when `point` is inside it (a bucket: between its walls, below their tops).
    virtual bool holds(const ItemDesc& item, Vec2 point) const { return (void)item, (void)point, false; }

    /// The ball it shoots and its muzzle speed, m/s (cannons only).
    virtual std::optional<CircleDef> shot(const ItemDesc& item) const { return (void)item, std::nullopt; }
    /// The muzzle speed of its shots, m/s (cannons only).
    virtual double muzzleSpeed(const ItemDesc& item) const { return (void)item, 0.0; }
    /// The most speed it can give a body of mass `lightest` in `seconds` under gravity `g` (0 for
    /// parts that add no energy): a bound the random-level tests check the world against.
    virtual double speedGiven(const ItemDesc& item, double lightest, double g, double seconds) const;

    /// Before each step: what it does to its bodies (a balloon's lift).
    virtual void beforeStep(LevelRun& run, int item) const { (void)run, (void)item; }
    /// After each step: its timers (a bomb's fuse, a cannon's fire_at).
    virtual void afterStep(LevelRun& run, int item) const { (void)run, (void)item; }
    /// True while a timer of its own will still act (a fuse not yet burnt, a fire_at not yet come):
    /// `rube solve` ends a run when nothing moves only when no part waits.
    virtual bool waits(const ItemDesc& item, const ItemState& state) const { return (void)item, (void)state, false; }
    /// A ball touched it at `point` (`by` names the ball, as LevelRun::nameOf does), on its circle or
    /// on one of its rigid bodies: targets and switches report it, a bomb on impact goes off, a
    /// flipper struck on its bat swings up.
    virtual void hit(LevelRun& run, int item, Vec2 point, const std::string& by) const {
        (void)run, (void)item, (void)point, (void)by;
    }
    /// True when a laser's beam reflects off its segments (r = d - 2 (d.n) n) rather than stopping there.
    virtual bool reflects() const { return false; }
    /// A laser's beam reached it at `point` (`by` names the laser): a detector switches.
    virtual void beamReached(LevelRun& run, int item, Vec2 point, const std::string& by) const {
        (void)run, (void)item, (void)point, (void)by;
    }
    /// A switch named it, or a script's fire, detonate or toggle did: what it does then.
    virtual void trigger(LevelRun& run, int item) const { (void)run, (void)item; }
    /// The action a click on it takes while running, if any (fire, detonate, toggle).
    virtual std::optional<ActionKind> clickAction() const { return std::nullopt; }
    /// Why a click can no longer use it ("gun has fired already"), or "".
    virtual std::string spent(const ItemDesc& item, const ItemState& state) const {
        return (void)item, (void)state, "";
    }

    /// Draws the item as it is in the run.
    virtual void draw(const PartDrawing& drawing) const = 0;
    /// Draws its inventory icon, `size` across (world units) at `centre`, faded when none is left.
    virtual void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const;

protected:
    /// An item of this kind at `position` holding `params`: what every kind's make() returns.
    template <class P>
    ItemDesc made(Vec2 position, P params) const {
        ItemDesc item;
        item.kind = this;
        item.position = position;
        item.params = PartParams(std::move(params));
        return item;
    }
};

/// Every kind, in order().
std::span<const ItemKind> allPartKinds();
/// The kind called `name`, or nullptr.
ItemKind findPartKind(std::string_view name);
/// The kind called `name`; it must exist (tests and the kinds' own files name kinds this way).
ItemKind partKind(std::string_view name);
/// The kinds that play `role`, in referenceOrder().
std::vector<ItemKind> partKindsPlaying(PartRole role);
/// The docs' table of every kind and its keys (game/scene-format.md holds it; a test checks they agree).
std::string partKindsMarkdown();
/// `text` as a cell of a Markdown table: a '|' in it is escaped, since it would end the cell.
std::string markdownCell(std::string_view text);

} // namespace rube::game

/// Defines the descriptor of the kind in game/src/items/FILE.cpp (one line at the end of that file).
/// The build lists every file of game/src/items/ in a generated parts_list.cpp that calls each
/// rubePart_FILE(), so no descriptor is left out by the linker (see game/CMakeLists.txt).
#define RUBE_PART(FILE, KIND)                                                                                          \
    ::rube::game::ItemKind rubePart_##FILE() {                                                                         \
        static const KIND kind;                                                                                        \
        return &kind;                                                                                                  \
    }
