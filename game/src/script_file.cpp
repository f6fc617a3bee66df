// Script files: read with the scene's TableReader, so their errors read like a level's, and
// checked against the level they play (names, kinds, and the placement rules).
#include "script_file.hpp"

#include "scene_reading.hpp"
#include "toml_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

namespace rube::game {

namespace {

constexpr std::string_view kTopKeys[] = {"level", "steps", "capture", "place", "action", "expect"};
constexpr std::string_view kCaptureKeys[] = {"size", "every"};
constexpr std::string_view kPlaceKeys[] = {"kind", "position", "angle", "name"};
constexpr std::string_view kDoNames[] = {"rotate", "aim", "fire", "detonate", "toggle", "fire-when", "cut"};
constexpr std::string_view kRotateKeys[] = {"step", "do", "item", "angle"};
constexpr std::string_view kAimKeys[] = {"step", "do", "item", "angle", "point", "target", "arc"};
constexpr std::string_view kItemKeys[] = {"step", "do", "item"};
constexpr std::string_view kFireWhenKeys[] = {"step", "do", "item", "target"};
constexpr std::string_view kExpectKeys[] = {"goal", "hit", "shot", "explosion", "by", "before_step"};
// Issue 23: a step is a simulation step, a frame a written picture; scripts said "frame" for steps.
constexpr KeyRename kActionRenames[] = {{"frame", "step"}};
constexpr KeyRename kExpectRenames[] = {{"before_frame", "before_step"}};
constexpr std::string_view kArcNames[] = {"low", "high"};
// The longest run a script may ask for: an hour at 60 steps a second.
constexpr std::int64_t kMaxSteps = 216'000;

// The item an action or expectation names must exist and be of the kind it acts on.
bool checkItem(TableReader& table, std::string_view key, const std::string& name, const SceneDesc& level,
               PartRole role) {
    std::string message = itemReferenceError(level.level, key, name, role, " in level '" + level.name + "'");
    if (message.empty()) return true;
    table.error(table.valuePlace(key), std::move(message));
    return false;
}

// An expectation's `by` names a ball: an item or placement (a cannon for its shots), or a named [[circle]].
void checkStriker(TableReader& expect, const std::string& name, const SceneDesc& level) {
    std::vector<std::string_view> names;
    for (const ItemDesc& item : level.level.items)
        if (!item.name.empty()) names.push_back(item.name);
    for (const std::string& circle : level.circleNames)
        if (!circle.empty()) names.push_back(circle);
    for (const std::string& body : level.bodyNames)
        if (!body.empty()) names.push_back(body);
    if (std::find(names.begin(), names.end(), name) != names.end()) return;
    expect.error(expect.valuePlace("by"), "unknown item, circle or body '" + name + "' in level '" + level.name + "'" +
                                              unknownNameHint(name, names, "the level has", "the level names nothing"));
}

// A click's action (fire, detonate, toggle, fire-when) on a part the level's `clicks` leave out.
void checkClickable(TableReader& table, const std::string& name, const SceneDesc& level) {
    if (level.level.clickable(name) || level.level.find(name) < 0) return;
    std::string allowed;
    for (const std::string& click : *level.level.clicks) allowed += (allowed.empty() ? "" : ", ") + click;
    table.error(table.valuePlace("item"), "level '" + level.name + "' lets no click act on '" + name +
                                              "' (its clicks: " + (allowed.empty() ? "none" : allowed) + ")");
}

void readCapture(TableReader& root, ScriptDesc& script) {
    const toml::table* table = root.table("capture", "[capture] with size and every");
    if (!table) return;
    TableReader capture(*table, "in [capture]", kCaptureKeys, root.diagnostics());
    if (const toml::node* node = capture.find("size")) {
        const auto* array = node->as_array();
        const bool ok = array && array->size() == 2 && array->get(0)->is_integer() && array->get(1)->is_integer();
        const auto w = ok ? array->get(0)->as_integer()->get() : 0;
        const auto h = ok ? array->get(1)->as_integer()->get() : 0;
        if (!ok || w < 1 || h < 1 || w > 8192 || h > 8192)
            capture.error(placeOf(node->source()), "size must be [width, height] in whole pixels, each 1 to 8192");
        else script.size = render::FrameSize{static_cast<int>(w), static_cast<int>(h)};
    }
    script.every = capture.integer("every", 1, 10'000);
}

std::string tomlString(std::string_view text); // below, with the writer

// The TOML text of a value as the file wrote it: a string quoted as the writer quotes names, a
// number or array as TOML prints them.
std::string tomlText(const toml::node& node) {
    if (const auto* text = node.as_string()) return tomlString(text->get());
    std::ostringstream out;
    node.visit([&](const auto& value) { out << value; });
    return out.str();
}

// A [[place]] table's keys: its own, and once its kind is known the kind's own keys, which it may
// give as a level's [[item]] does (a plank's length, a bomb's trigger and fuse).
std::vector<std::string_view> placeKeys(const toml::table& table) {
    std::vector<std::string_view> keys(std::begin(kPlaceKeys), std::end(kPlaceKeys));
    const toml::node* kind = table.get("kind");
    const ItemKind named = kind && kind->is_string() ? findPartKind(kind->as_string()->get()) : nullptr;
    if (named && named->placeable())
        for (const PartKey& key : named->keys())
            if (std::find(keys.begin(), keys.end(), key.key) == keys.end()) keys.push_back(key.key);
    return keys;
}

// A placement's name must be new: actions and expectations find placed items by it, as level items.
void checkPlacedName(TableReader& place, const Placement& p, const SceneDesc& level, const ScriptDesc& script) {
    if (p.name.empty()) return;
    if (level.level.find(p.name) >= 0) {
        place.error(place.valuePlace("name"),
                    "name '" + p.name + "' is taken by an item of level '" + level.name + "'");
        return;
    }
    for (const Placement& earlier : script.placements)
        if (earlier.name == p.name)
            place.error(place.valuePlace("name"), "name '" + p.name + "' is taken by the placement at line " +
                                                      std::to_string(earlier.place.line));
}

void readPlacements(TableReader& root, const SceneDesc& level, ScriptDesc& script) {
    std::vector<std::string_view> placeable;
    for (ItemKind kind : allPartKinds())
        if (kind->placeable()) placeable.push_back(kind->name());
    for (const toml::table* table : root.arrayOfTables("place")) {
        const std::vector<std::string_view> keys = placeKeys(*table);
        TableReader place(*table, "in [[place]]", keys, root.diagnostics());
        Placement p;
        const auto kind = place.choice("kind", placeable, Need::required);
        const auto position = place.vec2("position", Need::required);
        if (const auto a = place.number("angle", NumberRange{-360.0, 360.0})) {
            p.angleDegrees = *a;
            p.angle = scriptRadians(*a);
        }
        p.name = place.string("name").value_or("");
        p.place = place.tablePlace();
        if (!kind || !position) continue;
        p.kind = partKind(placeable[*kind]);
        p.position = *position;
        checkPlacedName(place, p, level, script);
        // A TOML table iterates in key order; the file's order is the one to write back.
        std::vector<std::pair<toml::source_position, std::pair<std::string, std::string>>> own;
        for (const auto& [key, value] : *table)
            if (std::find(std::begin(kPlaceKeys), std::end(kPlaceKeys), key.str()) == std::end(kPlaceKeys))
                own.push_back({key.source().begin, {std::string(key.str()), tomlText(value)}});
        std::sort(own.begin(), own.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (auto& entry : own) p.ownKeys.push_back(std::move(entry.second));
        if (!p.ownKeys.empty()) {
            // The kind reads its own keys, with its own ranges and rules, as in a level's [[item]].
            SceneDesc scratch;
            SceneReading reading{root.diagnostics(), scratch, {}, {}};
            ItemDesc item = p.kind->make(p.position);
            p.kind->read(place, item, reading);
            p.params = item.params;
        }
        script.placements.push_back(p);
    }
}

void readAction(const toml::table& table, Diagnostics& diag, const SceneDesc& level, ScriptDesc& script) {
    // The verb decides the keys; read it first, as a level's [[item]] reads its kind.
    const toml::node* verb = table.get("do");
    std::size_t index = std::size(kDoNames);
    if (verb && verb->is_string())
        for (std::size_t i = 0; i < std::size(kDoNames); ++i)
            if (kDoNames[i] == verb->as_string()->get()) index = i;
    const ActionKind kind = index < std::size(kDoNames) ? static_cast<ActionKind>(index) : ActionKind::fire;
    const std::span<const std::string_view> keys = kind == ActionKind::rotate
                                                       ? std::span<const std::string_view>(kRotateKeys)
                                                   : kind == ActionKind::aim
                                                       ? std::span<const std::string_view>(kAimKeys)
                                                   : kind == ActionKind::fireWhen
                                                       ? std::span<const std::string_view>(kFireWhenKeys)
                                                       : std::span<const std::string_view>(kItemKeys);
    TableReader action(table, "in [[action]]",
                       index < std::size(kDoNames) ? keys : std::span<const std::string_view>(kAimKeys), diag, {}, {},
                       kActionRenames);
    if (!action.choice("do", kDoNames, Need::required)) return;
    Action a;
    a.kind = kind;
    a.place = action.tablePlace();
    a.step = action.integer("step", 0, kMaxSteps, Need::required).value_or(0);
    // A script reads as a timeline: an action listed after a later one is almost always a slip
    // (a step number typed wrong), and taking it silently would play something else.
    if (!script.actions.empty() && a.step < script.actions.back().step)
        action.error(action.valuePlace("step"), "actions must be listed in step order: step " + std::to_string(a.step) +
                                                    " comes after step " + std::to_string(script.actions.back().step) +
                                                    " (line " + std::to_string(script.actions.back().place.line) + ")");
    a.item = action.string("item", Need::required).value_or("");
    if (a.item.empty()) return;
    switch (kind) {
    case ActionKind::rotate:
        checkItem(action, "item", a.item, level, PartRole::fire);
        if (const auto angle = action.number("angle", NumberRange{-360.0, 360.0}, Need::required)) {
            a.angleDegrees = *angle;
            a.angle = scriptRadians(*angle);
        }
        break;
    case ActionKind::aim: {
        checkItem(action, "item", a.item, level, PartRole::fire);
        if (const auto angle = action.number("angle", NumberRange{-360.0, 360.0})) {
            a.angleDegrees = *angle;
            a.angle = scriptRadians(*angle);
        }
        a.point = action.vec2("point");
        a.target = action.string("target").value_or("");
        if (const auto arc = action.choice("arc", kArcNames)) a.highArc = *arc == 1;
        const int ways = (action.find("angle") ? 1 : 0) + (action.find("point") ? 1 : 0) +
                         (action.find("target") ? 1 : 0);
        if (ways != 1)
            action.error(action.tablePlace(),
                         "an aim needs exactly one of angle, point or target, got " + std::to_string(ways));
        if (!a.target.empty()) checkItem(action, "target", a.target, level, PartRole::aimTarget);
        break;
    }
    case ActionKind::fire:
        if (checkItem(action, "item", a.item, level, PartRole::fire)) checkClickable(action, a.item, level);
        break;
    case ActionKind::detonate:
        if (checkItem(action, "item", a.item, level, PartRole::detonate)) checkClickable(action, a.item, level);
        break;
    case ActionKind::toggle:
        if (checkItem(action, "item", a.item, level, PartRole::toggle)) checkClickable(action, a.item, level);
        break;
    case ActionKind::cut:
        // Ropes are not items: they are the level's [[rope]] tables, named there.
        if (level.findRope(a.item) < 0) {
            std::vector<std::string_view> names;
            for (const std::string& name : level.ropeNames)
                if (!name.empty()) names.push_back(name);
            action.error(action.valuePlace("item"),
                         "unknown rope '" + a.item + "' in level '" + level.name + "'" +
                             unknownNameHint(a.item, names, "the level has", "the level has no named rope"));
        }
        break;
    case ActionKind::fireWhen:
        // The cannon keeps its aim; only the moment of firing is worked out, when the action is taken.
        if (checkItem(action, "item", a.item, level, PartRole::fire)) checkClickable(action, a.item, level);
        a.target = action.string("target", Need::required).value_or("");
        if (!a.target.empty()) checkItem(action, "target", a.target, level, PartRole::aimTarget);
        break;
    }
    script.actions.push_back(a);
}

void readExpectations(TableReader& root, const SceneDesc& level, ScriptDesc& script) {
    for (const toml::table* table : root.arrayOfTables("expect")) {
        TableReader expect(*table, "in [[expect]]", kExpectKeys, root.diagnostics(), {}, {}, kExpectRenames);
        Expectation e;
        e.place = expect.tablePlace();
        const auto before = expect.integer("before_step", 1, kMaxSteps, Need::required);
        const int ways = (expect.find("goal") ? 1 : 0) + (expect.find("hit") ? 1 : 0) + (expect.find("shot") ? 1 : 0) +
                         (expect.find("explosion") ? 1 : 0);
        if (ways != 1) {
            expect.error(e.place, "an expectation needs exactly one of goal = true, hit, shot or explosion, got " +
                                      std::to_string(ways));
            continue;
        }
        if (const auto goal = expect.boolean("goal")) {
            if (!*goal) expect.error(expect.valuePlace("goal"), "goal = false expects nothing; write goal = true");
            if (!level.level.goal) expect.error(expect.valuePlace("goal"), "level '" + level.name + "' has no [goal]");
            e.kind = EventKind::goal;
        } else if (const auto hit = expect.string("hit")) {
            e.kind = EventKind::hit;
            e.item = *hit;
            checkItem(expect, "hit", *hit, level, PartRole::hitReport);
        } else if (const auto shot = expect.string("shot")) {
            e.kind = EventKind::shot;
            e.item = *shot;
            checkItem(expect, "shot", *shot, level, PartRole::fire);
        } else if (const auto boom = expect.string("explosion")) {
            e.kind = EventKind::explosion;
            e.item = *boom;
            checkItem(expect, "explosion", *boom, level, PartRole::detonate);
        }
        if (const auto by = expect.string("by")) {
            e.by = *by;
            if (e.kind != EventKind::hit && e.kind != EventKind::goal)
                expect.error(expect.valuePlace("by"), std::string("by names what must hit or reach the goal; ") +
                                                          (e.kind == EventKind::shot ? "a shot" : "an explosion") +
                                                          " has no by");
            else checkStriker(expect, e.by, level);
        }
        if (before) e.beforeStep = *before;
        script.expectations.push_back(e);
    }
}

} // namespace

double scriptRadians(double degrees) { return degrees * std::numbers::pi / 180.0; }

std::string Expectation::describe() const {
    const std::string when = (by.empty() ? "" : " by '" + by + "'") + " before step " + std::to_string(beforeStep);
    switch (kind) {
    case EventKind::goal: return "goal reached" + when;
    case EventKind::hit: return "'" + item + "' hit" + when;
    case EventKind::shot: return "cannon '" + item + "' fired" + when;
    case EventKind::explosion: return "bomb '" + item + "' exploded" + when;
    }
    return "";
}

std::string_view actionVerb(ActionKind kind) { return kDoNames[static_cast<int>(kind)]; }

ScriptLoad parseScript(std::string_view text, const std::string& fileName, const SceneDesc& level) {
    Diagnostics diag(fileName);
    std::optional<toml::table> parsed = parseToml(text, fileName, diag);
    if (!parsed) return {std::nullopt, diag.sorted()};
    toml::table& document = *parsed;
    ScriptDesc script;
    TableReader root(document, "at the top level of a script", kTopKeys, diag);
    if (const auto name = root.string("level", Need::required)) {
        script.level = *name;
        if (*name != level.name)
            root.error(root.valuePlace("level"),
                       "this script plays level '" + *name + "', but the level given is '" + level.name + "'");
    }
    script.steps = root.integer("steps", 1, kMaxSteps);
    readCapture(root, script);
    readPlacements(root, level, script);
    // Actions and expectations may name placed items too: they join the level's items, after them,
    // as LevelRun adds them.
    SceneDesc placed = level;
    for (const Placement& p : script.placements)
        if (!p.name.empty()) placed.level.items.push_back(placedItem(p));
    for (const toml::table* table : root.arrayOfTables("action")) readAction(*table, diag, placed, script);
    readExpectations(root, placed, script);
    if (!diag.empty()) return {std::nullopt, diag.sorted()};
    // The rules of placement are checked last: they only make sense for a script that reads.
    for (const PlacementRefusal& refusal : placementRefusals(level, script.placements))
        diag.error(script.placements[refusal.index].place, refusal.message);
    if (!diag.empty()) return {std::nullopt, diag.sorted()};
    return {std::move(script), {}};
}

ScriptLoad loadScriptFile(const std::filesystem::path& file, const SceneDesc& level) {
    SceneError error;
    const std::optional<std::string> text = readTextFile(file, error);
    if (!text) return {std::nullopt, {error}};
    return parseScript(*text, file.string(), level);
}

// The writer: what the reader above reads, key for key, so that writing and reading back gives the
// same script (tests/script_file_test.cpp checks it on every shipped solution).

std::string scriptNumber(double value) {
    // -0 would read back as the integer 0 and lose the sign that a bit-for-bit replay keeps.
    if (value == 0.0 && std::signbit(value)) return "-0.0";
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

namespace {

// A TOML basic string: quotes and backslashes escaped, control characters as \uXXXX (TOML allows
// none of them raw), so any name the reader accepted is written back readable.
std::string tomlString(std::string_view text) {
    std::string out = "\"";
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (byte < 0x20 || byte == 0x7f) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", byte);
            out += escaped;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

void writePlacement(std::ostream& out, const Placement& p) {
    out << "\n[[place]]\nkind = \"" << itemKindName(p.kind) << "\"\nposition = [" << scriptNumber(p.position.x) << ", "
        << scriptNumber(p.position.y) << "]\n";
    if (p.angleDegrees != 0.0 || std::signbit(p.angleDegrees))
        out << "angle = " << scriptNumber(p.angleDegrees) << '\n';
    if (!p.name.empty()) out << "name = " << tomlString(p.name) << '\n';
    for (const auto& [key, value] : p.ownKeys) out << key << " = " << value << '\n';
}

void writeAction(std::ostream& out, const Action& a) {
    out << "\n[[action]]\nstep = " << a.step << "\ndo = \"" << actionVerb(a.kind) << "\"\nitem = " << tomlString(a.item)
        << '\n';
    if (a.angle) out << "angle = " << scriptNumber(a.angleDegrees) << '\n';
    if (a.point) out << "point = [" << scriptNumber(a.point->x) << ", " << scriptNumber(a.point->y) << "]\n";
    if (!a.target.empty()) out << "target = " << tomlString(a.target) << '\n';
    // An aim at a point or item names its arc; one at an angle only when it was given one.
    if (a.kind == ActionKind::aim && (!a.angle || a.highArc))
        out << "arc = \"" << (a.highArc ? "high" : "low") << "\"\n";
}

void writeExpectation(std::ostream& out, const Expectation& e) {
    out << "\n[[expect]]\n";
    switch (e.kind) {
    case EventKind::goal: out << "goal = true\n"; break;
    case EventKind::hit: out << "hit = " << tomlString(e.item) << '\n'; break;
    case EventKind::shot: out << "shot = " << tomlString(e.item) << '\n'; break;
    case EventKind::explosion: out << "explosion = " << tomlString(e.item) << '\n'; break;
    }
    if (!e.by.empty()) out << "by = " << tomlString(e.by) << '\n';
    out << "before_step = " << e.beforeStep << '\n';
}

} // namespace

std::string writeScript(const ScriptDesc& script, std::string_view header) {
    std::ostringstream out;
    out << header << "level = " << tomlString(script.level) << '\n';
    if (script.steps) out << "steps = " << *script.steps << '\n';
    if (script.size || script.every) {
        out << "\n[capture]\n";
        if (script.size) out << "size = [" << script.size->width << ", " << script.size->height << "]\n";
        if (script.every) out << "every = " << *script.every << '\n';
    }
    for (const Placement& p : script.placements) writePlacement(out, p);
    for (const Action& a : script.actions) writeAction(out, a);
    for (const Expectation& e : script.expectations) writeExpectation(out, e);
    return out.str();
}

} // namespace rube::game
