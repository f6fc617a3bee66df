// Scene files: the bodies, [[circle]], [[circle_grid]] and [[segment]].
#include "scene_reading.hpp"

#include <cmath>

namespace rube::game {

namespace {

constexpr std::string_view kCircleKeys[] = {"position", "velocity",   "angular_velocity", "inertia", "radius",
                                            "mass",     "bounciness", "friction",         "motion",  "path"};
constexpr std::string_view kGridKeys[] = {"origin",     "columns",          "rows",    "spacing", "stagger",
                                          "velocity",   "angular_velocity", "inertia", "radius",  "mass",
                                          "bounciness", "friction",         "motion",  "path"};
constexpr std::string_view kSegmentKeys[] = {"a",        "b",    "radius",        "bounciness",
                                             "friction", "path", "surface_speed", "pivot"};
// A name is how goals and scripts refer to a body; it is not offered in a physics scene's key lists.
constexpr std::string_view kNameKey[] = {"name"};
constexpr std::string_view kMotionNames[] = {"dynamic", "kinematic", "static"};
constexpr Motion kMotions[] = {Motion::dynamic, Motion::kinematic, Motion::fixed};

// One grid may make this many circles: a pile, not a memory exhaustion by a stray zero.
constexpr std::int64_t kMaxGridCircles = 100'000;
// And a whole scene at most this many: ten thousand already take seconds a step.
constexpr std::int64_t kMaxSceneCircles = 100'000;

Material readMaterial(TableReader& table) {
    Material material;
    if (const auto c = table.number("bounciness", NumberRange::unit())) material.bounciness = *c;
    if (const auto mu = table.number("friction", NumberRange::nonNegative())) material.friction = *mu;
    return material;
}

// The keys a [[circle]] and a [[circle_grid]] share. A path makes the circle kinematic unless
// it says otherwise, and a kinematic circle without a path would have nowhere to go.
CircleDef readCircleFields(TableReader& table, SceneReading& reading) {
    CircleDef def;
    if (const auto v = table.vec2("velocity")) def.velocity = *v;
    if (const auto r = table.number("radius", NumberRange::size(), Need::required)) def.radius = *r;
    if (const auto m = table.number("mass", NumberRange::mass())) def.mass = *m;
    if (const auto w = table.number("angular_velocity")) def.angularVelocity = *w;
    // I = k m r^2: 1/2 a solid disc, 1 a thin ring; more than a ring would need mass outside the rim.
    if (const auto k = table.number("inertia", NumberRange{0.0, 1.0, true})) def.inertiaFactor = *k;
    def.material = readMaterial(table);
    const auto motion = table.choice("motion", kMotionNames);
    const auto path = readPathReference(table, reading);
    if (motion) def.motion = kMotions[*motion];
    if (path) {
        def.path = *path;
        if (!motion) def.motion = Motion::kinematic;
        else if (def.motion != Motion::kinematic)
            table.error(table.valuePlace("motion"), "a circle with a path must be kinematic, got motion '" +
                                                        std::string(kMotionNames[*motion]) + "'");
    } else if (motion && def.motion == Motion::kinematic && !table.find("path")) {
        table.error(table.valuePlace("motion"), "a kinematic circle needs a path = \"name\" of a [[path]] to follow");
    }
    return def;
}

void readCircle(const toml::table& table, SceneReading& reading) {
    TableReader circle(table, "in [[circle]]", kCircleKeys, reading.diag, {}, kNameKey);
    const auto position = circle.vec2("position", NumberRange::coordinate(), Need::required);
    CircleDef def = readCircleFields(circle, reading);
    def.position = position.value_or(Vec2{});
    reading.scene.circleNames.push_back(readBodyName(circle, reading));
    reading.scene.circles.push_back(def);
}

void readCircleGrid(const toml::table& table, SceneReading& reading) {
    TableReader grid(table, "in [[circle_grid]]", kGridKeys, reading.diag);
    const auto origin = grid.vec2("origin", NumberRange::coordinate(), Need::required);
    const auto columns = grid.integer("columns", 1, 10'000, Need::required);
    const auto rows = grid.integer("rows", 1, 10'000, Need::required);
    const auto spacing = grid.numberOrVec2("spacing", NumberRange::positive(), Need::required);
    const double stagger = grid.number("stagger").value_or(0.0);
    const CircleDef def = readCircleFields(grid, reading);
    if (!origin || !columns || !rows || !spacing) return;
    if (*columns * *rows > kMaxGridCircles) {
        grid.error(grid.valuePlace("rows"), "circle_grid makes " + std::to_string(*columns * *rows) +
                                                " circles; one grid may make at most " +
                                                std::to_string(kMaxGridCircles));
        return;
    }
    if (const auto total = static_cast<std::int64_t>(reading.scene.circles.size()) + *columns * *rows;
        total > kMaxSceneCircles) {
        grid.error(grid.tablePlace(), "this circle_grid brings the scene to " + std::to_string(total) +
                                          " circles, more than the " + std::to_string(kMaxSceneCircles) +
                                          " a scene may have");
        return;
    }
    // Neighbours closer than a diameter would start inside each other and fly apart on the first step.
    const double diameter = 2.0 * def.radius;
    if ((*columns > 1 && spacing->x < diameter) || (*rows > 1 && spacing->y < diameter)) {
        const std::string got = spacing->x == spacing->y ? formatNumber(spacing->x)
                                                         : formatPair(spacing->x, spacing->y);
        grid.error(grid.valuePlace("spacing"), "spacing must be at least the diameter " + formatNumber(diameter) +
                                                   " so the circles do not start overlapping, got " + got);
        return;
    }
    for (std::int64_t row = 0; row < *rows; ++row) {
        // Every other row shifts by `stagger`, so a pile does not fall as perfectly stacked columns.
        const double shift = row % 2 == 1 ? stagger : 0.0;
        for (std::int64_t column = 0; column < *columns; ++column) {
            CircleDef circle = def;
            circle.position = *origin + Vec2{static_cast<double>(column) * spacing->x + shift,
                                             static_cast<double>(row) * spacing->y};
            reading.scene.circles.push_back(circle);
            reading.scene.circleNames.emplace_back();
        }
    }
}

void readSegment(const toml::table& table, SceneReading& reading) {
    TableReader segment(table, "in [[segment]]", kSegmentKeys, reading.diag, {}, kNameKey);
    SegmentDef def;
    const auto a = segment.vec2("a", NumberRange::coordinate(), Need::required);
    const auto b = segment.vec2("b", NumberRange::coordinate(), Need::required);
    if (const auto r = segment.number("radius", NumberRange::thickness())) def.radius = *r;
    def.material = readMaterial(segment);
    const std::string name = readBodyName(segment, reading);
    if (const auto path = readPathReference(segment, reading)) def.path = *path;
    if (const auto v = segment.number("surface_speed")) def.surfaceSpeed = *v;
    if (const auto v = segment.number("pivot", NumberRange::unit())) def.pivotAlong = *v;
    if (a && b && *a == *b) {
        // A segment of zero length has no direction, so no normal to bounce off.
        segment.error(segment.valuePlace("b"), "b must differ from a: the segment has zero length");
        return;
    }
    def.a = a.value_or(Vec2{});
    def.b = b.value_or(Vec2{1.0, 0.0});
    reading.scene.segments.push_back(def);
    reading.scene.segmentNames.push_back(name);
}

} // namespace

void readCircles(TableReader& root, SceneReading& reading) {
    const auto tables = root.arrayOfTables("circle");
    if (static_cast<std::int64_t>(tables.size()) > kMaxSceneCircles) {
        reading.diag.error(placeOf(tables[kMaxSceneCircles]->source()),
                           "too many [[circle]] tables: " + std::to_string(tables.size()) + ", more than the " +
                               std::to_string(kMaxSceneCircles) + " circles a scene may have");
        return;
    }
    for (const toml::table* table : tables) readCircle(*table, reading);
}

void readCircleGrids(TableReader& root, SceneReading& reading) {
    for (const toml::table* table : root.arrayOfTables("circle_grid")) readCircleGrid(*table, reading);
}

void readSegments(TableReader& root, SceneReading& reading) {
    for (const toml::table* table : root.arrayOfTables("segment")) readSegment(*table, reading);
}

} // namespace rube::game
