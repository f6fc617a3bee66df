// Scene files: the top level, [world], [view] and [[path]]; the bodies are read in scene_bodies.cpp.
#include "scene_file.hpp"

#include "method_budget.hpp"
#include "scene_reading.hpp"
#include "toml_writer.hpp"

#include <algorithm>
#include <numbers>

namespace rube::game {

namespace {

constexpr std::string_view kWaterKeys[] = {"min", "max", "density", "drag"};
// Every top-level key, the level's tables (item, inventory, zone, goal, hint) and clicks included, so a
// `[[zones]]` typo is offered `zone`: one format for scenes and levels, one list.
constexpr std::string_view kTopAndLevelKeys[] = {
    "name", "description", "world", "view",  "path", "circle",    "circle_grid", "segment", "water", "rope",
    "box",  "capsule",     "pivot", "joint", "item", "inventory", "zone",        "goal",    "hint", "clicks"};
constexpr std::string_view kWorldKeys[] = {"gravity",  "time_step",           "method",        "bounds",
                                           "substeps", "max_events_per_step", "resting_speed", "duration",
                                           "air_drag", "sleep_speed",         "time_to_sleep", "workers"};
constexpr std::string_view kAirDragKeys[] = {"linear", "quadratic"};
constexpr std::string_view kBoundsKeys[] = {"min", "max"};
constexpr std::string_view kViewKeys[] = {"min", "max"};
constexpr std::string_view kPathKeys[] = {"name", "keys", "loop"};

// A world key written at the top level is a common slip; say where it goes instead of guessing a typo.
constexpr KeyHome kTopHomes[] = {{"gravity", "[world]"},
                                 {"time_step", "[world]"},
                                 {"method", "[world]"},
                                 {"bounds", "[world]"},
                                 {"substeps", "[world]"},
                                 {"duration", "[world]"},
                                 {"max_events_per_step", "[world]"},
                                 {"resting_speed", "[world]"},
                                 {"air_drag", "[world]"},
                                 {"sleep_speed", "[world]"},
                                 {"time_to_sleep", "[world]"},
                                 {"workers", "[world]"}};

// A run longer than this is a mistake in duration or time_step, not a plan.
constexpr double kMaxDefaultSteps = 1e9;

} // namespace

// A box written as min and max corners, max above and to the right of min; `what` names it in errors.
std::optional<Aabb> readBox(TableReader& box, std::string_view what) {
    const auto min = box.vec2("min", Need::required);
    const auto max = box.vec2("max", Need::required);
    if (!min || !max) return std::nullopt;
    if (!(min->x < max->x && min->y < max->y)) {
        box.error(box.valuePlace("max"), std::string(what) + " max must be greater than min in both x and y, got min " +
                                             formatPair(min->x, min->y) + " and max " + formatPair(max->x, max->y));
        return std::nullopt;
    }
    return Aabb{*min, *max};
}

namespace {

void readBounds(TableReader& world, SceneDesc& scene) {
    const toml::table* table = world.table("bounds", "{ min = [x, y], max = [x, y] }");
    if (!table) return;
    TableReader bounds(*table, "in world.bounds", kBoundsKeys, world.diagnostics());
    if (const auto box = readBox(bounds, "bounds")) scene.world.bounds = *box;
}

// [view] is for the camera only: the physics never sees it.
void readView(TableReader& root, SceneDesc& scene) {
    const toml::table* table = root.table("view", "[view] with min = [x, y] and max = [x, y]");
    if (!table) return;
    TableReader view(*table, "in [view]", kViewKeys, root.diagnostics());
    scene.view = readBox(view, "view");
}

// Drag of still air: F = -2r (linear v + quadratic |v| v) on every dynamic ball (see fields.hpp).
void readAirDrag(TableReader& world, SceneDesc& scene) {
    const toml::table* table = world.table("air_drag", "{ linear = N s/m, quadratic = N s^2/m^2 }");
    if (!table) return;
    TableReader drag(*table, "in world.air_drag", kAirDragKeys, world.diagnostics());
    // Past 1000 a ball stops in a fraction of a step: a unit slip, not a thick fluid.
    const NumberRange range{0.0, 1000.0};
    if (const auto k = drag.number("linear", range)) scene.world.airDrag.linear = *k;
    if (const auto k = drag.number("quadratic", range)) scene.world.airDrag.quadratic = *k;
}

// [[water]]: a pool from min to max; its top edge is the surface.
void readWaters(TableReader& root, SceneDesc& scene) {
    for (const toml::table* table : root.arrayOfTables("water")) {
        TableReader water(*table, "in [[water]]", kWaterKeys, root.diagnostics());
        const auto box = readBox(water, "water");
        Water pool;
        if (const auto rho = water.number("density", NumberRange::positive())) pool.density = *rho;
        if (const auto drag = water.number("drag", NumberRange::nonNegative())) pool.drag = *drag;
        if (!box) continue;
        pool.min = box->min;
        pool.max = box->max;
        scene.waters.push_back(pool);
    }
}

void readWorld(TableReader& root, SceneDesc& scene) {
    const toml::table* table = root.table("world", "[world]");
    if (!table) return;
    TableReader world(*table, "in [world]", kWorldKeys, root.diagnostics());
    WorldDef& def = scene.world;
    if (const auto g = world.vec2("gravity")) def.gravity = *g;
    if (const auto dt = world.number("time_step", NumberRange::positive())) def.timeStep = *dt;
    std::string_view names[std::size(kAllMethods)];
    std::transform(std::begin(kAllMethods), std::end(kAllMethods), names, methodName);
    if (const auto m = world.choice("method", names)) def.method = kAllMethods[*m];
    readBounds(world, scene);
    readAirDrag(world, scene);
    if (const auto n = world.integer("substeps", 1, 1000)) def.substeps = static_cast<int>(*n);
    if (const auto n = world.integer("workers", 1, kMaxWorkers)) def.workers = static_cast<int>(*n);
    if (const auto n = world.integer("max_events_per_step", 1, 10'000'000)) def.maxEventsPerStep = static_cast<int>(*n);
    if (const auto v = world.number("resting_speed", NumberRange::nonNegative())) def.restingSpeed = *v;
    if (const auto v = world.number("sleep_speed", NumberRange::nonNegative())) def.sleepSpeed = *v;
    if (const auto t = world.number("time_to_sleep", NumberRange::positive())) def.timeToSleep = *t;
    if (const auto d = world.number("duration", NumberRange::positive())) {
        if (*d / def.timeStep > kMaxDefaultSteps)
            world.error(world.valuePlace("duration"), "duration " + formatNumber(*d) + " s at time_step " +
                                                          formatNumber(def.timeStep) + " s is more than 1e9 steps");
        else scene.duration = *d;
    }
}

// The keys of a path: [[t, x, y], ...] with t increasing, at least two of them; a fourth number is the
// angle, in degrees, a segment on the path has turned about its pivot by then (a rotating paddle).
std::optional<KinematicPath> readKeys(TableReader& path) {
    const toml::node* node = path.get("keys", Need::required);
    if (!node) return std::nullopt;
    const auto* array = node->as_array();
    if (!array) {
        path.error(placeOf(node->source()),
                   "keys must be an array of [t, x, y] keys, got " + std::string(typeName(*node)));
        return std::nullopt;
    }
    if (array->size() < 2) {
        path.error(placeOf(node->source()),
                   "keys must hold at least 2 keys [t, x, y], got " + std::to_string(array->size()));
        return std::nullopt;
    }
    KinematicPath result;
    bool ok = true;
    for (const toml::node& element : *array) {
        const auto* key = element.as_array();
        if (!key || key->size() < 3 || key->size() > 4) {
            path.error(placeOf(element.source()),
                       "a path key must be [t, x, y] or [t, x, y, angle], got " +
                           (key ? std::to_string(key->size()) + " numbers" : std::string(typeName(element))));
            ok = false;
            continue;
        }
        const auto t = readNumber(*key->get(0), "a path key's t", path.diagnostics());
        const auto x = readNumber(*key->get(1), "a path key's x", path.diagnostics());
        const auto y = readNumber(*key->get(2), "a path key's y", path.diagnostics());
        const auto angle = key->size() == 4 ? readNumber(*key->get(3), "a path key's angle", path.diagnostics())
                                            : std::optional<double>{0.0};
        if (!t || !x || !y || !angle) {
            ok = false;
            continue;
        }
        // Equal times would be a jump, moving the body with infinite speed for one step.
        if (!result.keys.empty() && *t <= result.keys.back().time) {
            path.error(placeOf(key->get(0)->source()), "path key times must increase, got " + formatNumber(*t) +
                                                           " after " + formatNumber(result.keys.back().time));
            ok = false;
        } else if (result.keys.empty() && *t < 0.0) {
            path.error(placeOf(key->get(0)->source()), "path key times must be at least 0, got " + formatNumber(*t));
            ok = false;
        }
        result.keys.push_back({*t, {*x, *y}, *angle * std::numbers::pi / 180.0});
    }
    if (!ok) return std::nullopt;
    return result;
}

void readPaths(TableReader& root, SceneReading& reading) {
    for (const toml::table* table : root.arrayOfTables("path")) {
        TableReader path(*table, "in [[path]]", kPathKeys, reading.diag);
        const auto name = path.string("name", Need::required);
        auto keys = readKeys(path);
        const auto loop = path.boolean("loop");
        if (!name) continue;
        if (name->empty()) {
            path.error(path.valuePlace("name"), "name must not be empty");
            continue;
        }
        if (reading.pathIndex.contains(*name)) {
            path.error(path.valuePlace("name"), "a path named '" + *name + "' is already defined");
            continue;
        }
        // Registered even when its keys are wrong, so bodies using it do not also report it as unknown.
        reading.pathIndex[*name] = static_cast<int>(reading.scene.paths.size());
        NamedPath named{*name, keys.value_or(KinematicPath{})};
        named.path.loop = loop.value_or(false);
        reading.scene.paths.push_back(std::move(named));
    }
}

} // namespace

std::optional<int> readPathReference(TableReader& table, SceneReading& reading) {
    const auto name = table.string("path");
    if (!name) return std::nullopt;
    if (const auto it = reading.pathIndex.find(*name); it != reading.pathIndex.end()) return it->second;
    std::vector<std::string_view> defined;
    for (const auto& [known, index] : reading.pathIndex) defined.push_back(known);
    std::string message = "unknown path '" + *name + "'";
    if (defined.empty()) message += " (no [[path]] is defined)";
    else if (const auto match = closestMatch(*name, defined))
        message += " (did you mean '" + std::string(*match) + "'?)";
    else message += " (defined paths: " + joinNames(defined) + ")";
    table.error(table.valuePlace("path"), std::move(message));
    return std::nullopt;
}

namespace {

// The document without what the level writer writes from the SceneDesc (name, description, the
// view and the level's tables), as TOML: the physics, which the editor does not change.
std::string physicsTables(const toml::table& document) {
    toml::table physics = document;
    for (const char* key : {"name", "description", "view", "item", "inventory", "zone", "goal", "hint"})
        physics.erase(key);
    return tomlTables(physics);
}

} // namespace

SceneLoad parseScene(std::string_view text, const std::string& fileName) {
    Diagnostics diag(fileName);
    std::optional<toml::table> parsed = parseToml(text, fileName, diag);
    if (!parsed) return {std::nullopt, diag.sorted()};
    toml::table& document = *parsed;
    SceneDesc scene;
    SceneReading reading{diag, scene, {}, {}};
    TableReader root(document, "at the top level", kTopAndLevelKeys, diag, kTopHomes);
    if (const auto name = root.string("name", Need::required)) {
        if (name->empty()) root.error(root.valuePlace("name"), "name must not be empty");
        scene.name = *name;
    }
    scene.description = root.string("description").value_or("");
    readWorld(root, scene);
    readView(root, scene);
    readWaters(root, scene);
    readPaths(root, reading);
    readCircles(root, reading);
    readCircleGrids(root, reading);
    readSegments(root, reading);
    readRopes(root, reading);
    readRigidBodies(root, reading);
    readJoints(root, reading);
    readLevel(root, reading);
    // A level that names no method gets "auto", the cheapest that holds for what it does; a
    // physics scene keeps the exact method, the course's reference, unless it names another.
    // Bodies that turn need the solver: a scene with some gets "auto" too, and naming a method
    // that cannot move them is an error at the name.
    const toml::table* world = document["world"].as_table();
    const bool namesMethod = world && world->contains("method");
    const bool rotating = needsRotatingSolver(scene);
    std::string why;
    // A scene with other errors is not built to ask exact about its springs: only the method's kind counts.
    if (rotating && namesMethod &&
        (diag.empty() ? !methodMovesRotating(scene, scene.world.method, why)
                      : !movesTurningBodies(scene.world.method) &&
                            !(scene.world.method == Method::exact && scene.pivots.empty() && scene.bodies.empty()))) {
        TableReader worldTable(*world, "in [world]", kWorldKeys, diag);
        worldTable.error(worldTable.valuePlace("method"),
                         !why.empty()
                             ? why
                             : "method '" + std::string(methodName(scene.world.method)) +
                                   (scene.joints.empty() ? "' cannot move turning boxes, capsules or pivots"
                                                         : "' cannot move turning boxes, capsules, pivots or joints") +
                                   ": use 'auto' or 'solver'");
    }
    // Naming a method too slow for the scene's size is an error at the name (method_budget.hpp).
    if (const std::string why = namesMethod ? methodBudgetRefusal(scene, scene.world.method) : "";
        !why.empty() && diag.empty()) {
        TableReader worldTable(*world, "in [world]", kWorldKeys, diag);
        worldTable.error(worldTable.valuePlace("method"), why);
    }
    if (!diag.empty()) return {std::nullopt, diag.sorted()};
    scene.physicsToml = physicsTables(document);
    if ((scene.level.isLevel() || rotating) && !namesMethod) scene.world.method = Method::automatic;
    // Nor does a scene too large for exact's pair-by-pair search (method_budget.hpp): it gets
    // "auto", which runs exact wherever exact affords the step.
    if (!namesMethod && !methodBudgetRefusal(scene, scene.world.method).empty()) scene.world.method = Method::automatic;
    return {std::move(scene), {}};
}

SceneLoad loadSceneFile(const std::filesystem::path& file) {
    SceneError error;
    const std::optional<std::string> text = readTextFile(file, error);
    if (!text) return {std::nullopt, {error}};
    return parseScene(*text, file.string());
}

} // namespace rube::game
