// Scene files: [[rope]], an inextensible rope from a dynamic circle to a fixed anchor or another circle.
// Read after the bodies, since a rope names the circles it joins (by index in body order, or by name).
#include "scene_reading.hpp"

namespace rube::game {

namespace {

constexpr std::string_view kRopeKeys[] = {"circle", "anchor", "other", "length"};
// A name is how a switch or a script cuts a rope; like a body's, it is not offered in a physics scene's key list.
constexpr std::string_view kNameKey[] = {"name"};

// The circle a `circle` or `other` key names: an index in body order (see scene-format.md) or a
// [[circle]]'s name; reports an index out of range or an unknown name at the value.
std::optional<int> readCircleReference(TableReader& rope, std::string_view key, SceneReading& reading, Need need) {
    const toml::node* node = rope.get(key, need);
    if (!node) return std::nullopt;
    const auto& circles = reading.scene.circles;
    const SourcePlace place = placeOf(node->source());
    if (const auto* index = node->as_integer()) {
        const std::int64_t i = index->get();
        if (i < 0 || i >= static_cast<std::int64_t>(circles.size())) {
            rope.error(place, std::string(key) + " must be a circle's index from 0 to " +
                                  std::to_string(circles.size()) + " (exclusive) or its name, got " +
                                  std::to_string(i));
            return std::nullopt;
        }
        return static_cast<int>(i);
    }
    if (const auto* text = node->as_string()) {
        const std::string& name = text->get();
        std::vector<std::string_view> names;
        for (std::size_t i = 0; i < circles.size(); ++i) {
            if (reading.scene.circleNames[i] == name) return static_cast<int>(i);
            if (!reading.scene.circleNames[i].empty()) names.push_back(reading.scene.circleNames[i]);
        }
        rope.error(place, "unknown circle '" + name + "'" +
                              unknownNameHint(name, names, "named circles", "no [[circle]] has a name"));
        return std::nullopt;
    }
    rope.error(place, std::string(key) + " must be a circle's index (integer) or name (string), got " +
                          std::string(typeName(*node)));
    return std::nullopt;
}

void readRope(const toml::table& table, SceneReading& reading) {
    TableReader rope(table, "in [[rope]]", kRopeKeys, reading.diag, {}, kNameKey);
    const auto circle = readCircleReference(rope, "circle", reading, Need::required);
    const bool toCircle = rope.find("other") != nullptr;
    if (toCircle && rope.find("anchor")) {
        rope.error(rope.valuePlace("anchor"),
                   "a rope ends at an anchor or at another circle, not both: remove anchor or other");
        return;
    }
    const auto other = toCircle ? readCircleReference(rope, "other", reading, Need::required) : std::nullopt;
    const auto anchor = toCircle ? std::nullopt : rope.vec2("anchor", NumberRange::coordinate(), Need::required);
    const auto length = rope.number("length", NumberRange::positive());
    const std::string name = readBodyName(rope, reading);
    if (!circle || (toCircle ? !other : !anchor)) return;
    const int otherIndex = toCircle ? other.value_or(-1) : -1;
    const Vec2 anchorPoint = anchor.value_or(Vec2{});
    const CircleDef& ball = reading.scene.circles[static_cast<std::size_t>(*circle)];
    if (ball.motion != Motion::dynamic) {
        // A rope pulls the circle it holds; a static or kinematic one cannot be pulled.
        rope.error(rope.valuePlace("circle"),
                   "a rope's circle must be dynamic (the rope pulls it); use other for a fixed end");
        return;
    }
    if (otherIndex == *circle) {
        rope.error(rope.valuePlace("other"), "a rope cannot join a circle to itself");
        return;
    }
    const Vec2 farEnd = otherIndex >= 0 ? reading.scene.circles[static_cast<std::size_t>(otherIndex)].position
                                        : anchorPoint;
    const double apart = ball.position.distance(farEnd);
    // Without a length the rope is just taut at the start; a rope shorter than the ends' distance
    // would yank the ball on the first step, a mistake in the file rather than a plan.
    const double ropeLength = length.value_or(apart);
    if (!(ropeLength > 0.0)) {
        rope.error(rope.tablePlace(), "the rope's ends start at the same point: give it a length");
        return;
    }
    // A millionth of slack for positions written to a few decimals (a bob at 15 degrees, say).
    if (apart > ropeLength * (1.0 + 1e-6)) {
        rope.error(rope.valuePlace("length"), "the rope's ends start " + formatNumber(apart) +
                                                  " m apart, more than its length " + formatNumber(ropeLength));
        return;
    }
    reading.scene.ropes.push_back(SceneRope{*circle, otherIndex, anchorPoint, ropeLength});
    reading.scene.ropeNames.push_back(name);
}

} // namespace

void readRopes(TableReader& root, SceneReading& reading) {
    for (const toml::table* table : root.arrayOfTables("rope")) readRope(*table, reading);
}

} // namespace rube::game
