// The level writer: the level's own parts written line by line with numbers in their shortest exact
// form (scriptNumber: 0.2, not 0.20000000000000001) and strings quoted by toml++, then the physics
// tables as read, printed by toml++'s formatter.
#include "level_writer.hpp"

#include "script_file.hpp"
#include "toml_writer.hpp"

#include <numbers>

namespace rube::game {

namespace {

std::string quoted(const std::string& text) { return tomlQuoted(text); }

// Strings are built by appending: GCC 12 warns (-Wrestrict, wrongly) at "literal" + std::string.
std::string pair(Vec2 v) {
    std::string text = "[";
    text += scriptNumber(v.x);
    text += ", ";
    text += scriptNumber(v.y);
    return text += "]";
}

void line(std::string& out, std::string_view key, const std::string& value) {
    out += key;
    out += " = ";
    out += value;
    out += '\n';
}

void box(std::string& out, std::string_view header, const Aabb& box) {
    out += header;
    line(out, "min", pair(box.min));
    line(out, "max", pair(box.max));
}

} // namespace

std::string writeItem(const ItemDesc& item) {
    std::string out = "[[item]]\n";
    line(out, "kind", quoted(std::string(item.kind->name())));
    if (!item.name.empty()) line(out, "name", quoted(item.name));
    line(out, "position", pair(item.position));
    // Degrees as read when the angle is unchanged, so a file reads back bit for bit.
    if (item.angleDegrees || item.angle != 0.0) {
        const bool asRead = item.angleDegrees && *item.angleDegrees * std::numbers::pi / 180.0 == item.angle;
        line(out, "angle", scriptNumber(asRead ? *item.angleDegrees : item.angle * 180.0 / std::numbers::pi));
    }
    for (const std::string& own : item.ownLines) {
        out += own;
        out += '\n';
    }
    return out;
}

namespace {

void goal(std::string& out, const Goal& goal) {
    out += "\n[goal]\n";
    line(out, "text", quoted(goal.text));
    line(out, "condition", quoted(std::string(conditionName(goal.kind))));
    if (goal.kind == GoalKind::targetHit) line(out, "target", quoted(goal.item));
    if (goal.kind == GoalKind::ballInBucket) line(out, "bucket", quoted(goal.item));
    if (goal.kind == GoalKind::reachArea) {
        if (!goal.item.empty()) line(out, "item", quoted(goal.item));
        std::string area = "{ min = ";
        area += pair(goal.area.min);
        area += ", max = ";
        area += pair(goal.area.max);
        line(out, "area", area += " }");
    }
    if (goal.timeLimit) line(out, "time_limit", scriptNumber(*goal.timeLimit));
}

} // namespace

std::string writeLevel(const SceneDesc& scene, const std::string& header) {
    std::string text = header;
    if (!header.empty()) text += header.back() == '\n' ? "\n" : "\n\n";
    line(text, "name", quoted(scene.name));
    if (!scene.description.empty()) line(text, "description", quoted(scene.description));
    text += scene.physicsToml;
    if (scene.view) box(text, "\n[view]\n", *scene.view);
    const LevelDesc& level = scene.level;
    for (const ItemDesc& i : level.items) {
        text += '\n';
        text += writeItem(i);
    }
    if (!level.inventory.empty()) {
        text += "\n[inventory]\n";
        for (const auto& [kind, count] : level.inventory) line(text, kind, std::to_string(count));
    }
    for (const Zone& zone : level.zones) box(text, "\n[[zone]]\n", zone.box);
    if (level.goal) goal(text, *level.goal);
    for (const Hint& hint : level.hints) {
        text += "\n[[hint]]\n";
        line(text, "text", quoted(hint.text));
    }
    return text;
}

} // namespace rube::game
