// Shortcuts `rube solve` found in shipped levels, and the fixes: the level as it was is searched
// again and the shortcut is found; the level as it ships is searched whole and none is.
#include "scene_file.hpp"
#include "solve_report.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace rube::game;

namespace {

SolveReport solve(const SceneDesc& level, const std::string& scriptFile, std::uint64_t budget) {
    const ScriptLoad intended = loadScriptFile(scriptFile, level);
    REQUIRE(intended.script);
    const SearchSpace space(level, {});
    SolveOptions options;
    options.budget = budget;
    options.jobs = 2;
    return makeReport(searchLevel(level, space, options), space, partsUsed(*intended.script));
}

// The level as it was before a fix: its file with the text `now` (which must be in it) written back as `was`.
SceneLoad levelAsItWas(const std::string& file, const std::string& now, const std::string& was) {
    SceneError error;
    std::string text = readTextFile(file, error).value();
    const std::size_t at = text.find(now);
    REQUIRE(at != std::string::npos);
    text.replace(at, now.size(), was);
    return parseScene(text, file);
}

} // namespace

TEST_CASE("pegs gave a heavy ball that was a shortcut dropped beside the top pin, and now gives none") {
    const std::string file = RUBE_GAME_LEVELS_DIR "/pegs.toml";
    const std::string script = RUBE_GAME_LEVELS_DIR "/pegs.solution.toml";
    // The level as it was: a heavy ball in the inventory beside the bouncy one.
    const std::string inventory = "[inventory]\nbouncy = 1\n";
    const SceneLoad old = levelAsItWas(file, inventory, inventory + "heavy = 1\n");
    REQUIRE(old.ok());
    // 1200 runs search the heavy ball's 300 placements whole (an equal share of the budget each).
    const SolveReport was = solve(*old.scene, script, 1200);
    REQUIRE(planSearch(SearchSpace(*old.scene, {}), 1200).whole[2]);
    const auto heavyAlone = std::find_if(was.groups.begin(), was.groups.end(),
                                         [](const SolutionGroup& g) { return g.uses == "heavy"; });
    REQUIRE(heavyAlone != was.groups.end());
    CHECK_FALSE(heavyAlone->shortcut.empty());

    const SceneLoad now = loadSceneFile(file);
    REQUIRE(now.ok());
    const SearchSpace space(*now.scene, {});
    const SolveReport is = solve(*now.scene, script, space.size());
    CHECK(is.exhaustive);
    CHECK_FALSE(is.result.solutions.empty());
    CHECK(is.shortcuts() == 0);
}

TEST_CASE("rope, chain-reaction and balloon were solved by clicks alone, and now let no click act") {
    for (const char* name : {"rope", "chain-reaction", "balloon"}) {
        CAPTURE(name);
        const std::string file = std::string(RUBE_GAME_LEVELS_DIR "/") + name + ".toml";
        const std::string script = std::string(RUBE_GAME_LEVELS_DIR "/") + name + ".solution.toml";
        // The level as it was: every part a click acts on could be clicked.
        const SceneLoad old = levelAsItWas(file, "clicks = []\n", "");
        REQUIRE(old.ok());
        // Placing nothing is its own subset, searched whole within this budget: clicks alone solved it.
        const SolveReport was = solve(*old.scene, script, 400);
        const auto clicksAlone = std::find_if(was.groups.begin(), was.groups.end(), [](const SolutionGroup& g) {
            // One kind of click alone: no ';' between subsets, no '+' between kinds (a character test:
            // g++ 12 warns falsely on std::string::find inlined through the precompiled header).
            const bool one = std::none_of(g.uses.begin(), g.uses.end(), [](char c) { return c == ';' || c == '+'; });
            return one && g.uses != "nothing" &&
                   (g.uses.starts_with("aim") || g.uses.starts_with("fire") || g.uses.starts_with("detonate") ||
                    g.uses.starts_with("toggle"));
        });
        REQUIRE(clicksAlone != was.groups.end());
        CHECK_FALSE(clicksAlone->shortcut.empty());

        const SceneLoad now = loadSceneFile(file);
        REQUIRE(now.ok());
        const SolveReport is = solve(*now.scene, script, 400);
        CHECK_FALSE(is.result.solutions.empty());
        for (const SolutionGroup& g : is.groups) {
            CAPTURE(g.uses);
            // What the groups may still use: parts, and aims (editing); no fire, detonate or toggle.
            CHECK(g.uses.find("fire ") == std::string::npos);
            CHECK(g.uses.find("detonate ") == std::string::npos);
            CHECK(g.uses.find("toggle ") == std::string::npos);
        }
    }
    // rope gives one heavy ball and nothing else to do: searched whole, it has no shortcut left.
    const SceneLoad rope = loadSceneFile(RUBE_GAME_LEVELS_DIR "/rope.toml");
    REQUIRE(rope.ok());
    const SolveReport whole = solve(*rope.scene, RUBE_GAME_LEVELS_DIR "/rope.solution.toml",
                                    SearchSpace(*rope.scene, {}).size());
    CHECK(whole.exhaustive);
    CHECK(whole.shortcuts() == 0);
}

TEST_CASE("gears had a catapult paddle under the zone that a heavy ball alone glanced off onto the switch, and "
          "shorter paddles leave no shortcut") {
    const std::string file = RUBE_GAME_LEVELS_DIR "/gears.toml";
    const std::string script = RUBE_GAME_LEVELS_DIR "/gears.solution.toml";
    // The level as it was: paddles of 0.9 m, the left tip at x = -2.33 m, under the zone (to -2.15 m).
    const SceneLoad old = levelAsItWas(file, "paddle = 0.6\n", "paddle = 0.9\n");
    REQUIRE(old.ok());
    const auto heavyAlone = [](const SolveReport& report) {
        return std::find_if(report.groups.begin(), report.groups.end(),
                            [](const SolutionGroup& g) { return g.uses == "heavy"; });
    };
    // 2000 runs search the heavy ball's 416 placements whole (subsets: nothing, ramp, heavy, both).
    const SolveReport was = solve(*old.scene, script, 2000);
    REQUIRE(planSearch(SearchSpace(*old.scene, {}), 2000).whole[2]);
    REQUIRE(heavyAlone(was) != was.groups.end());
    CHECK_FALSE(heavyAlone(was)->shortcut.empty());

    const SceneLoad now = loadSceneFile(file);
    REQUIRE(now.ok());
    REQUIRE(planSearch(SearchSpace(*now.scene, {}), 2000).whole[2]);
    const SolveReport is = solve(*now.scene, script, 2000);
    CHECK_FALSE(is.result.solutions.empty());
    CHECK(heavyAlone(is) == is.groups.end());
    CHECK(is.shortcuts() == 0);
}
