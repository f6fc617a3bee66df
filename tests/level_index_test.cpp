// levels/index.toml: every shipped level listed once, in a readable order, and the reader's errors.
#include "level_folder.hpp"
#include "level_index.hpp"
#include "scene_file.hpp"
#include "script_file.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <set>

using namespace rube::game;
namespace fs = std::filesystem;

namespace {

const fs::path kLevels = RUBE_GAME_LEVELS_DIR;

std::string firstError(const LevelIndexLoad& load) {
    REQUIRE_FALSE(load.errors.empty());
    return load.errors.front().format();
}

bool anyError(const LevelIndexLoad& load, const std::string& text) {
    for (const SceneError& e : load.errors)
        if (e.format() == text) return true;
    return false;
}

// The part kinds a level shows or gives: its items', its inventory's and what its solution places.
std::set<std::string_view> kindsOf(const IndexedLevel& level) {
    const SceneLoad scene = loadSceneFile(level.file);
    REQUIRE(scene.ok());
    std::set<std::string_view> kinds;
    for (const ItemDesc& item : scene.scene->level.items) kinds.insert(item.kind->name());
    for (const auto& entry : scene.scene->level.inventory) kinds.insert(partKind(entry.first)->name());
    fs::path solution = level.file;
    solution.replace_extension(".solution.toml");
    const ScriptLoad script = loadScriptFile(solution, *scene.scene);
    REQUIRE(script.script);
    for (const Placement& placed : script.script->placements) kinds.insert(placed.kind->name());
    return kinds;
}

} // namespace

TEST_CASE("the level index lists every shipped level exactly once", "[index]") {
    const LevelIndexLoad load = loadLevelIndex(kLevels / "index.toml");
    for (const SceneError& e : load.errors) FAIL(e.format());
    REQUIRE(load.levels);
    std::set<fs::path> listed;
    for (const IndexedLevel& level : *load.levels) listed.insert(fs::canonical(level.file));
    std::set<fs::path> shipped;
    for (const LevelFile& file : levelFilesIn(kLevels, LevelFileRole::level)) shipped.insert(fs::canonical(file.path));
    CHECK(listed == shipped);
    CHECK(load.levels->size() == listed.size());
}

TEST_CASE("the level index's difficulty never falls by more than one from one level to the next", "[index]") {
    const LevelIndexLoad load = loadLevelIndex(kLevels / "index.toml");
    REQUIRE(load.levels);
    for (std::size_t i = 1; i < load.levels->size(); ++i) {
        INFO((*load.levels)[i].file);
        CHECK((*load.levels)[i].difficulty >= (*load.levels)[i - 1].difficulty - 1);
    }
}

TEST_CASE("the level index reports bad entries at their place", "[index]") {
    CHECK(firstError(parseLevelIndex("[[level]]\nfile = \"ramp.toml\"\ntitle = \"x\"\ndifficulty = 9\n", "i.toml",
                                     kLevels)) == "i.toml:4:14: difficulty must be between 1 and 5, got 9");
    CHECK(firstError(parseLevelIndex("[[level]]\nfile = \"nope.toml\"\ntitle = \"x\"\ndifficulty = 1\n", "i.toml",
                                     kLevels)) == "i.toml:2:8: no level file 'nope.toml' beside the index");
    CHECK(firstError(parseLevelIndex("[[level]]\nfile = \"ramp.toml\"\ntitle = \"x\"\ndifficulty = 1\n"
                                     "introduces = [\"rampp\"]\n",
                                     "i.toml", kLevels)) == "i.toml:5:15: unknown part kind 'rampp' (did you mean 'ramp'?)");
    CHECK(firstError(parseLevelIndex("[[level]]\nfile = \"ramp.toml\"\ntitle = \"a\"\ndifficulty = 1\n"
                                     "[[level]]\nfile = \"ramp.toml\"\ntitle = \"b\"\ndifficulty = 1\n",
                                     "i.toml", kLevels)) == "i.toml:6:8: 'ramp.toml' is listed already, at line 1");
    CHECK(anyError(parseLevelIndex("[[level]]\nfile = \"ramp.toml\"\ntitel = \"a\"\ndifficulty = 1\n", "i.toml", kLevels),
                   "i.toml:3:1: unknown key 'titel' in [[level]] (did you mean 'title'?)"));
    CHECK(firstError(parseLevelIndex("[[level]]\nfile = \"ramp.toml\"\ntitle = \"x\"\ndifficulty = 1\n"
                                     "solve_budget = 10\nsolve_fraction = 1.5\n",
                                     "i.toml", kLevels)) ==
          "i.toml:6:18: solve_fraction must be between 0 and 1, got 1.5");
    CHECK(firstError(parseLevelIndex("[[level]]\nfile = \"ramp.toml\"\ntitle = \"x\"\ndifficulty = 1\n"
                                     "solve_fraction = 0.5\n",
                                     "i.toml", kLevels)) ==
          "i.toml:5:18: solve_fraction needs solve_budget, the runs it was measured with");
    const LevelIndexLoad measured = parseLevelIndex("[[level]]\nfile = \"ramp.toml\"\ntitle = \"x\"\ndifficulty = 1\n"
                                                    "solve_budget = 10\nsolve_fraction = 0.25\n",
                                                    "i.toml", kLevels);
    REQUIRE(measured.levels);
    CHECK(measured.levels->front().solveBudget == 10);
    CHECK(measured.levels->front().solveFraction == 0.25);
}

// Issue 22: at least eight levels are chain reactions of five or more distinct parts. Counted here:
// the levels the index rates 4 or 5 (hard chains; a hard level of few parts, such as paddle, is not
// one) whose parts, the kinds of the level's items and of what its solution places (the ball that
// starts it and the target it ends on count, as in the example), number five or more.
TEST_CASE("at least eight chain levels, each of five or more distinct part kinds", "[index]") {
    const LevelIndexLoad load = loadLevelIndex(kLevels / "index.toml");
    REQUIRE(load.levels);
    int chains = 0;
    for (const IndexedLevel& level : *load.levels) {
        if (level.difficulty < 4) continue;
        INFO(level.file.filename().string());
        const std::set<std::string_view> kinds = kindsOf(level);
        if (kinds.size() >= 5) ++chains;
    }
    CHECK(chains >= 8);
}

// Issue 22: every part is introduced by a level before a harder one uses it in combination. The
// index's `introduces` names, for each kind, the first level that shows or gives it: once, and no
// level uses a kind that it or an earlier level has not introduced.
TEST_CASE("every part kind is introduced once, by the first level that uses it", "[index]") {
    const LevelIndexLoad load = loadLevelIndex(kLevels / "index.toml");
    REQUIRE(load.levels);
    std::set<std::string> introduced;
    for (const IndexedLevel& level : *load.levels) {
        INFO(level.file.filename().string());
        for (const std::string& kind : level.introduces) {
            INFO(kind);
            CHECK(introduced.insert(kind).second);
        }
        for (const std::string_view kind : kindsOf(level)) {
            INFO(kind);
            CHECK(introduced.count(std::string(kind)) == 1);
        }
    }
    for (ItemKind kind : allPartKinds()) {
        INFO(kind->name());
        CHECK(introduced.count(std::string(kind->name())) == 1);
    }
}
