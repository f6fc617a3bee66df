// The level writer: every shipped level reads, writes and reads back to the same level (its parts
// field by field, the writer's own output a fixed point, and its solution replaying to the same
// goal step and state hash); a level changed in memory, as the editor changes it, is written so.
#include "level_folder.hpp"
#include "check_command.hpp"
#include "level_run.hpp"
#include "level_writer.hpp"
#include "scene_file.hpp"
#include "script_file.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace rube;
using namespace rube::game;

namespace {

const std::filesystem::path kLevels = RUBE_GAME_LEVELS_DIR;

SceneDesc reread(const std::string& text, const std::string& name) {
    const SceneLoad load = parseScene(text, name + ".written.toml");
    INFO(text);
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return *load.scene;
}

// Runs `level` with `script` to its goal (or `steps`): the goal step and the final state hash.
std::pair<std::optional<std::int64_t>, std::uint64_t> play(const SceneDesc& level, const ScriptDesc& script,
                                                           std::int64_t steps) {
    LevelRun run(level, script.placements);
    std::size_t next = 0;
    for (std::int64_t i = 0; i < steps; ++i) {
        for (; next < script.actions.size() && script.actions[next].step == i; ++next)
            takeAction(script.actions[next], run);
        run.step();
    }
    return {run.goalStep(), stateHash(run.world())};
}

void requireSameLevel(const SceneDesc& a, const SceneDesc& b) {
    CHECK(a.name == b.name);
    CHECK(a.description == b.description);
    CHECK(a.world.timeStep == b.world.timeStep);
    CHECK(a.world.gravity.x == b.world.gravity.x);
    CHECK(a.world.gravity.y == b.world.gravity.y);
    CHECK(a.world.method == b.world.method);
    CHECK(a.circles.size() == b.circles.size());
    CHECK(a.segments.size() == b.segments.size());
    CHECK(a.bodies.size() == b.bodies.size());
    CHECK(a.ropes.size() == b.ropes.size());
    CHECK(a.waters.size() == b.waters.size());
    REQUIRE(a.view.has_value() == b.view.has_value());
    if (a.view) {
        CHECK(a.view->min.x == b.view->min.x);
        CHECK(a.view->max.y == b.view->max.y);
    }
    REQUIRE(a.level.items.size() == b.level.items.size());
    for (std::size_t i = 0; i < a.level.items.size(); ++i) {
        INFO("item " << i);
        const ItemDesc& x = a.level.items[i];
        const ItemDesc& y = b.level.items[i];
        CHECK(x.kind == y.kind);
        CHECK(x.name == y.name);
        CHECK(x.position.x == y.position.x);
        CHECK(x.position.y == y.position.y);
        CHECK(x.angle == y.angle);
        CHECK(x.ownLines == y.ownLines);
        CHECK(itemExtent(x).min.x == itemExtent(y).min.x);
        CHECK(itemExtent(x).max.y == itemExtent(y).max.y);
    }
    CHECK(a.level.inventory == b.level.inventory);
    REQUIRE(a.level.zones.size() == b.level.zones.size());
    for (std::size_t i = 0; i < a.level.zones.size(); ++i) {
        CHECK(a.level.zones[i].box.min.x == b.level.zones[i].box.min.x);
        CHECK(a.level.zones[i].box.max.y == b.level.zones[i].box.max.y);
    }
    REQUIRE(a.level.goal.has_value() == b.level.goal.has_value());
    if (a.level.goal) {
        CHECK(a.level.goal->text == b.level.goal->text);
        CHECK(a.level.goal->kind == b.level.goal->kind);
        CHECK(a.level.goal->item == b.level.goal->item);
        CHECK(a.level.goal->area.min == b.level.goal->area.min);
        CHECK(a.level.goal->area.max == b.level.goal->area.max);
        CHECK(a.level.goal->timeLimit == b.level.goal->timeLimit);
    }
    REQUIRE(a.level.hints.size() == b.level.hints.size());
    for (std::size_t i = 0; i < a.level.hints.size(); ++i) CHECK(a.level.hints[i].text == b.level.hints[i].text);
}

} // namespace

TEST_CASE("every shipped level reads, writes and reads back to the same level", "[level][writer]") {
    int levels = 0;
    for (const LevelFile& file : levelFilesIn(kLevels, LevelFileRole::level)) {
        const std::string name = file.level;
        INFO(name);
        const SceneLoad load = loadSceneFile(file.path);
        REQUIRE(load.ok());
        const SceneDesc& original = *load.scene;
        const std::string written = writeLevel(original, "# " + name + ", written back");
        const SceneDesc back = reread(written, name);
        requireSameLevel(original, back);
        // The writer's output is its own fixed point.
        CHECK(writeLevel(back, "# " + name + ", written back") == written);
        // The solution plays the same on both, to the bit.
        const ScriptLoad solution = loadScriptFile(kLevels / (name + ".solution.toml"), back);
        INFO((solution.errors.empty() ? std::string() : solution.errors.front().format()));
        REQUIRE(solution.script);
        const std::int64_t steps = original.level.goal && original.level.goal->timeLimit
                                       ? static_cast<std::int64_t>(*original.level.goal->timeLimit / 0.01)
                                       : 600;
        const auto before = play(original, *solution.script, steps);
        const auto after = play(back, *solution.script, steps);
        CHECK(before.first.has_value());
        CHECK(before.first == after.first);
        CHECK(before.second == after.second);
        // And `rube check --strict` passes the written level with its solution beside it.
        const std::filesystem::path folder = std::filesystem::temp_directory_path() / "rube-level-writer";
        std::filesystem::create_directories(folder);
        std::ofstream(folder / (name + ".toml")) << written;
        std::filesystem::copy_file(kLevels / (name + ".solution.toml"), folder / (name + ".solution.toml"),
                                   std::filesystem::copy_options::overwrite_existing);
        CheckOptions check;
        check.files = {(folder / (name + ".toml")).string(), (folder / (name + ".solution.toml")).string()};
        check.strict = true;
        std::ostringstream out, err;
        INFO(err.str());
        CHECK(checkFiles(check, out, err) == ExitCode::ok);
        INFO(err.str());
        CHECK(err.str().empty());
        ++levels;
    }
    CHECK(levels >= 17);
}

TEST_CASE("a level changed in memory is written as changed", "[level][writer]") {
    const SceneLoad load = loadSceneFile(kLevels / "cannon-arc.toml");
    REQUIRE(load.ok());
    // Over a range of moves and turns, the written file reads back to the moved, turned item.
    for (int k = -3; k <= 3; ++k) {
        SceneDesc level = *load.scene;
        ItemDesc& gun = level.level.items[static_cast<std::size_t>(level.level.find("gun"))];
        gun.position = gun.position + Vec2{0.25 * k, 0.05 * k};
        gun.angleDegrees = 15.0 * k;
        gun.angle = 15.0 * k * std::numbers::pi / 180.0;
        level.level.inventory["plank"] = k + 4;
        level.level.hints.push_back({"hint " + std::to_string(k), {}});
        level.level.goal->timeLimit = 5.0 + k;
        const SceneDesc back = reread(writeLevel(level), "changed");
        requireSameLevel(level, back);
        // The goal made a reach-area one, for any ball and for a named one (the editor keeps it so).
        level.level.goal->kind = GoalKind::reachArea;
        level.level.goal->item.clear();
        level.level.goal->area = {{-1.0 + 0.3 * k, 0.5}, {2.0, 3.25 + 0.1 * k}};
        if (k >= 0) {
            ItemDesc ball = partKind("steel")->make({0.5 * k, 1.0});
            ball.name = "ball";
            level.level.items.push_back(ball);
            level.level.goal->item = "ball";
        }
        requireSameLevel(level, reread(writeLevel(level), "changed"));
    }
}
