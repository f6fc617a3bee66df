// Level files: the tables a level adds to a scene, [[item]], [inventory], [[zone]] and [goal],
// read by the same TableReader as every other table so that errors look the same everywhere.
#include "scene_file.hpp"
#include "scene_reading.hpp"
#include "toml_writer.hpp"

#include <algorithm>
#include <array>
#include <numbers>

namespace rube::game {

namespace {

constexpr std::string_view kBoxKeys[] = {"min", "max"}; // a zone's, and a reach-area goal's area
constexpr std::string_view kHintKeys[] = {"text"};
constexpr std::string_view kGoalKeys[] = {"text", "condition", "target", "bucket", "item", "area", "time_limit"};
constexpr std::string_view kConditionNames[] = {"target-hit", "ball-in-bucket", "all-targets", "reach-area"};
/// The keys each condition takes besides text, condition and time_limit (in GoalKind order).
constexpr std::array<std::array<std::string_view, 2>, 4> kConditionKeys{{{"target"}, {"bucket"}, {}, {"item", "area"}}};

// The keys a kind's [[item]] may hold, as its descriptor lists them.
std::vector<std::string_view> keysOf(ItemKind kind) {
    std::vector<std::string_view> keys;
    for (const PartKey& key : kind->keys()) keys.push_back(key.key);
    return keys;
}

std::vector<std::string_view> kindNames() {
    std::vector<std::string_view> names;
    for (ItemKind kind : allPartKinds()) names.push_back(kind->name());
    return names;
}

// The kind decides which keys an item may hold, so it is read before the table's keys are checked.
std::optional<ItemKind> readKind(const toml::table& table, Diagnostics& diag) {
    const toml::node* node = table.get("kind");
    const auto names = kindNames();
    if (!node) {
        diag.error(placeOf(table.source()),
                   "missing required key 'kind' in [[item]] (one of " + joinNames(names) + ")");
        return std::nullopt;
    }
    const auto* text = node->as_string();
    if (!text) {
        diag.error(placeOf(node->source()), "kind must be a string, got " + std::string(typeName(*node)));
        return std::nullopt;
    }
    if (const ItemKind kind = findPartKind(text->get())) return kind;
    std::string message = "kind must be one of " + joinNames(names) + ", got '" + text->get() + "'";
    if (const auto match = closestMatch(text->get(), names))
        message += " (did you mean '" + std::string(*match) + "'?)";
    diag.error(placeOf(node->source()), std::move(message));
    return std::nullopt;
}

void readItem(const toml::table& table, SceneReading& reading) {
    const auto kind = readKind(table, reading.diag);
    if (!kind) return;
    TableReader reader(table, "in [[item]] of kind '" + std::string((*kind)->name()) + "'", keysOf(*kind),
                       reading.diag);
    // What goals and scripts point at needs a name: the kind says whether it is one.
    const std::string name = readBodyName(reader, reading, (*kind)->needsName() ? Need::required : Need::optional);
    const auto position = reader.vec2("position", NumberRange::coordinate(), Need::required);
    ItemDesc item = (*kind)->make(position.value_or(Vec2{}));
    item.name = name;
    item.place = reader.tablePlace();
    (*kind)->read(reader, item, reading);
    // What the level writer needs to write the item back as it was read.
    if (const toml::node* angle = table.get("angle"); angle && (angle->is_integer() || angle->is_floating_point()))
        item.angleDegrees = angle->value<double>();
    for (const auto& [key, value] : table) {
        if (key == "kind" || key == "name" || key == "position" || key == "angle") continue;
        item.ownLines.push_back(std::string(key.str()) + " = " + tomlValue(value));
    }
    reading.scene.level.items.push_back(item);
}

void readInventory(TableReader& root, SceneReading& reading) {
    const toml::table* table = root.table("inventory", "[inventory] with kind = count");
    if (!table) return;
    std::vector<std::string_view> placeable;
    for (ItemKind kind : allPartKinds())
        if (kind->placeable()) placeable.push_back(kind->name());
    TableReader inventory(*table, "in [inventory] (placeable kinds)", placeable, reading.diag);
    for (std::string_view kind : placeable)
        if (const auto n = inventory.integer(kind, 0, 1000))
            reading.scene.level.inventory[std::string(kind)] = static_cast<int>(*n);
}

void readZones(TableReader& root, SceneReading& reading) {
    for (const toml::table* table : root.arrayOfTables("zone")) {
        TableReader zone(*table, "in [[zone]]", kBoxKeys, reading.diag);
        if (const auto box = readBox(zone, "zone")) reading.scene.level.zones.push_back({*box, zone.tablePlace()});
    }
}

// Hints, in the order the player is shown them (H in the play window).
void readHints(TableReader& root, SceneReading& reading) {
    for (const toml::table* table : root.arrayOfTables("hint")) {
        TableReader hint(*table, "in [[hint]]", kHintKeys, reading.diag);
        const auto text = hint.string("text", Need::required);
        if (!text) continue;
        if (text->find_first_not_of(" \t\n") == std::string::npos) {
            hint.error(hint.valuePlace("text"), "a hint's text must not be empty");
            continue;
        }
        reading.scene.level.hints.push_back({*text, hint.tablePlace()});
    }
}

// A name must refer to an item of the right kind; the message lists the ones that would do.
void checkReference(Diagnostics& diag, SourcePlace place, std::string_view key, const std::string& name, PartRole role,
                    const LevelDesc& level) {
    if (std::string message = itemReferenceError(level, key, name, role); !message.empty())
        diag.error(place, std::move(message));
}

// A key that another condition takes is an error, not ignored: `bucket` under target-hit says so.
void refuseOtherConditionsKeys(TableReader& goal, GoalKind kind) {
    const auto& own = kConditionKeys[static_cast<std::size_t>(kind)];
    std::string takes; // "target", "item and area"
    for (std::string_view key : own)
        if (!key.empty()) takes += (takes.empty() ? "" : " and ") + std::string(key);
    for (const auto& keys : kConditionKeys)
        for (std::string_view key : keys)
            if (!key.empty() && goal.find(key) && std::find(own.begin(), own.end(), key) == own.end())
                goal.error(goal.valuePlace(key), "condition '" + std::string(conditionName(kind)) + "' takes no '" +
                                                     std::string(key) + "' (" +
                                                     (takes.empty() ? "it takes no item" : "it takes " + takes) + ")");
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
    if (condition) refuseOtherConditionsKeys(goal, result.kind);
    if (condition && result.kind == GoalKind::targetHit) {
        if (const auto name = goal.string("target", Need::required)) {
            result.item = *name;
            checkReference(reading.diag, goal.valuePlace("target"), "target", *name, PartRole::goalTarget, level);
        }
    } else if (condition && result.kind == GoalKind::ballInBucket) {
        if (const auto name = goal.string("bucket", Need::required)) {
            result.item = *name;
            checkReference(reading.diag, goal.valuePlace("bucket"), "bucket", *name, PartRole::goalBucket, level);
        }
    } else if (condition && result.kind == GoalKind::reachArea) {
        // The item whose centre must come into the area; without one, any ball (a placed one, a shot).
        if (const auto name = goal.string("item")) {
            result.item = *name;
            checkReference(reading.diag, goal.valuePlace("item"), "item", *name, PartRole::goalMover, level);
        }
        if (const toml::table* area = goal.table("area", "{ min = [x, y], max = [x, y] }", Need::required)) {
            TableReader box(*area, "in goal.area", kBoxKeys, reading.diag);
            if (const auto read = readBox(box, "area")) result.area = *read;
        }
    } else if (condition) {
        bool any = false;
        for (const ItemDesc& item : level.items) any = any || item.kind->plays(PartRole::goalTarget);
        if (!any)
            goal.error(goal.valuePlace("condition"),
                       "condition 'all-targets' needs at least one [[item]] of kind 'target'");
    }
    reading.scene.level.goal = result;
}

} // namespace

std::string_view conditionName(GoalKind kind) { return kConditionNames[static_cast<std::size_t>(kind)]; }

std::string readBodyName(TableReader& table, SceneReading& reading, Need need) {
    const auto name = table.string("name", need);
    if (!name) return "";
    if (name->empty()) {
        table.error(table.valuePlace("name"), "name must not be empty");
        return "";
    }
    if (const auto it = reading.names.find(*name); it != reading.names.end()) {
        table.error(table.valuePlace("name"),
                    "the name '" + *name + "' is already used at line " + std::to_string(it->second.line));
        return "";
    }
    reading.names[*name] = table.valuePlace("name");
    return *name;
}

// `clicks`: names of fixed items a click acts on (their kind has a click action).
void readClicks(TableReader& root, SceneReading& reading) {
    const toml::node* node = root.find("clicks");
    if (!node) return;
    const toml::array* array = node->as_array();
    if (!array) {
        root.error(root.valuePlace("clicks"),
                   "clicks must be an array of item names, got " + std::string(typeName(*node)));
        return;
    }
    const LevelDesc& level = reading.scene.level;
    std::vector<std::string_view> usable;
    for (const ItemDesc& item : level.items)
        if (item.kind->clickAction() && !item.name.empty()) usable.push_back(item.name);
    std::vector<std::string> names;
    for (const toml::node& element : *array) {
        const auto* name = element.as_string();
        const SourcePlace place = placeOf(element.source());
        if (!name) {
            reading.diag.error(place, "clicks must hold item names (strings), got " + std::string(typeName(element)));
            continue;
        }
        if (std::find(usable.begin(), usable.end(), name->get()) == usable.end()) {
            const int item = level.find(name->get());
            reading.diag.error(
                place, item < 0 ? "unknown item '" + name->get() + "' in clicks" +
                                      unknownNameHint(name->get(), usable, "a click acts on",
                                                      "the level has no part a click acts on")
                                : "clicks names '" + name->get() + "', a " +
                                      std::string(itemKindName(level.items[static_cast<std::size_t>(item)].kind)) +
                                      ", which no click acts on");
            continue;
        }
        names.push_back(name->get());
    }
    reading.scene.level.clicks = std::move(names);
}

// The editor's check of a part's own keys: the reader's own readItem and checkReferences, among the
// level's other items (references to them resolve, and their names stay taken).
ItemLoad readItemAgain(const SceneDesc& level, std::size_t index, std::string_view itemToml) {
    Diagnostics diag(level.name);
    const std::optional<toml::table> parsed = parseToml(itemToml, level.name, diag);
    const toml::array* items = parsed ? (*parsed)["item"].as_array() : nullptr;
    const toml::table* table = items && items->size() == 1 ? items->get(0)->as_table() : nullptr;
    if (!table) {
        if (diag.empty()) diag.error({1, 1}, "one [[item]] table was expected");
        return {std::nullopt, diag.sorted()};
    }
    SceneDesc scene = level;
    scene.level.items.erase(scene.level.items.begin() + static_cast<std::ptrdiff_t>(index));
    SceneReading reading{diag, scene, {}, {}};
    for (std::size_t i = 0; i < scene.paths.size(); ++i) reading.pathIndex[scene.paths[i].name] = static_cast<int>(i);
    for (const ItemDesc& other : scene.level.items)
        if (!other.name.empty()) reading.names[other.name] = other.place;
    readItem(*table, reading);
    if (diag.empty() && scene.level.items.size() == level.level.items.size())
        scene.level.items.back().kind->checkReferences(scene.level.items.back(), reading);
    if (!diag.empty()) return {std::nullopt, diag.sorted()};
    return {scene.level.items.back(), {}};
}

void readLevel(TableReader& root, SceneReading& reading) {
    for (const toml::table* table : root.arrayOfTables("item")) readItem(*table, reading);
    readClicks(root, reading);
    readInventory(root, reading);
    readZones(root, reading);
    readGoal(root, reading);
    readHints(root, reading);
    // References between items (a switch's `triggers`) are checked once every item is known, so a
    // switch may name a later cannon.
    for (const ItemDesc& item : reading.scene.level.items) item.kind->checkReferences(item, reading);
}

} // namespace rube::game
