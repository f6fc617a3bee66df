// Level tests: every level in levels/ is solved by its script and not solved as it stands, the
// placement rules refuse what they should, and aiming through the game layer hits analytically.
#include "level_folder.hpp"
#include "items/part_common.hpp" // a ball's parameters, to start one moving
#include "level_run.hpp"
#include "scene_file.hpp"
#include "script_file.hpp"
#include "solution_nudges.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <optional>
#include <numbers>
#include <filesystem>
#include <map>
#include <tuple>

using namespace rube;
using namespace rube::game;

namespace {

// Every level with a solution (levels/NAME.solution.toml), sorted: a new level is tested by being there.
std::vector<std::string> solvedLevels() {
    std::vector<std::string> names;
    for (const LevelFile& file : levelFilesIn(RUBE_GAME_LEVELS_DIR, LevelFileRole::solution)) names.push_back(file.level);
    return names;
}

SceneDesc loadLevel(const std::string& name) {
    const SceneLoad load = loadSceneFile(std::filesystem::path(RUBE_GAME_LEVELS_DIR) / (name + ".toml"));
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return *load.scene;
}

// Plays a level with its script (headless) and returns the run; actions as `rube run` takes them.
LevelRun play(const SceneDesc& level, const ScriptDesc& script, std::int64_t steps) {
    LevelRun run(level, script.placements);
    std::size_t next = 0;
    for (std::int64_t i = 0; i < steps; ++i) {
        for (; next < script.actions.size() && script.actions[next].step == i; ++next)
            REQUIRE(takeAction(script.actions[next], run).empty());
        run.step();
    }
    return run;
}

SceneDesc parseLevel(const std::string& text) {
    const SceneLoad load = parseScene(text, "test.toml");
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return *load.scene;
}

std::string firstError(const std::string& text) {
    const SceneLoad load = parseScene(text, "t.toml");
    return load.errors.empty() ? std::string("no error") : load.errors.front().format();
}

} // namespace

TEST_CASE("each level's solution reaches the goal, and the level as it stands does not", "[level]") {
    const std::vector<std::string> levels = solvedLevels();
    REQUIRE(levels.size() >= 16);
    for (const std::string& name : levels) {
        INFO(name);
        const SceneDesc level = loadLevel(name);
        const ScriptLoad script = loadScriptFile(
            std::filesystem::path(RUBE_GAME_LEVELS_DIR) / (name + ".solution.toml"), level);
        INFO((script.errors.empty() ? std::string() : script.errors.front().format()));
        REQUIRE(script.script);
        REQUIRE(level.level.goal->timeLimit);
        const auto steps = static_cast<std::int64_t>(*level.level.goal->timeLimit / level.world.timeStep);
        CHECK(play(level, *script.script, steps).goalStep().has_value());
        CHECK_FALSE(play(level, ScriptDesc{}, steps).goalStep().has_value());
    }
}

// Issue 22: a level is a puzzle only if the plausible wrong ideas fail. Each level ships at least two
// wrong attempts (NAME.wrong.WORD.toml, level_folder.hpp), each placing or doing something the
// level allows; none may reach the goal. Another intended solution (NAME.solution.WORD.toml) must
// reach it, with placements other than the intended solution's.
TEST_CASE("each level's wrong attempts fail and its other solutions reach the goal", "[level]") {
    std::map<std::string, int> wrongs;
    for (const LevelFile& file : levelFilesIn(RUBE_GAME_LEVELS_DIR, LevelFileRole::wrong)) {
        INFO(file.path.filename().string());
        const SceneDesc level = loadLevel(file.level);
        const ScriptLoad script = loadScriptFile(file.path, level);
        INFO((script.errors.empty() ? std::string() : script.errors.front().format()));
        REQUIRE(script.script);
        REQUIRE(checkPlacements(level, script.script->placements) == std::nullopt);
        CHECK((!script.script->placements.empty() || !script.script->actions.empty()));
        const auto steps = static_cast<std::int64_t>(*level.level.goal->timeLimit / level.world.timeStep);
        CHECK_FALSE(play(level, *script.script, steps).goalStep().has_value());
        ++wrongs[file.level];
    }
    for (const std::string& name : solvedLevels()) {
        INFO(name << " has " << wrongs[name] << " wrong attempts (NAME.wrong.WORD.toml); it needs two");
        CHECK(wrongs[name] >= 2);
    }
    int alternatives = 0;
    for (const LevelFile& file : levelFilesIn(RUBE_GAME_LEVELS_DIR, LevelFileRole::alternative)) {
        ++alternatives;
        INFO(file.path.filename().string());
        const SceneDesc level = loadLevel(file.level);
        const ScriptLoad script = loadScriptFile(file.path, level);
        INFO((script.errors.empty() ? std::string() : script.errors.front().format()));
        REQUIRE(script.script);
        const ScriptLoad intended = loadScriptFile(
            std::filesystem::path(RUBE_GAME_LEVELS_DIR) / (file.level + ".solution.toml"), level);
        REQUIRE(intended.script);
        const auto key = [](const std::vector<Placement>& placements) {
            std::vector<std::tuple<std::string_view, double, double, double>> parts;
            for (const Placement& p : placements) parts.emplace_back(p.kind->name(), p.position.x, p.position.y, p.angle);
            std::sort(parts.begin(), parts.end());
            return parts;
        };
        CHECK(key(script.script->placements) != key(intended.script->placements));
        const auto steps = static_cast<std::int64_t>(*level.level.goal->timeLimit / level.world.timeStep);
        CHECK(play(level, *script.script, steps).goalStep().has_value());
    }
    CHECK(alternatives >= 1);
}

// A solution should not hang on one point of the play window's 5 cm grid: a player who has the idea
// would also have to find the one spot, and any change to the engine could tip the shipped solution
// over. chain-door's did: 3 of 12 drops on its switch reached the goal, and the file described a
// throw that never happened. So every solution script (NAME.solution.toml and each
// NAME.solution.WORD.toml) must still reach the goal with any one of its placements moved one grid
// step either way along x or y. A move the placement rules refuse (out of its zone, onto a part) is
// skipped, but every placement must keep at least one.
TEST_CASE("each level's solutions still reach the goal with a placement moved one 5 cm grid step", "[level][nudges]") {
    std::vector<LevelFile> files = levelFilesIn(RUBE_GAME_LEVELS_DIR, LevelFileRole::solution);
    for (const LevelFile& file : levelFilesIn(RUBE_GAME_LEVELS_DIR, LevelFileRole::alternative)) files.push_back(file);
    REQUIRE(files.size() >= 60);
    int moves = 0;
    for (const LevelFile& file : files) {
        INFO(file.path.filename().string());
        const SceneDesc level = loadLevel(file.level);
        const ScriptLoad script = loadScriptFile(file.path, level);
        REQUIRE(script.script);
        const auto steps = static_cast<std::int64_t>(*level.level.goal->timeLimit / level.world.timeStep);
        const std::vector<PlacementNudge> nudges = nudgePlacements(level, *script.script, steps);
        CHECK(nudges.size() == 4 * script.script->placements.size());
        for (std::size_t i = 0; i < script.script->placements.size(); ++i) {
            int tried = 0;
            for (const PlacementNudge& n : nudges) {
                if (n.placement != i || n.refused) continue;
                ++tried;
                ++moves;
                INFO(describeNudge(*script.script, n));
                CHECK(n.reached);
            }
            INFO("placement " << i << ": every move one grid step either way was refused");
            CHECK(tried > 0);
        }
    }
    CHECK(moves >= 200);
}

// Issue 23: the goal event says where the goal happened and what did it. For a target goal, the hit
// that completed it: its point of impact (on the target's surface, within a radius of its centre)
// and the ball that struck; for a bucket, the ball resting in it. It was [0, 0] and nobody.
TEST_CASE("each level's goal event is where the goal happened, by what did it", "[level]") {
    int byNamed = 0;
    for (const std::string& name : solvedLevels()) {
        INFO(name);
        const SceneDesc level = loadLevel(name);
        const ScriptLoad script = loadScriptFile(
            std::filesystem::path(RUBE_GAME_LEVELS_DIR) / (name + ".solution.toml"), level);
        REQUIRE(script.script);
        const auto steps = static_cast<std::int64_t>(*level.level.goal->timeLimit / level.world.timeStep);
        const LevelRun run = play(level, *script.script, steps);
        REQUIRE(run.goalStep());
        const GameEvent& goal = *std::find_if(run.events().begin(), run.events().end(),
                                              [](const GameEvent& e) { return e.kind == EventKind::goal; });
        CHECK(goal.step == *run.goalStep());
        if (level.level.goal->kind == GoalKind::ballInBucket) {
            const ItemDesc& bucket = run.items()[static_cast<std::size_t>(run.find(level.level.goal->item))];
            CHECK(bucket.kind->holds(bucket, goal.position));
        } else if (level.level.goal->kind == GoalKind::reachArea) {
            // Where the item's centre came into the area: inside it, and the goal's item did it.
            const Aabb& area = level.level.goal->area;
            CHECK(goal.position.x >= area.min.x);
            CHECK(goal.position.x <= area.max.x);
            CHECK(goal.position.y >= area.min.y);
            CHECK(goal.position.y <= area.max.y);
            if (!level.level.goal->item.empty()) CHECK(goal.by == level.level.goal->item);
        } else {
            // The latest hit on a goal target, at the goal's step, is the one the goal repeats.
            const auto hit = std::find_if(run.events().rbegin(), run.events().rend(), [&](const GameEvent& e) {
                return e.kind == EventKind::hit && e.step == goal.step;
            });
            REQUIRE(hit != run.events().rend());
            CHECK(goal.position == hit->position);
            CHECK(goal.by == hit->by);
            // On the target's surface, for a target that stays put (a moving one has moved on since).
            const int target = run.find(hit->item);
            const double radius = run.world().circle(run.states()[static_cast<std::size_t>(target)].circle).radius;
            if (run.itemVelocity(target) == Vec2{})
                CHECK((goal.position - run.itemPosition(target)).length() <= radius * 1.01);
        }
        if (!goal.by.empty()) ++byNamed;
        // What the levels' own words say did it.
        if (name == "balloon") CHECK(goal.by == "gun");       // the cannon's shot
        if (name == "crates") CHECK(goal.by == "last-crate"); // a [[box]], knocked onto the flag
    }
    CHECK(byNamed >= 3);
}

TEST_CASE("a hit names the ball that struck: an item, a placement, a cannon's shot", "[level]") {
    const SceneDesc level = parseLevel(
        "name = \"who\"\n[world]\ntime_step = 0.01\n[[segment]]\na = [-8, 0]\nb = [8, 0]\n"
        "[[item]]\nkind = \"heavy\"\nname = \"red\"\nposition = [0, 3]\n"
        "[[item]]\nkind = \"target\"\nname = \"flag\"\nposition = [0, 0.35]\n"
        "[[item]]\nkind = \"target\"\nname = \"far\"\nposition = [4, 0.35]\n"
        "[[item]]\nkind = \"target\"\nname = \"high\"\nposition = [-4, 2.5]\n"
        "[[item]]\nkind = \"cannon\"\nname = \"gun\"\nposition = [-6, 1]\n");
    Placement blue;
    blue.kind = partKind("bouncy");
    blue.position = {4.0, 3.0};
    blue.name = "blue";
    LevelRun run(level, {blue});
    const std::string aimed = run.aimAtItem(run.find("gun"), run.find("high"), false);
    INFO(aimed);
    REQUIRE(aimed.empty());
    run.fire(run.find("gun"));
    for (int i = 0; i < 200; ++i) run.step();
    const auto byOf = [&](const std::string& item) {
        for (const GameEvent& e : run.events())
            if (e.kind == EventKind::hit && e.item == item) return e.by;
        return std::string("no hit");
    };
    CHECK(byOf("flag") == "red");
    CHECK(byOf("far") == "blue");
    CHECK(byOf("high") == "gun");
}

TEST_CASE("level errors are file:line:col messages", "[level]") {
    const std::string floor = "name = \"t\"\n[[segment]]\na = [-5, 0]\nb = [5, 0]\n";
    CHECK(firstError(floor + "[[item]]\nkind = \"plank\"\nposition = [0, 1]\nangel = 30\n") ==
          "t.toml:8:1: unknown key 'angel' in [[item]] of kind 'plank' (did you mean 'angle'?)");
    // The whole catalogue, in its order: today's kinds first, any later kind after them.
    std::string catalogue;
    for (ItemKind kind : allPartKinds()) catalogue += (catalogue.empty() ? "" : ", ") + std::string(kind->name());
    CHECK(catalogue.starts_with("heavy, bouncy, steel, balloon, plank, ramp, bumper, cannon, bomb, target, bucket, "
                                "switch, magnet, fan, rocket"));
    CHECK(firstError(floor + "[[item]]\nkind = \"cannnon\"\nposition = [0, 1]\n") ==
          "t.toml:6:8: kind must be one of " + catalogue + ", got 'cannnon' (did you mean 'cannon'?)");
    CHECK(firstError(floor + "[[item]]\nkind = \"target\"\nname = \"T\"\nposition = [0, 1]\n[goal]\ntext = "
                             "\"x\"\ncondition = \"target-hit\"\ntarget = \"U\"\n") ==
          "t.toml:12:10: unknown target 'U' (the level has: T)");
    CHECK(firstError(floor + "[[item]]\nkind = \"switch\"\nposition = [0, 1]\ntriggers = \"gun\"\n") ==
          "t.toml:8:12: unknown cannon, bomb, fan, magnet, rocket, scissors, timer, candle, laser, lift, conveyor, "
          "motor, launcher, glove, gate, hammer, flipper, car, pendulum or rope 'gun' (the level has no cannon, bomb, fan, "
          "magnet, rocket, scissors, timer, candle, laser, lift, conveyor, motor, launcher, glove, gate, hammer, "
          "flipper, car, pendulum or rope)");
    CHECK(firstError(floor + "[[item]]\nkind = \"bomb\"\nposition = [0, 1]\nstrength = -2\n") ==
          "t.toml:8:12: strength must be greater than 0 and at most 10000, got -2");
    CHECK(firstError(floor + "[inventory]\nplank = \"two\"\n") == "t.toml:6:9: plank must be an integer, got string");
    // Every placeable kind, in the catalogue's order: today's first, any later placeable kind after them.
    std::string placeable;
    for (ItemKind kind : allPartKinds())
        if (kind->placeable()) placeable += (placeable.empty() ? "" : ", ") + std::string(kind->name());
    CHECK(placeable.starts_with("heavy, bouncy, steel, balloon, plank, ramp, bumper, bomb, magnet, fan, rocket"));
    CHECK(firstError(floor + "[inventory]\ncannon = 1\n") ==
          "t.toml:6:1: unknown key 'cannon' in [inventory] (placeable kinds) (known keys: " + placeable + ")");
    CHECK(firstError(floor + "[[circle]]\nname = \"a\"\nposition = [0, 1]\nradius = 0.2\n[[item]]\nkind = "
                             "\"heavy\"\nname = \"a\"\nposition = [2, 1]\n") ==
          "t.toml:11:8: the name 'a' is already used at line 6");
}

TEST_CASE("placements are refused by rule and place", "[level]") {
    const SceneDesc level = loadLevel("ramp");
    const auto refusal = [&](std::vector<Placement> placements) {
        const auto r = checkPlacements(level, placements);
        return r ? r->message : std::string("accepted");
    };
    CHECK(refusal({{partKind("ramp"), {-4.5, 2.5}, -0.5, "", {}}}) == "accepted");
    CHECK(
        refusal({{partKind("plank"), {-4.5, 2.5}, 0.0, "", {}}}) ==
        "placement refused: plank at [-4.5, 2.5] exceeds the inventory: the level gives 0 planks and this is number 1");
    CHECK(refusal({{partKind("ramp"), {-4.5, 2.5}, 0.0, "", {}}, {partKind("ramp"), {-4.5, 3.5}, 0.0, "", {}}})
              .starts_with("placement refused: ramp at [-4.5, 3.5] exceeds the inventory"));
    CHECK(refusal({{partKind("ramp"), {3, 2.5}, 0.0, "", {}}}) ==
          "placement refused: ramp at [3, 2.5] is not wholly inside a placement zone (it spans [1.45, 2.45] to [4.55, "
          "2.55])");
    // Overlaps: with a fixed part inside the zone, and with an earlier placement.
    const SceneDesc crowded = parseLevel("name = \"c\"\n[[item]]\nkind = \"bumper\"\nposition = [0, 0]\n"
                                         "[inventory]\nheavy = 2\n[[zone]]\nmin = [-3, -3]\nmax = [3, 3]\n");
    const auto crowdedRefusal = [&](std::vector<Placement> placements) {
        const auto r = checkPlacements(crowded, placements);
        return r ? r->message : std::string("accepted");
    };
    CHECK(crowdedRefusal({{partKind("heavy"), {0.6, 0.0}, 0.0, "", {}}}) ==
          "placement refused: heavy at [0.6, 0] overlaps the fixed bumper");
    CHECK(crowdedRefusal({{partKind("heavy"), {0.71, 0.0}, 0.0, "", {}}}) == "accepted");
    CHECK(crowdedRefusal({{partKind("heavy"), {2, 0.0}, 0.0, "", {}}, {partKind("heavy"), {2, 0.5}, 0.0, "", {}}}) ==
          "placement refused: heavy at [2, 0.5] overlaps placement 1 (heavy)");
}

TEST_CASE("an aimed gravity shot passes within 1 % of the ball's radius of the aimed point", "[level][aim]") {
    SceneDesc level = parseLevel(
        "name = \"aim\"\n[world]\ntime_step = 0.01\n[[item]]\nkind = \"cannon\"\nname = \"gun\"\n"
        "position = [0, 0]\nspeed = 12\nammo = \"steel\"\n[goal]\ntext = \"x\"\ncondition = \"all-targets\"\n"
        "[[item]]\nkind = \"target\"\nname = \"far\"\nposition = [100, 100]\n");
    for (const bool high : {false, true}) {
        LevelRun run(level, {});
        const Vec2 aimed{9.0, 2.5};
        REQUIRE(run.aimAtPoint(0, aimed, high).empty());
        run.fire(0);
        const int ball = static_cast<int>(run.world().circles().size()) - 1;
        const double radius = run.world().circles()[static_cast<std::size_t>(ball)].radius;
        double closest = 1e9;
        const Vec2 g = run.world().def().gravity;
        for (int i = 0; i < 400; ++i) {
            // Between steps a free ball flies p + v t + g t^2 / 2: look along it, not only at the steps.
            const Circle c = run.world().circles()[static_cast<std::size_t>(ball)];
            for (int k = 0; k < 100; ++k) {
                const double t = 0.01 * k / 100.0;
                closest = std::min(closest, (c.position + c.velocity * t + g * (0.5 * t * t)).distance(aimed));
            }
            run.step();
        }
        INFO((high ? "high" : "low") << " arc, closest " << closest);
        CHECK(closest < 0.01 * radius);
    }
    LevelRun run(level, {});
    CHECK(run.aimAtPoint(0, {60.0, 0.0}, false).starts_with("cannon 'gun' cannot reach [60, 0]: "));
}

TEST_CASE("a led shot hits a target moving at constant velocity", "[level][aim]") {
    const SceneDesc level = loadLevel("moving-target");
    for (const int fireAt : {0, 50, 120}) {
        INFO("fired at step " << fireAt);
        LevelRun run(level, {});
        for (int i = 0; i < fireAt; ++i) run.step();
        REQUIRE(run.aimAtItem(run.find("gun"), run.find("runner"), false).empty());
        run.fire(run.find("gun"));
        for (int i = 0; i < 300 && !run.goalStep(); ++i) run.step();
        CHECK(run.goalStep().has_value());
    }
}

TEST_CASE("a bomb pushes only the bodies within its blast radius", "[level][explosion]") {
    const SceneDesc level = parseLevel(
        "name = \"b\"\n[world]\ngravity = [0, 0]\n[[item]]\nkind = \"bomb\"\nname = \"B\"\n"
        "position = [0, 0]\nblast_radius = 2\nstrength = 4\n[[item]]\nkind = \"steel\"\nposition = [1, 0]\n"
        "[[item]]\nkind = \"steel\"\nposition = [3, 0]\n");
    LevelRun run(level, {});
    const CircleId casing = run.states()[0].circle;
    run.detonate(run.find("B"));
    CHECK(run.world().circle(run.states()[1].circle).velocity.x ==
          Approx(4.0 * 0.5 / 4.0)); // J = 4 (1 - 1/2), m = 4 kg
    CHECK(run.world().circle(run.states()[2].circle).velocity == Vec2{});
    // The casing is gone from the world, and its handle says so.
    CHECK(run.world().circles().size() == 2);
    CHECK_FALSE(run.world().isValid(casing));
    CHECK(run.states()[0].circle.isNull());
    REQUIRE(run.events().size() == 1);
    CHECK(run.events()[0].count == 1);
}

TEST_CASE("the bucket goal needs a ball resting inside it for half a second", "[level]") {
    const SceneDesc level = parseLevel("name = \"b\"\n[world]\ntime_step = 0.01\n[[segment]]\na = [-5, 0]\nb = [5, 0]\n"
                                       "[[item]]\nkind = \"bucket\"\nname = \"pail\"\nposition = [0, 0.05]\nwidth = 2\n"
                                       "[[item]]\nkind = \"heavy\"\nposition = [0, 3]\nvelocity = [0, 0]\n"
                                       "[goal]\ntext = \"x\"\ncondition = \"ball-in-bucket\"\nbucket = \"pail\"\n");
    const auto settle = [&](double vx) {
        SceneDesc moving = level;
        moving.level.items[1].params.as<parts::BallParams>().velocity = {vx, 0.0};
        LevelRun run(moving, {});
        for (int i = 0; i < 300 && !run.goalStep(); ++i) run.step();
        return run.goalStep();
    };
    // Dropped straight in, it lands after sqrt(2 x 2.6 / 9.81) = 0.73 s and counts 0.5 s later.
    const auto frame = settle(0.0);
    REQUIRE(frame);
    CHECK(*frame >= 72 + 50);
    CHECK(*frame <= 73 + 50 + 5);
    // Thrown sideways, it flies over the wall and rests beside the bucket: not in it.
    CHECK_FALSE(settle(4.0));
}

// The reach-area goal: reached the first step the ball's centre is in the area. A ball dropped from
// rest at height h is at h - g t^2 / 2 after t (the exact method's free flight is that parabola), so
// it comes into an area whose top is at y_a in step ceil(sqrt(2 (h - y_a) / g) / dt).
TEST_CASE("reach-area: a dropped ball comes into the area in the step free fall gives", "[level]") {
    const auto levelText = [](double h, double top, double left, const std::string& item) {
        std::string text = "name = \"r\"\n[world]\ntime_step = 0.01\n[[segment]]\na = [-5, 0]\nb = [5, 0]\n"
                           "[[item]]\nkind = \"steel\"\nname = \"drop\"\nposition = [0, " +
                           std::to_string(h) +
                           "]\n[[item]]\nkind = \"bouncy\"\nname = \"still\"\nposition = [3, 0.25]\n"
                           "[goal]\ntext = \"x\"\ncondition = \"reach-area\"\n";
        if (!item.empty()) text += "item = \"" + item + "\"\n";
        return text + "area = { min = [" + std::to_string(left) + ", 0.05], max = [" + std::to_string(left + 2.0) +
               ", " + std::to_string(top) + "] }\ntime_limit = 3\n";
    };
    const auto goalOf = [](const SceneDesc& level) {
        LevelRun run(level, {});
        for (int i = 0; i < 300 && !run.goalStep(); ++i) run.step();
        return std::pair{run.goalStep(), run.events().empty() ? GameEvent{} : run.events().back()};
    };
    int cases = 0;
    for (const double h : {2.0, 3.5, 5.0, 7.25}) {
        for (const double top : {0.4, 0.9, 1.7}) {
            INFO("dropped from " << h << " m into an area up to " << top << " m");
            const double g = 9.81;
            const auto expected = static_cast<std::int64_t>(std::ceil(std::sqrt(2.0 * (h - top) / g) / 0.01));
            // The named ball, and any ball: the same step, by the same ball, at the area's top.
            for (const std::string item : {"drop", ""}) {
                const auto [step, event] = goalOf(parseLevel(levelText(h, top, -1.0, item)));
                REQUIRE(step);
                CHECK(*step == expected);
                CHECK(event.kind == EventKind::goal);
                CHECK(event.by == "drop");
                CHECK(event.position.y <= top);
                CHECK(event.position.y > top - g * 0.01 * (0.01 * static_cast<double>(expected)));
                ++cases;
            }
            // An area beside the fall is never reached, and neither is one for the ball that stays put.
            CHECK_FALSE(goalOf(parseLevel(levelText(h, top, 1.5, "drop"))).first);
            CHECK_FALSE(goalOf(parseLevel(levelText(h, top, -1.0, "still"))).first);
        }
    }
    CHECK(cases == 24);
}

TEST_CASE("reach-area: its keys are read with their places, and other conditions' keys are refused", "[level]") {
    const std::string head = "name = \"t\"\n[[segment]]\na = [-5, 0]\nb = [5, 0]\n[[item]]\nkind = \"steel\"\nname = "
                             "\"ball\"\nposition = [0, 1]\n[[item]]\nkind = \"target\"\nname = \"flag\"\nposition = "
                             "[2, 1]\n[goal]\ntext = \"x\"\n";
    CHECK(firstError(head + "condition = \"reach-area\"\nitem = \"ball\"\n") ==
          "t.toml:13:1: missing required key 'area' in [goal]");
    CHECK(firstError(head + "condition = \"reach-area\"\narea = { min = [1, 0], max = [-1, 3] }\n") ==
          "t.toml:16:30: area max must be greater than min in both x and y, got min [1, 0] and max [-1, 3]");
    CHECK(firstError(head + "condition = \"reach-area\"\narea = { min = [-1, 0], max = [1, 3], mn = 2 }\n") ==
          "t.toml:16:39: unknown key 'mn' in goal.area (known keys: min, max)");
    CHECK(firstError(head + "condition = \"reach-area\"\nitem = \"flag\"\narea = { min = [-1, 0], max = [1, 3] }\n")
              .starts_with("t.toml:16:8: item 'flag' is a target, not a heavy, bouncy, steel, balloon, rocket"));
    CHECK(
        firstError(head + "condition = \"reach-area\"\ntarget = \"flag\"\narea = { min = [-1, 0], max = [1, 3] }\n") ==
        "t.toml:16:10: condition 'reach-area' takes no 'target' (it takes item and area)");
    // A key of another condition was read past without a word before reach-area came.
    CHECK(firstError(head + "condition = \"target-hit\"\ntarget = \"flag\"\nbucket = \"pail\"\n") ==
          "t.toml:17:10: condition 'target-hit' takes no 'bucket' (it takes target)");
    CHECK(firstError(head + "condition = \"all-targets\"\nitem = \"ball\"\n") ==
          "t.toml:16:8: condition 'all-targets' takes no 'item' (it takes no item)");
    CHECK(firstError(head + "condition = \"reach-area\"\nitem = \"ball\"\narea = { min = [-1, 0], max = [1, 3] }\n") ==
          "no error");
}

TEST_CASE("trampoline: the heavy ball dropped where the bouncy one goes does not clear the wall", "[level]") {
    const SceneDesc level = loadLevel("trampoline");
    const std::vector<Placement> heavy{{partKind("heavy"), {-3.8, 5.8}, 0.0, "", {}}};
    REQUIRE_FALSE(checkPlacements(level, heavy));
    LevelRun run(level, heavy);
    for (int i = 0; i < 800; ++i) run.step();
    CHECK_FALSE(run.goalStep());
}

TEST_CASE("magnet: it pulls steel only, the same ball made of rubber slides on under the bell", "[level][fields]") {
    SceneDesc level = loadLevel("magnet");
    const std::vector<Placement> magnet{{partKind("magnet"), {3.6, 1.35}, 0.0, "", {}}};
    REQUIRE_FALSE(checkPlacements(level, magnet));
    const auto reached = [&](const SceneDesc& scene) {
        LevelRun run(scene, magnet);
        for (int i = 0; i < 1000; ++i) run.step();
        return run.goalStep().has_value();
    };
    CHECK(reached(level));
    level.level.items.front().kind = partKind("bouncy"); // same start, not magnetic
    CHECK_FALSE(reached(level));
}

TEST_CASE("fan: a toggle turns it off and on again", "[level][fields]") {
    const SceneDesc level = loadLevel("fan");
    const std::vector<Placement> fan{{partKind("fan"), {-3.0, 0.6}, 74.0 * std::numbers::pi / 180.0, "", {}}};
    REQUIRE_FALSE(checkPlacements(level, fan));
    const auto play = [&](int toggles) {
        LevelRun run(level, fan);
        const int item = static_cast<int>(run.items().size()) - 1;
        REQUIRE(run.items()[static_cast<std::size_t>(item)].kind == partKind("fan"));
        for (int i = 0; i < toggles; ++i) run.toggle(item);
        for (int i = 0; i < 800; ++i) run.step();
        return run;
    };
    const LevelRun off = play(1);
    CHECK_FALSE(off.goalStep());
    CHECK(off.world().circles()[0].position.x < 0.0); // it never crossed the wall
    CHECK(play(2).goalStep());
}

TEST_CASE("fan: the heavy ball dropped in the same air is not lifted over the wall", "[level][fields]") {
    SceneDesc level = loadLevel("fan");
    const std::vector<Placement> fan{{partKind("fan"), {-3.0, 0.6}, 74.0 * std::numbers::pi / 180.0, "", {}}};
    level.level.items.front().kind = partKind("heavy");
    LevelRun run(level, fan);
    for (int i = 0; i < 1200; ++i) run.step();
    CHECK_FALSE(run.goalStep());
    CHECK(run.world().circles()[0].position.x < 0.0); // still behind the wall
}

TEST_CASE("fire-when times a fixed-angle shot so that it hits a moving target", "[level][aim]") {
    const SceneDesc level = loadLevel("moving-target");
    const auto playScript = [&](const std::string& actions) {
        const ScriptLoad load = parseScript("level = \"moving-target\"\n" + actions, "s.toml", level);
        INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
        REQUIRE(load.script);
        return play(level, *load.script, 600);
    };
    // The barrel stays at the level's 45 degrees: only the moment of firing is chosen.
    const LevelRun timed = playScript(
        "[[action]]\nstep = 0\ndo = \"fire-when\"\nitem = \"gun\"\ntarget = \"runner\"\n");
    REQUIRE(timed.goalStep());
    REQUIRE(timed.events().front().kind == EventKind::shot);
    CHECK(timed.events().front().step > 100); // it waited for the runner to come near the arc
    CHECK(timed.states()[static_cast<std::size_t>(timed.find("gun"))].aim == Approx(std::numbers::pi / 4));
    // Fired at once along the same aim, the shot misses: the timing is what hits.
    CHECK_FALSE(playScript("[[action]]\nstep = 0\ndo = \"fire\"\nitem = \"gun\"\n").goalStep());
    // Fired from the next frames too, the timing still finds the runner.
    CHECK(playScript("[[action]]\nstep = 90\ndo = \"fire-when\"\nitem = \"gun\"\ntarget = \"runner\"\n").goalStep());
    // Aimed level and away from it, no timing can meet the runner: a reason, not a shot.
    LevelRun run(level, {});
    run.aim(run.find("gun"), std::numbers::pi);
    CHECK(run.fireWhen(run.find("gun"), run.find("runner"))
              .starts_with("cannon 'gun' cannot time a shot at 'runner' at its aim: "));
    CHECK(run.events().empty());
}

TEST_CASE("fire-when names a cannon and a target", "[level]") {
    const SceneDesc level = loadLevel("moving-target");
    const auto firstScriptError = [&](const std::string& text) {
        const ScriptLoad load = parseScript("level = \"moving-target\"\n" + text, "s.toml", level);
        return load.errors.empty() ? std::string("no error") : load.errors.front().format();
    };
    CHECK(firstScriptError("[[action]]\nstep = 0\ndo = \"fire-when\"\nitem = \"gun\"\n") ==
          "s.toml:2:1: missing required key 'target' in [[action]]");
    CHECK(firstScriptError("[[action]]\nstep = 0\ndo = \"fire-when\"\nitem = \"gun\"\ntarget = \"runer\"\n") ==
          "s.toml:6:10: unknown target, bomb, switch or bucket 'runer' in level 'moving-target' (did you mean "
          "'runner'?)");
    CHECK(firstScriptError(
              "[[action]]\nstep = 0\ndo = \"fire-when\"\nitem = \"gun\"\ntarget = \"runner\"\narc = \"high\"\n") ==
          "s.toml:7:1: unknown key 'arc' in [[action]] (known keys: step, do, item, target)");
}

TEST_CASE("levels and scripts word a bad reference alike", "[level]") {
    const std::string floor = "name = \"t\"\n[[segment]]\na = [-5, 0]\nb = [5, 0]\n";
    CHECK(firstError(
              floor +
              "[[item]]\nkind = \"bomb\"\nname = \"B\"\nposition = [0, 1]\n[[item]]\nkind = \"target\"\nname = \"T\"\n"
              "position = [2, 1]\n[goal]\ntext = \"x\"\ncondition = \"target-hit\"\ntarget = \"B\"\n") ==
          "t.toml:16:10: target 'B' is a bomb, not a target (the level has: T)");
    const SceneDesc level = loadLevel("moving-target");
    const auto scriptError = [&](const std::string& text) {
        const ScriptLoad load = parseScript("level = \"moving-target\"\n" + text, "s.toml", level);
        return load.errors.empty() ? std::string("no error") : load.errors.front().format();
    };
    CHECK(scriptError("[[action]]\nstep = 0\ndo = \"fire\"\nitem = \"runner\"\n") ==
          "s.toml:5:8: item 'runner' is a target, not a cannon (the level has: gun)");
    CHECK(scriptError("[[expect]]\nexplosion = \"gun\"\nbefore_step = 9\n") ==
          "s.toml:3:13: explosion 'gun' is a cannon, not a bomb (the level has no bomb)");
    CHECK(scriptError("[[expect]]\nhit = \"runnr\"\nbefore_step = 9\n") ==
          "s.toml:3:7: unknown target, switch or detector 'runnr' in level 'moving-target' (did you mean 'runner'?)");
}

TEST_CASE("rope: the switch cuts the rope, too early or too late and the ball misses the bucket", "[level][rope]") {
    const SceneDesc level = loadLevel("rope");
    const auto playFrom = [&](double height) {
        const std::vector<Placement> drop{{partKind("heavy"), {-5.0, height}, 0.0, "", {}}};
        REQUIRE_FALSE(checkPlacements(level, drop));
        LevelRun run(level, drop);
        for (int i = 0; i < 480; ++i) run.step();
        return run;
    };
    const LevelRun solved = playFrom(5.2);
    CHECK(solved.goalStep());
    CHECK(solved.world().ropes()[0].cut);
    CHECK_FALSE(playFrom(3.0).goalStep()); // cut on the way down: it falls short
    CHECK_FALSE(playFrom(8.0).goalStep()); // cut on the way up: it flies over
    // Nothing placed: the rope holds and the ball swings on, always exactly L from the anchor.
    LevelRun idle(level, {});
    double worst = 0.0;
    for (int i = 0; i < 480; ++i) {
        idle.step();
        worst = std::max(worst, std::abs(idle.world().circles()[0].position.distance({0.0, 6.0}) - 3.0));
    }
    CHECK_FALSE(idle.world().ropes()[0].cut);
    CHECK(worst < 1e-12);
}

TEST_CASE("rope: a script cuts a rope by name, an unknown rope is an error at its place", "[level][rope]") {
    const SceneDesc level = loadLevel("rope");
    const ScriptLoad ok = parseScript("level = \"rope\"\n[[action]]\nstep = 54\ndo = \"cut\"\nitem = \"rope\"\n",
                                      "s.toml", level);
    REQUIRE(ok.script);
    LevelRun run = play(level, *ok.script, 480);
    CHECK(run.world().ropes()[0].cut);
    CHECK(run.goalStep()); // cut at the same moment the switch would: the same throw
    const ScriptLoad bad = parseScript("level = \"rope\"\n[[action]]\nstep = 54\ndo = \"cut\"\nitem = \"rpoe\"\n",
                                       "s.toml", level);
    REQUIRE(bad.errors.size() == 1);
    CHECK(bad.errors[0].format() == "s.toml:5:8: unknown rope 'rpoe' in level 'rope' (did you mean 'rope'?)");
}

TEST_CASE("rope: a switch may name a rope, a name that is neither item nor rope is still refused", "[level][rope]") {
    const std::string base = "name = \"t\"\n[[circle]]\nname = \"bob\"\nposition = [0, 1]\nradius = 0.2\n"
                             "[[rope]]\nname = \"line\"\ncircle = \"bob\"\nanchor = [0, 3]\n"
                             "[[item]]\nkind = \"switch\"\nposition = [3, 0]\n";
    CHECK(firstError(base + "triggers = \"line\"\n") == "no error");
    // Ropes are among what a switch can switch, so a typo of a rope's name is offered the rope.
    CHECK(firstError(base + "triggers = \"lnie\"\n") ==
          "t.toml:13:12: unknown cannon, bomb, fan, magnet, rocket, "
          "scissors, timer, candle, laser, lift, conveyor, motor, launcher, glove, "
          "gate, hammer, flipper, car, pendulum or rope 'lnie' (did you mean 'line'?)");
}

TEST_CASE("paddle: the ramp too steep misses the paddle, and a paddle that never turns never throws the wheel",
          "[level][kinematic]") {
    const auto placed = [](double angle) {
        return std::vector<Placement>{{partKind("ramp"), {-1.0, 2.25}, angle * std::numbers::pi / 180.0, "", {}}};
    };
    const auto run = [](const SceneDesc& level, const std::vector<Placement>& placements) {
        LevelRun r(level, placements);
        for (int i = 0; i < 1000; ++i) r.step();
        return r;
    };
    SceneDesc level = loadLevel("paddle");
    REQUIRE_FALSE(checkPlacements(level, placed(-15.0)));
    CHECK(run(level, placed(-15.0)).goalStep());
    CHECK_FALSE(run(level, placed(-40.0)).goalStep()); // the wheel shoots past the paddle's lip side
    // The same paddle held at rest: the wheel lies on it and never reaches the flag.
    for (NamedPath& path : level.paths)
        for (PathKey& key : path.path.keys) key.angle = 8.0 * std::numbers::pi / 180.0;
    CHECK_FALSE(run(level, placed(-15.0)).goalStep());
}

TEST_CASE("seesaw: the heavy ball turns the seesaw only from left of the pivot, the dominoes fall in turn",
          "[level][seesaw]") {
    const SceneDesc level = loadLevel("seesaw");
    REQUIRE(level.world.method == Method::automatic);
    // Bodies: 0 the plank, 1 the box on its right end, 2..6 the dominoes (file order); circles:
    // 0 the marble, 1 the striker, 2 the placed heavy ball.
    struct Played {
        std::optional<std::int64_t> goal;
        double plankAngle = 0.0;     // at the end, counter-clockwise
        std::array<int, 5> fellAt{}; // the step each domino passed 45 degrees leftwards (-1: never)
        double heavyLeftmost = 1e9;  // the heavy ball's smallest x
    };
    const auto playFrom = [&](std::optional<double> x) {
        std::vector<Placement> drop;
        if (x) drop.push_back({partKind("heavy"), {*x, 3.0}, 0.0, "", {}});
        REQUIRE_FALSE(checkPlacements(level, drop));
        LevelRun run(level, drop);
        Played played;
        played.fellAt.fill(-1);
        for (int i = 0; i < 480; ++i) {
            run.step();
            for (std::size_t d = 0; d < 5; ++d)
                if (played.fellAt[d] < 0 && run.world().bodies()[d + 2].angle > std::numbers::pi / 4.0)
                    played.fellAt[d] = i + 1;
            if (x) played.heavyLeftmost = std::min(played.heavyLeftmost, run.world().circles()[2].position.x);
        }
        played.goal = run.goalStep();
        played.plankAngle = run.world().bodies()[0].angle;
        return played;
    };
    const Played solved = playFrom(0.3);
    REQUIRE(solved.goal);
    // 314 with warm-started friction (3db5d9d; 308 with rigid warm starting, 299 before; this check did not
    // run from 3db5d9d to 20c2154, its name held a ';' that ctest split). 297 since auto chooses per island:
    // the heavy ball falls on exact's parabola until it nears the plank (the solver's semi-implicit fall
    // was 2.6 mm lower after 19 steps), so it strikes the plank at another instant. 303 since the rigid
    // contacts are solved in colours (issue 26: another Gauss-Seidel order; the dominoes fall at the same steps).
    // 295 since auto lets its solver islands of boxes sleep (issue 26): the settled dominoes rest until struck.
    // 297 since a contact's two points are solved together (rigid_normal_pair.hpp): a domino no longer
    // turns where it lands on both corners. 296 since the dominoes' contacts with each other and the
    // floor stack (RigidContact::stacking: stiffer, relaxed once), and fall a step sooner.
    CHECK(*solved.goal == 296);
    // Turned over: left end down on the floor, 1.5 sin a + 0.05 cos a = 0.6, a = 0.378 rad.
    CHECK(solved.plankAngle == Approx(0.378).margin(0.005));
    CHECK(solved.heavyLeftmost > -0.3); // the gate stopped the heavy ball: only the striker went on
    INFO("fell at steps " << solved.fellAt[0] << " " << solved.fellAt[1] << " " << solved.fellAt[2] << " "
                          << solved.fellAt[3] << " " << solved.fellAt[4]);
    CHECK(solved.fellAt[0] > 0);
    for (std::size_t d = 1; d < 5; ++d) CHECK(solved.fellAt[d] > solved.fellAt[d - 1]); // one after another
    CHECK(playFrom(0.7).goal);
    CHECK_FALSE(playFrom(1.6).goal); // right of the pivot: the plank does not turn over
    CHECK_FALSE(playFrom(2.7).goal); // on the low end: the ball rolls off to the right
    // Nothing placed: the plank rests on its right end and no domino falls.
    const Played idle = playFrom(std::nullopt);
    CHECK_FALSE(idle.goal);
    CHECK(idle.plankAngle == Approx(-0.378).margin(0.005));
    for (const int step : idle.fellAt) CHECK(step < 0);
}

TEST_CASE("crates: the crates' impacts are on one axis, v' = u - C (v - u), too low or too high a drop misses",
          "[level][block]") {
    const SceneDesc level = loadLevel("crates");
    REQUIRE(level.world.method == Method::automatic);
    // Bodies: 0 the crate under the gate, 1 the last crate (4 kg each, C = 1); circles: 0 the flag
    // (C = 0.5), 1 the placed steel ball (4 kg, C = 0.7).
    const auto drop = [](double x, double y) {
        return std::vector<Placement>{{partKind("steel"), {x, y}, 0.0, "", {}}};
    };
    REQUIRE_FALSE(checkPlacements(level, drop(-4.5, 5.0)));
    LevelRun run(level, drop(-4.5, 5.0));
    REQUIRE(run.world().circles().size() == 2);
    REQUIRE(run.world().circles()[1].radius == 0.2);
    REQUIRE(run.world().bodies().size() == 2);
    const double g = run.world().def().gravity.y;
    const auto vx = [](double mass1, double v1, double mass2, double v2, double c) {
        const double u = (mass1 * v1 + mass2 * v2) / (mass1 + mass2); // the centre of mass's velocity
        return std::pair{u - c * (v1 - u), u - c * (v2 - u)};         // v' = u - C (v - u) on the axis
    };
    int ballOnCrate = -1, crateOnCrate = -1, crateOnFlag = -1;
    double ballAtImpact = 0.0, crateAtImpact = 0.0, flagApproach = 0.0, ballRightmost = -1e9;
    for (int i = 0; i < 480; ++i) {
        const Vec2 ballBefore = run.world().circles()[1].velocity;
        const Vec2 crateBefore = run.world().bodies()[0].velocity;
        const Vec2 lastBefore = run.world().bodies()[1].velocity;
        run.step();
        const Vec2 ball = run.world().circles()[1].velocity;
        const Vec2 crate = run.world().bodies()[0].velocity;
        const Vec2 last = run.world().bodies()[1].velocity;
        ballRightmost = std::max(ballRightmost, run.world().circles()[1].position.x);
        for (const Impact& impact : run.world().lastImpacts()) {
            if (impact.body < 0 || impact.approachSpeed < 0.5) continue; // resting contacts on the shelf
            INFO("step " << i + 1 << " block " << impact.body << " normal " << impact.normal.x << " "
                         << impact.normal.y);
            if (impact.body == 0 && impact.otherKind == Other::circle && impact.other == 1) {
                // The ball meets the crate's left face: x axis only; the shelf keeps both at vy = 0.
                ballOnCrate = i + 1;
                ballAtImpact = ballBefore.x;
                CHECK(impact.normal == Vec2{1.0, 0.0});
                CHECK(crateBefore.x == 0.0);
                const auto [ballAfter, crateAfter] = vx(4.0, ballBefore.x, 4.0, crateBefore.x, 0.7);
                CHECK(ball.x == Approx(ballAfter).epsilon(1e-12));   // 0.15 v
                CHECK(crate.x == Approx(crateAfter).epsilon(1e-12)); // 0.85 v
                CHECK(ball.x == Approx(0.15 * ballBefore.x).epsilon(1e-12));
            } else if (impact.body == 0 && impact.otherKind == Other::body && impact.other == 1) {
                // Equal masses, C = 1: the crate stops dead and the last crate takes all its velocity.
                crateOnCrate = i + 1;
                crateAtImpact = crateBefore.x;
                CHECK(impact.normal == Vec2{-1.0, 0.0});
                const auto [crateAfter, lastAfter] = vx(4.0, crateBefore.x, 4.0, lastBefore.x, 1.0);
                CHECK(crate.x == Approx(crateAfter).margin(1e-12));
                CHECK(crate.x == Approx(0.0).margin(1e-12));
                CHECK(last.x == Approx(lastAfter).epsilon(1e-12));
                CHECK(last.x == Approx(crateBefore.x).epsilon(1e-12));
            } else if (impact.body == 1 && impact.otherKind == Other::circle && impact.other == 0 && crateOnFlag < 0) {
                // The last crate lands on the flag from above: y axis only, vx kept, vy' = -C vy with
                // C = 1 x 0.5, then gravity for the rest of the step.
                crateOnFlag = i + 1;
                flagApproach = impact.approachSpeed;
                CHECK(impact.normal == Vec2{0.0, 1.0});
                CHECK(last.x == lastBefore.x);
                CHECK(last.y ==
                      Approx(0.5 * impact.approachSpeed + g * (run.world().time() - impact.time)).epsilon(1e-12));
            }
        }
    }
    INFO("ball on crate at step " << ballOnCrate << " (" << ballAtImpact << " m/s), crate on crate at step "
                                  << crateOnCrate << " (" << crateAtImpact << " m/s), crate on flag at step "
                                  << crateOnFlag << " (" << flagApproach << " m/s)");
    CHECK(ballOnCrate == 83);
    CHECK(crateOnCrate == 99);
    CHECK(crateOnFlag == 146);
    CHECK(crateAtImpact == Approx(0.85 * ballAtImpact).epsilon(1e-12));
    REQUIRE(run.goalStep());
    CHECK(*run.goalStep() == 146);
    CHECK(run.world().stats().autoSolverSteps == 0); // nothing has friction: every step was exact
    CHECK(ballRightmost < -1.2);                     // the gate held the ball: only a crate reached the flag
    const auto played = [&](std::vector<Placement> placements) {
        REQUIRE_FALSE(checkPlacements(level, placements));
        LevelRun r(level, placements);
        for (int i = 0; i < 480; ++i) r.step();
        return r.goalStep();
    };
    CHECK(played(drop(-4.5, 5.5)));
    CHECK_FALSE(played(drop(-4.5, 4.0))); // 3.14 m/s: lands on the wall's top and skims past the flag
    CHECK_FALSE(played(drop(-4.5, 6.0))); // 3.98 m/s: flies over the flag
    CHECK_FALSE(played(drop(-3.0, 4.0))); // over the shelf: the ball lands dead and never moves
    CHECK_FALSE(played({}));
}

TEST_CASE("a domino that tips onto a target marks it hit, one that stands does not", "[level][rigid]") {
    // A 0.1 x 0.5 m domino tilted past its critical angle atan(0.1 / 0.5) = 11.3 deg falls onto the target.
    const auto level = [](double tilt) {
        return parseLevel(
            "name = \"d\"\n[world]\nmethod = \"auto\"\n[[segment]]\na = [-5, 0]\nb = [5, 0]\nfriction = 0.6\n"
            "[[box]]\nname = \"domino\"\nposition = [0, 0.25]\nsize = [0.1, 0.5]\nmass = 0.2\nfriction = 0.6\n"
            "bounciness = 0\nangle_degrees = " +
            std::to_string(tilt) +
            "\n"
            "[[item]]\nkind = \"target\"\nname = \"T\"\nposition = [0.7, 0.3]\n"
            "[goal]\ntext = \"x\"\ncondition = \"target-hit\"\ntarget = \"T\"\n");
    };
    LevelRun falls(level(-20.0), {});
    for (int i = 0; i < 180; ++i) falls.step();
    REQUIRE(falls.goalStep());
    REQUIRE(falls.events().size() >= 1);
    CHECK(falls.events().front().kind == EventKind::hit);
    CHECK(falls.events().front().item == "T");
    std::printf("domino onto a target: hit at step %lld, point [%.3f, %.3f]\n",
                static_cast<long long>(falls.events().front().step), falls.events().front().position.x,
                falls.events().front().position.y);
    CHECK(falls.events().front().by == "domino"); // the scene's [[box]], by its name
    LevelRun stands(level(-5.0), {});
    for (int i = 0; i < 180; ++i) stands.step();
    CHECK_FALSE(stands.goalStep());
    CHECK(stands.events().empty());
    // The same fall by a domino part: the hit and the goal name it, as a ball's are named, and so
    // does its trace name (LevelRun::bodyName); a [[box]] is not an item.
    for (const double tilt : {-15.0, -25.0, -35.0}) {
        INFO("tilted " << tilt << " degrees");
        LevelRun part(parseLevel("name = \"d\"\n[world]\nmethod = \"auto\"\n[[segment]]\na = [-5, 0]\nb = [5, 0]\n"
                                 "friction = 0.6\n[[item]]\nkind = \"domino\"\nname = \"tile\"\nposition = [0, 0.25]\n"
                                 "angle = " +
                                 std::to_string(tilt) +
                                 "\n[[item]]\nkind = \"target\"\nname = \"T\"\nposition = [0.55, 0.3]\n"
                                 "[goal]\ntext = \"x\"\ncondition = \"target-hit\"\ntarget = \"T\"\n"),
                      {});
        for (int i = 0; i < 180 && !part.goalStep(); ++i) part.step();
        REQUIRE(part.goalStep());
        CHECK(part.events().front().by == "tile");
        CHECK(part.events().back().by == "tile"); // the goal event
        REQUIRE(part.world().bodies().size() == 1);
        CHECK(part.itemOfBody(0) == part.find("tile"));
        CHECK(part.bodyName(0) == "tile");
    }
    CHECK(falls.itemOfBody(0) == -1);
    CHECK(falls.bodyName(0) == "domino");
}

TEST_CASE("a level's clicks name the parts a click may act on, and scripts that click others are refused", "[level]") {
    const std::string head = "name = \"t\"\n";
    const std::string items = "[[item]]\nkind = \"cannon\"\nname = \"gun\"\nposition = [0, 1]\n"
                              "[[item]]\nkind = \"target\"\nname = \"flag\"\nposition = [5, 1]\n";
    CHECK(firstError(head + "clicks = \"gun\"\n" + items) ==
          "t.toml:2:10: clicks must be an array of item names, got string");
    CHECK(firstError(head + "clicks = [\"gnu\"]\n" + items) ==
          "t.toml:2:11: unknown item 'gnu' in clicks (did you mean 'gun'?)");
    CHECK(firstError(head + "clicks = [\"flag\"]\n" + items) ==
          "t.toml:2:11: clicks names 'flag', a target, which no click acts on");
    const SceneDesc none = parseLevel(head + "clicks = []\n" + items);
    CHECK_FALSE(none.level.clickable("gun"));
    CHECK(parseLevel(head + "clicks = [\"gun\"]\n" + items).level.clickable("gun"));
    CHECK(parseLevel(head + items).level.clickable("gun")); // no clicks key: every part
    // A script's click on it is refused where it is written; an aim is editing, not a click.
    const ScriptLoad fire = parseScript("level = \"t\"\n[[action]]\nstep = 3\ndo = \"fire\"\nitem = \"gun\"\n",
                                        "s.toml", none);
    REQUIRE_FALSE(fire.errors.empty());
    CHECK(fire.errors.front().format() == "s.toml:5:8: level 't' lets no click act on 'gun' (its clicks: none)");
    CHECK(
        parseScript("level = \"t\"\n[[action]]\nstep = 0\ndo = \"aim\"\nitem = \"gun\"\nangle = 30\n", "s.toml", none)
            .script.has_value());
}
