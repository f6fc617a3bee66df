// Scene files: [[box]], a rigid box. With fixed_rotation (the default) it is lecture 3's block: an
// axis-aligned box that never turns, moved by every time-step method.
#include "scene_reading.hpp"

namespace rube::game {

namespace {

constexpr std::string_view kBoxKeys[] = {"position", "size", "velocity", "mass", "bounciness", "friction", "motion",
                                         "fixed_rotation"};
// A name is how goals and scripts refer to a body; it is not offered in a physics scene's key list.
constexpr std::string_view kNameKey[] = {"name"};
constexpr std::string_view kBoxMotionNames[] = {"dynamic", "static"};
constexpr Motion kBoxMotions[] = {Motion::dynamic, Motion::fixed};

void readBox(const toml::table& table, SceneReading& reading) {
    TableReader box(table, "in [[box]]", kBoxKeys, reading.diag, {}, kNameKey);
    RigidBodyDef def;
    def.shape = BodyShape::box;
    const auto position = box.vec2("position", Need::required);
    const auto size = box.numberOrVec2("size", NumberRange::positive(), Need::required);
    if (const auto v = box.vec2("velocity")) def.velocity = *v;
    if (const auto m = box.number("mass", NumberRange::positive())) def.mass = *m;
    if (const auto c = box.number("bounciness", NumberRange::unit())) def.material.bounciness = *c;
    if (const auto mu = box.number("friction", NumberRange::nonNegative())) def.material.friction = *mu;
    if (const auto motion = box.choice("motion", kBoxMotionNames)) def.motion = kBoxMotions[*motion];
    def.fixedRotation = box.boolean("fixed_rotation").value_or(true);
    const std::string name = readBodyName(box, reading);
    if (!position || !size) return;
    def.position = *position;
    def.halfExtents = *size * 0.5; // size is the full width and height, as a player measures a crate
    reading.scene.bodies.push_back(def);
    reading.scene.bodyNames.push_back(name);
}

} // namespace

void readBoxes(TableReader& root, SceneReading& reading) {
    for (const toml::table* table : root.arrayOfTables("box")) readBox(*table, reading);
}

} // namespace rube::game
