// Scene files: [[box]] and [[capsule]], rigid bodies that turn (or lecture 3's blocks with
// fixed_rotation), and [[pivot]], a rigid body pinned to the world at a point. Rigid bodies are
// numbered in file order, every [[box]] first, then every [[capsule]]; a pivot names one by index or name.
#include "part_kind.hpp"
#include "scene_errors.hpp"
#include "scene_reading.hpp"

#include "scene.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace rube::game {

namespace {

constexpr std::string_view kBoxKeys[] = {"position",   "size",     "half_extents", "angle_degrees",
                                         "mass",       "density",  "velocity",     "angular_velocity",
                                         "bounciness", "friction", "motion",       "fixed_rotation"};
// A name is how goals and scripts refer to a body; it is not offered in a physics scene's key list.
constexpr std::string_view kNameKey[] = {"name"};
constexpr std::string_view kPivotKeys[] = {"body", "anchor"};
// No kinematic bodies yet: a rigid body has no scripted path (a moving platform is a segment).
constexpr std::string_view kMotionNames[] = {"dynamic", "static"};
constexpr Motion kMotions[] = {Motion::dynamic, Motion::fixed};

double areaOf(BodyShape shape, Vec2 he) {
    return shape == BodyShape::box ? 4.0 * he.x * he.y : 4.0 * he.x * he.y + std::numbers::pi * he.y * he.y;
}

void readRigidBody(const toml::table& table, SceneReading& reading, BodyShape shape) {
    const char* where = shape == BodyShape::box ? "in [[box]]" : "in [[capsule]]";
    TableReader body(table, where, kBoxKeys, reading.diag, {}, kNameKey);
    RigidBodyDef def;
    def.shape = shape;
    const auto position = body.vec2("position", NumberRange::coordinate(), Need::required);
    const bool hasSize = body.find("size") != nullptr, hasHalf = body.find("half_extents") != nullptr;
    if (hasSize == hasHalf) {
        body.error(hasSize ? body.valuePlace("half_extents") : body.tablePlace(),
                   shape == BodyShape::box ? "give a box its size = [width, height] or its half_extents, one of them"
                                           : "give a capsule its size = [length, thickness] or its half_extents = "
                                             "[half core length, radius], one of them");
        return;
    }
    const auto extents = body.numberOrVec2(hasSize ? "size" : "half_extents", NumberRange::size(), Need::required);
    if (!position || !extents) return;
    def.position = *position;
    if (hasHalf) {
        def.halfExtents = *extents;
    } else if (shape == BodyShape::box) {
        def.halfExtents = *extents * 0.5;
    } else {
        // A capsule's size is its whole outline: length end to end over the caps, and its thickness.
        const double radius = 0.5 * extents->y;
        if (extents->x < 2.0 * radius) {
            body.error(body.valuePlace("size"), "a capsule's length must be at least its thickness");
            return;
        }
        def.halfExtents = {0.5 * extents->x - radius, radius};
    }
    if (const auto a = body.number("angle_degrees")) def.angle = *a * std::numbers::pi / 180.0;
    const auto mass = body.number("mass", NumberRange::mass());
    const auto density = body.number("density", NumberRange::positive());
    if (mass && density) body.error(body.valuePlace("density"), "give mass or density, not both");
    if (mass) def.mass = *mass;
    else if (density) {
        def.mass = *density * areaOf(shape, def.halfExtents);
        if (!NumberRange::mass().contains(def.mass))
            body.error(body.valuePlace("density"), "density times area gives a mass of " + formatNumber(def.mass) +
                                                       " kg; it must be " + NumberRange::mass().describe() + " kg");
    }
    if (const auto v = body.vec2("velocity")) def.velocity = *v;
    if (const auto w = body.number("angular_velocity")) def.angularVelocity = *w;
    if (const auto c = body.number("bounciness", NumberRange::unit())) def.material.bounciness = *c;
    if (const auto mu = body.number("friction", NumberRange::nonNegative())) def.material.friction = *mu;
    if (const auto motion = body.choice("motion", kMotionNames)) def.motion = kMotions[*motion];
    if (const auto fixed = body.boolean("fixed_rotation")) {
        if (*fixed && shape == BodyShape::capsule) {
            body.error(body.valuePlace("fixed_rotation"), "only a box can have fixed_rotation (lecture 3's block)");
            return;
        }
        def.fixedRotation = *fixed;
    }
    const std::string name = readBodyName(body, reading);
    reading.scene.bodies.push_back(def);
    reading.scene.bodyNames.push_back(name);
}

/// The body a pivot's `body` names by its `name` (an unknown name is reported with the closest one).
std::optional<std::int64_t> namedBody(TableReader& pivot, const SceneReading& reading) {
    const auto name = pivot.string("body", Need::required);
    if (!name) return std::nullopt;
    const auto& names = reading.scene.bodyNames;
    for (std::size_t i = 0; i < names.size(); ++i)
        if (!name->empty() && names[i] == *name) return static_cast<std::int64_t>(i);
    std::vector<std::string_view> defined;
    for (const std::string& known : names)
        if (!known.empty()) defined.push_back(known);
    std::string message = "unknown body '" + *name + "'";
    if (defined.empty()) message += " (no [[box]] or [[capsule]] has a name)";
    else if (const auto match = closestMatch(*name, defined))
        message += " (did you mean '" + std::string(*match) + "'?)";
    else message += " (named bodies: " + joinNames(defined) + ")";
    pivot.error(pivot.valuePlace("body"), std::move(message));
    return std::nullopt;
}

void readPivot(const toml::table& table, SceneReading& reading) {
    TableReader pivot(table, "in [[pivot]]", kPivotKeys, reading.diag);
    const auto& bodies = reading.scene.bodies;
    // `body` is an index in file order (boxes, then capsules) or a body's name.
    const toml::node* given = pivot.find("body");
    const auto index = given && given->is_string()
                           ? namedBody(pivot, reading)
                           : pivot.integer("body", 0,
                                           std::max<std::int64_t>(0, static_cast<std::int64_t>(bodies.size()) - 1),
                                           Need::required);
    if (!index) return;
    if (bodies.empty()) {
        pivot.error(pivot.valuePlace("body"), "a pivot pins a rigid body: no [[box]] or [[capsule]] is defined");
        return;
    }
    const RigidBodyDef& body = bodies[static_cast<std::size_t>(*index)];
    const Vec2 anchor = pivot.vec2("anchor", NumberRange::coordinate()).value_or(body.position);
    // The anchor in the body's own frame: turned back by its angle.
    const Vec2 d = anchor - body.position;
    const double c = std::cos(body.angle), s = std::sin(body.angle);
    reading.scene.pivots.push_back(
        ScenePivot{static_cast<int>(*index), {c * d.x + s * d.y, -s * d.x + c * d.y}, anchor});
}

} // namespace

void readRigidBodies(TableReader& root, SceneReading& reading) {
    for (const toml::table* table : root.arrayOfTables("box")) readRigidBody(*table, reading, BodyShape::box);
    for (const toml::table* table : root.arrayOfTables("capsule")) readRigidBody(*table, reading, BodyShape::capsule);
    for (const toml::table* table : root.arrayOfTables("pivot")) readPivot(*table, reading);
}

bool methodMovesRotating(const SceneDesc& scene, Method method, std::string& why) {
    why.clear();
    if (movesTurningBodies(method) || !needsRotatingSolver(scene)) return true;
    if (method != Method::exact || !scene.pivots.empty() || !scene.bodies.empty()) return false;
    // Joints alone: exact follows a spring to a fixed point on its closed form, where it has one.
    try {
        const World world = buildWorld(scene);
        requireJointMethod(method, world.joints(), world.circles(), world.def().gravity, false);
        return true;
    } catch (const std::logic_error& e) {
        why = e.what();
        return false;
    }
}

namespace {

// True when an item's bodies hold a joint or a rigid body that turns (a crate, a domino, a motor's wheel).
bool turns(const ItemBodies& bodies) {
    if (!bodies.joints.empty()) return true;
    for (const RigidBodyDef& b : bodies.rigidBodies)
        if (!isBlock(b)) return true;
    return false;
}

} // namespace

bool needsRotatingSolver(const SceneDesc& scene) {
    if (!scene.pivots.empty() || !scene.joints.empty()) return true;
    for (const RigidBodyDef& b : scene.bodies)
        if (!isBlock(b)) return true;
    // The level's parts, and those its inventory lets a player place (as made: a placement has no keys).
    for (const ItemDesc& item : scene.level.items)
        if (turns(item.kind->bodies(item))) return true;
    for (const auto& [name, count] : scene.level.inventory)
        if (const ItemKind kind = findPartKind(name); kind && count > 0 && turns(kind->bodies(kind->make({}))))
            return true;
    return false;
}

} // namespace rube::game
