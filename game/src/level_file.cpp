// Level files: the tables a level adds to a scene, [[item]], [inventory], [[zone]] and [goal],
// read by the same TableReader as every other table so that errors look the same everywhere.
#include "scene_reading.hpp"

#include <numbers>

namespace rube::game {

namespace {

constexpr std::string_view kBallKeys[] = {"kind", "name", "position", "radius", "velocity"};
constexpr std::string_view kBoardKeys[] = {"kind", "name", "position", "angle", "length"};
constexpr std::string_view kRoundKeys[] = {"kind", "name", "position", "radius"};
constexpr std::string_view kCannonKeys[] = {"kind", "name", "position", "angle", "speed", "ammo", "fire_at"};
constexpr std::string_view kBombKeys[] = {"kind", "name", "position", "radius", "blast_radius", "strength", "trigger", "fuse"};
constexpr std::string_view kTargetKeys[] = {"kind", "name", "position", "radius", "path"};
constexpr std::string_view kBucketKeys[] = {"kind", "name", "position", "width", "height"};
constexpr std::string_view kSwitchKeys[] = {"kind", "name", "position", "radius", "triggers"};
constexpr std::string_view kMagnetKeys[] = {"kind", "name", "position", "radius", "strength", "reach", "on"};
constexpr std::string_view kFanKeys[] = {"kind", "name", "position", "angle", "width", "speed", "reach", "on"};
constexpr std::string_view kRocketKeys[] = {"kind", "name", "position", "radius", "velocity", "angle", "thrust", "burn", "on"};
constexpr std::string_view kZoneKeys[] = {"min", "max"};
constexpr std::string_view kGoalKeys[] = {"text", "condition", "target", "bucket", "time_limit"};
constexpr std::string_view kTriggerNames[] = {"timer", "impact", "switch"};
constexpr std::string_view kConditionNames[] = {"target-hit", "ball-in-bucket", "all-targets"};
constexpr std::string_view kBallNames[] = {"heavy", "bouncy", "steel", "balloon"};

// A single item beyond this size is a typo for another unit, not a part of a puzzle.
constexpr double kMaxItemSize = 100.0;

std::span<const std::string_view> keysOf(ItemKind kind) {
    switch (kind) {
    case ItemKind::plank:
    case ItemKind::ramp: return kBoardKeys;
    case ItemKind::bumper: return kRoundKeys;
    case ItemKind::cannon: return kCannonKeys;
    case ItemKind::bomb: return kBombKeys;
    case ItemKind::target: return kTargetKeys;
    case ItemKind::bucket: return kBucketKeys;
    case ItemKind::switchItem: return kSwitchKeys;
    case ItemKind::magnet: return kMagnetKeys;
    case ItemKind::fan: return kFanKeys;
    case ItemKind::rocket: return kRocketKeys;
    default: return kBallKeys;
    }
}

std::vector<std::string_view> kindNames() {
    std::vector<std::string_view> names;
    for (ItemKind kind : kAllItemKinds) names.push_back(itemKindName(kind));
    return names;
}

// The kind decides which keys an item may hold, so it is read before the table's keys are checked.
std::optional<ItemKind> readKind(const toml::table& table, Diagnostics& diag) {
    const toml::node* node = table.get("kind");
    const auto names = kindNames();
    if (!node) {
        diag.error(placeOf(table.source()), "missing required key 'kind' in [[item]] (one of " + joinNames(names) + ")");
        return std::nullopt;
    }
    const auto* text = node->as_string();
    if (!text) {
        diag.error(placeOf(node->source()), "kind must be a string, got " + std::string(typeName(*node)));
        return std::nullopt;
    }
    for (ItemKind kind : kAllItemKinds)
        if (itemKindName(kind) == text->get()) return kind;
    std::string message = "kind must be one of " + joinNames(names) + ", got '" + text->get() + "'";
    if (const auto match = closestMatch(text->get(), names)) message += " (did you mean '" + std::string(*match) + "'?)";
    diag.error(placeOf(node->source()), std::move(message));
    return std::nullopt;
}

const NumberRange kSizeRange{0.0, kMaxItemSize, true};

void readKindFields(TableReader& table, ItemDesc& item, SceneReading& reading) {
    switch (item.kind) {
    case ItemKind::plank:
    case ItemKind::ramp:
        if (const auto a = table.number("angle", NumberRange{-360.0, 360.0})) item.angle = *a * std::numbers::pi / 180.0;
        if (const auto l = table.number("length", kSizeRange)) item.size = *l;
        break;
    case ItemKind::cannon: {
        if (const auto a = table.number("angle", NumberRange{-360.0, 360.0})) item.angle = *a * std::numbers::pi / 180.0;
        if (const auto s = table.number("speed", NumberRange{0.0, 1000.0, true})) item.speed = *s;
        if (const auto ammo = table.choice("ammo", kBallNames)) item.ammo = kAllItemKinds[*ammo];
        if (const auto t = table.number("fire_at", NumberRange::nonNegative())) item.fireAt = *t;
        break;
    }
    case ItemKind::bomb: {
        if (const auto r = table.number("radius", kSizeRange)) item.size = *r;
        if (const auto r = table.number("blast_radius", kSizeRange)) item.blastRadius = *r;
        if (const auto s = table.number("strength", NumberRange{0.0, 10000.0, true})) item.strength = *s;
        const auto trigger = table.choice("trigger", kTriggerNames);
        if (trigger) item.trigger = static_cast<Trigger>(*trigger);
        const auto fuse = table.number("fuse", NumberRange::nonNegative());
        if (fuse) item.fuse = *fuse;
        // A timer with no fuse would go off at an arbitrary default time the author never chose.
        if (item.trigger == Trigger::timer && !fuse && trigger)
            table.error(table.valuePlace("trigger"), "a bomb with trigger 'timer' needs fuse = seconds");
        else if (fuse && item.trigger != Trigger::timer)
            table.error(table.valuePlace("fuse"), "fuse is only for trigger = \"timer\"");
        break;
    }
    case ItemKind::target:
        if (const auto r = table.number("radius", kSizeRange)) item.size = *r;
        if (const auto path = readPathReference(table, reading)) item.path = *path;
        break;
    case ItemKind::bucket:
        if (const auto w = table.number("width", kSizeRange)) item.size = *w;
        if (const auto h = table.number("height", kSizeRange)) item.height = *h;
        break;
    case ItemKind::switchItem:
        if (const auto r = table.number("radius", kSizeRange)) item.size = *r;
        item.triggers = table.string("triggers", Need::required).value_or("");
        break;
    case ItemKind::magnet:
        if (const auto r = table.number("radius", kSizeRange)) item.size = *r;
        if (const auto s = table.number("strength", NumberRange{0.0, 10000.0, true})) item.strength = *s;
        if (const auto r = table.number("reach", kSizeRange)) item.reach = *r;
        if (const auto on = table.boolean("on")) item.on = *on;
        break;
    case ItemKind::fan:
        if (const auto a = table.number("angle", NumberRange{-360.0, 360.0})) item.angle = *a * std::numbers::pi / 180.0;
        if (const auto w = table.number("width", kSizeRange)) item.size = *w;
        if (const auto s = table.number("speed", NumberRange{0.0, 100.0, true})) item.speed = *s;
        if (const auto r = table.number("reach", kSizeRange)) item.reach = *r;
        if (const auto on = table.boolean("on")) item.on = *on;
        break;
    case ItemKind::rocket:
        if (const auto r = table.number("radius", kSizeRange)) item.size = *r;
        if (const auto v = table.vec2("velocity")) item.velocity = *v;
        if (const auto a = table.number("angle", NumberRange{-360.0, 360.0})) item.angle = *a * std::numbers::pi / 180.0;
        if (const auto f = table.number("thrust", NumberRange{0.0, 10000.0, true})) item.thrust = *f;
        if (const auto t = table.number("burn", NumberRange{0.0, 1000.0, true})) item.burn = *t;
        if (const auto on = table.boolean("on")) item.on = *on;
        break;
    default: // balls and bumpers
        if (const auto r = table.number("radius", kSizeRange)) item.size = *r;
        if (isBall(item.kind))
            if (const auto v = table.vec2("velocity")) item.velocity = *v;
        break;
    }
}

void readItem(const toml::table& table, SceneReading& reading) {
    const auto kind = readKind(table, reading.diag);
    if (!kind) return;
    TableReader reader(table, "in [[item]] of kind '" + std::string(itemKindName(*kind)) + "'", keysOf(*kind), reading.diag);
    // Cannons, targets, buckets and switches are what goals and scripts point at: they need a name.
    const bool named = *kind == ItemKind::cannon || *kind == ItemKind::target || *kind == ItemKind::bucket;
    const std::string name = readBodyName(reader, reading, named ? Need::required : Need::optional);
    const auto position = reader.vec2("position", NumberRange::coordinate(), Need::required);
    ItemDesc item = defaultItem(*kind, position.value_or(Vec2{}));
    item.name = name;
    item.place = reader.tablePlace();
    readKindFields(reader, item, reading);
    reading.scene.level.items.push_back(item);
}

void readInventory(TableReader& root, SceneReading& reading) {
    const toml::table* table = root.table("inventory", "[inventory] with kind = count");
    if (!table) return;
    std::vector<std::string_view> placeable;
    for (ItemKind kind : kAllItemKinds)
        if (isPlaceable(kind)) placeable.push_back(itemKindName(kind));
    TableReader inventory(*table, "in [inventory] (placeable kinds)", placeable, reading.diag);
    for (std::string_view kind : placeable)
        if (const auto n = inventory.integer(kind, 0, 1000)) reading.scene.level.inventory[std::string(kind)] = static_cast<int>(*n);
}

void readZones(TableReader& root, SceneReading& reading) {
    for (const toml::table* table : root.arrayOfTables("zone")) {
        TableReader zone(*table, "in [[zone]]", kZoneKeys, reading.diag);
        const auto min = zone.vec2("min", Need::required);
        const auto max = zone.vec2("max", Need::required);
        if (!min || !max) continue;
        if (!(min->x < max->x && min->y < max->y)) {
            zone.error(zone.valuePlace("max"), "zone max must be greater than min in both x and y, got min " +
                                                   formatPair(min->x, min->y) + " and max " + formatPair(max->x, max->y));
            continue;
        }
        reading.scene.level.zones.push_back({Aabb{*min, *max}, zone.tablePlace()});
    }
}

// A name must refer to an item of the right kind; the message lists the ones that would do.
void checkReference(Diagnostics& diag, SourcePlace place, std::string_view key, const std::string& name,
                    std::initializer_list<ItemKind> kinds, const LevelDesc& level) {
    if (std::string message = itemReferenceError(level, key, name, kinds); !message.empty()) diag.error(place, std::move(message));
}

void readGoal(TableReader& root, SceneReading& reading) {
    const toml::table* table = root.table("goal", "[goal] with text and condition");
    if (!table) return;
    TableReader goal(*table, "in [goal]", kGoalKeys, reading.diag);
    Goal result;
    result.text = goal.string("text", Need::required).value_or("");
    const auto condition = goal.choice("condition", kConditionNames, Need::required);
    if (condition) result.kind = static_cast<GoalKind>(*condition);
    if (const auto t = goal.number("time_limit", NumberRange::positive())) result.timeLimit = *t;
    const LevelDesc& level = reading.scene.level;
    if (condition && result.kind == GoalKind::targetHit) {
        if (const auto name = goal.string("target", Need::required)) {
            result.item = *name;
            checkReference(reading.diag, goal.valuePlace("target"), "target", *name, {ItemKind::target}, level);
        }
    } else if (condition && result.kind == GoalKind::ballInBucket) {
        if (const auto name = goal.string("bucket", Need::required)) {
            result.item = *name;
            checkReference(reading.diag, goal.valuePlace("bucket"), "bucket", *name, {ItemKind::bucket}, level);
        }
    } else if (condition) {
        bool any = false;
        for (const ItemDesc& item : level.items) any = any || item.kind == ItemKind::target;
        if (!any) goal.error(goal.valuePlace("condition"), "condition 'all-targets' needs at least one [[item]] of kind 'target'");
    }
    reading.scene.level.goal = result;
}

} // namespace

std::string readBodyName(TableReader& table, SceneReading& reading, Need need) {
    const auto name = table.string("name", need);
    if (!name) return "";
    if (name->empty()) {
        table.error(table.valuePlace("name"), "name must not be empty");
        return "";
    }
    if (const auto it = reading.names.find(*name); it != reading.names.end()) {
        table.error(table.valuePlace("name"), "the name '" + *name + "' is already used at line " +
                                                  std::to_string(it->second.line));
        return "";
    }
    reading.names[*name] = table.valuePlace("name");
    return *name;
}

void readLevel(TableReader& root, SceneReading& reading) {
    for (const toml::table* table : root.arrayOfTables("item")) readItem(*table, reading);
    readInventory(root, reading);
    readZones(root, reading);
    readGoal(root, reading);
    // Switch references are checked once every item is known, so a switch may name a later cannon.
    const auto items = root.arrayOfTables("item");
    std::size_t next = 0;
    for (const toml::table* table : items) {
        const toml::node* kind = table->get("kind");
        if (!kind || !kind->is_string() || kind->as_string()->get() != "switch") continue;
        while (next < reading.scene.level.items.size() && reading.scene.level.items[next].kind != ItemKind::switchItem) ++next;
        if (next >= reading.scene.level.items.size()) break;
        const std::string& target = reading.scene.level.items[next++].triggers;
        if (target.empty() || reading.scene.findRope(target) >= 0) continue; // a switch may cut a named [[rope]]
        const toml::node* node = table->get("triggers");
        checkReference(reading.diag, node ? placeOf(node->source()) : placeOf(table->source()), "triggers", target,
                       {ItemKind::cannon, ItemKind::bomb, ItemKind::fan, ItemKind::magnet, ItemKind::rocket}, reading.scene.level);
    }
}

} // namespace rube::game
