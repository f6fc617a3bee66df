// `rube solve`: the search space, the search and its report. The drop level's solution set is
// known in closed form (a ball falling straight touches the target when |x - x_t| < R + r), so the
// exhaustive search is checked against that law over several targets; the rest check that the
// result does not depend on threads, slices, or stopping runs early, and that a seed fixes it.
#include "json_reader.hpp"
#include "solve_report.hpp"

#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

using namespace rube;
using namespace rube::game;

namespace {

std::string readFile(const std::string& path) {
    SceneError error;
    const std::optional<std::string> text = readTextFile(path, error);
    REQUIRE(text);
    return *text;
}

SceneDesc loadLevel(const std::string& path) {
    const SceneLoad load = loadSceneFile(path);
    REQUIRE(load.ok());
    return *load.scene;
}

// The drop level with its target moved to x_t and given radius R.
SceneDesc dropLevel(double targetX, double targetRadius) {
    std::string text = readFile(RUBE_SOLVE_TESTS_DIR "/drop.toml");
    const auto replace = [&](const std::string& from, const std::string& to) {
        const auto at = text.find(from);
        REQUIRE(at != std::string::npos);
        text.replace(at, from.size(), to);
    };
    replace("position = [0.5, 0.4]", "position = [" + scriptNumber(targetX) + ", " + scriptNumber(targetRadius) + "]");
    replace("radius = 0.4", "radius = " + scriptNumber(targetRadius));
    const SceneLoad load = parseScene(text, "drop.toml");
    REQUIRE(load.ok());
    return *load.scene;
}

std::string searchJson(const SceneDesc& level, const SolveOptions& options) {
    const SearchSpace space(level, options.space);
    return reportJson(makeReport(searchLevel(level, space, options), space, std::nullopt), space);
}

} // namespace

TEST_CASE("the drop level's solutions are exactly the grid points within R + r of the target") {
    constexpr double kBallRadius = 0.3; // the heavy ball's
    for (const double targetX : {0.52, -1.13, 2.21})
        for (const double targetRadius : {0.25, 0.4, 0.7}) {
            CAPTURE(targetX, targetRadius);
            const SceneDesc level = dropLevel(targetX, targetRadius);
            const SearchSpace space(level, {});
            SolveOptions options;
            options.budget = 100000;
            const SearchResult result = searchLevel(level, space, options);
            REQUIRE(planSearch(space, options.budget).exhaustive());
            REQUIRE(space.kinds().size() == 1);
            std::set<std::pair<double, double>> expected, found;
            for (const Vec2 p : space.kinds()[0].positions) {
                const double gap = std::abs(p.x - targetX) - (targetRadius + kBallRadius);
                REQUIRE(std::abs(gap) > 1e-3); // no grid point grazes the target: the law decides every one
                if (gap < 0) expected.emplace(p.x, p.y);
            }
            for (const FoundSolution& s : result.solutions) {
                const ScriptDesc script = space.script(candidateOf(space, result, s.number));
                REQUIRE(script.placements.size() == 1); // nothing placed never solves
                found.emplace(script.placements[0].position.x, script.placements[0].position.y);
            }
            CHECK(found == expected);
            CHECK_FALSE(expected.empty());
            // Every point of the empty zone is allowed, and so is placing nothing.
            CHECK(result.valid() == space.kinds()[0].positions.size() + 1);
            CHECK(result.solveFraction(space) ==
                  Approx(static_cast<double>(expected.size()) / static_cast<double>(result.valid())));
        }
}

TEST_CASE("the fan-aim level's solutions are exactly the angles whose ray from the ball meets the target") {
    constexpr double kBallRadius = 0.25; // the bouncy ball's
    constexpr double kPi = 3.14159265358979323846;
    const std::string original = readFile(RUBE_SOLVE_TESTS_DIR "/fan-aim.toml");
    int solvedLevels = 0;
    for (const Vec2 target : {Vec2{5, 1.5}, Vec2{4.3, -1.3}, Vec2{6, 0.3}}) {
        CAPTURE(target.x, target.y);
        std::string text = original;
        const std::string from = "position = [5, 1.5]";
        text.replace(text.find(from), from.size(),
                     "position = [" + scriptNumber(target.x) + ", " + scriptNumber(target.y) + "]");
        const SceneLoad load = parseScene(text, "fan-aim.toml");
        REQUIRE(load.ok());
        SpaceOptions cut;
        cut.step = 100.0; // one point: the zone's centre
        cut.angleStep = 5.0;
        const SearchSpace space(*load.scene, cut);
        REQUIRE(space.kinds()[0].positions.size() == 1);
        SolveOptions options;
        options.space = cut;
        options.budget = 1000;
        const SearchResult result = searchLevel(*load.scene, space, options);
        REQUIRE(planSearch(space, options.budget).exhaustive());
        const Vec2 ball{1, 0};
        std::set<double> expected, found;
        for (const double degrees : space.kinds()[0].angles) {
            const Vec2 d = Vec2::fromAngle(degrees * kPi / 180.0);
            const Vec2 fromFan = ball - space.kinds()[0].positions[0];
            const double across = std::abs(d.cross(fromFan)), along = d.dot(fromFan);
            REQUIRE(std::abs(across - 0.6) > 1e-3); // the ball is clearly in or out of the column
            const Vec2 w = target - ball;
            const double miss = std::abs(d.cross(w)) - (0.4 + kBallRadius);
            REQUIRE(std::abs(miss) > 1e-2); // the ray clearly meets or misses the target
            if (along > 0 && across <= 0.6 && d.dot(w) > 0 && miss < 0) expected.insert(degrees);
        }
        for (const FoundSolution& s : result.solutions) {
            const ScriptDesc script = space.script(candidateOf(space, result, s.number));
            REQUIRE(script.placements.size() == 1);
            found.insert(script.placements[0].angleDegrees);
        }
        CHECK(found == expected);
        if (!expected.empty()) ++solvedLevels;
    }
    CHECK(solvedLevels >= 2);
}

TEST_CASE("the grid steps by a quarter of the part and keeps the part inside the zone") {
    const SceneDesc level = dropLevel(0.5, 0.4);
    const SearchSpace space(level, {});
    const KindAxis& heavy = space.kinds()[0];
    CHECK(heavy.step == Approx(0.15)); // a quarter of the 0.6 m ball
    for (const Vec2 p : heavy.positions) {
        CHECK(p.x - 0.3 >= -3 - 1e-9);
        CHECK(p.x + 0.3 <= 3 + 1e-9);
        CHECK(p.y - 0.3 >= 4 - 1e-9);
        CHECK(p.y + 0.3 <= 5 + 1e-9);
    }
    // Columns are a step apart and centred in the zone.
    CHECK(heavy.positions[1].x - heavy.positions[0].x == Approx(0.15));
    CHECK(heavy.positions.front().x + heavy.positions[static_cast<std::size_t>(heavy.columns[0] - 1)].x ==
          Approx(0.0).margin(1e-9));
}

TEST_CASE("a turning part is tried every 15 degrees over its period") {
    const SceneDesc level = loadLevel(RUBE_GAME_LEVELS_DIR "/ramp.toml");
    const SearchSpace space(level, {});
    REQUIRE(space.kinds().size() == 1);
    const KindAxis& ramp = space.kinds()[0];
    REQUIRE(ramp.angles.size() == 12); // a board is the same after half a turn: 180 / 15
    for (std::size_t k = 0; k < ramp.angles.size(); ++k) CHECK(ramp.angles[k] == Approx(-90.0 + 15.0 * k));
    const SceneDesc fan = loadLevel(RUBE_GAME_LEVELS_DIR "/fan.toml");
    CHECK(SearchSpace(fan, {}).kinds()[0].angles.size() == 24); // a fan pushes one way: a whole turn
}

TEST_CASE("stopping a run when nothing moves never changes its outcome") {
    int stoppedEarly = 0;
    for (const char* name : {"ramp", "bucket", "chain-reaction", "seesaw", "rope", "cannon-arc", "crates"}) {
        CAPTURE(name);
        const SceneDesc level = loadLevel(std::string(RUBE_GAME_LEVELS_DIR "/") + name + ".toml");
        const SearchSpace space(level, {});
        for (std::uint64_t n = 0; n < 6; ++n) {
            const ScriptDesc script = space.script(
                space.sample(static_cast<int>(n % static_cast<std::uint64_t>(space.subsetCount())), 7, n));
            const RunOutcome quick = runCandidate(level, script, space.steps(), true);
            const RunOutcome full = runCandidate(level, script, space.steps(), false);
            CHECK(quick.valid == full.valid);
            CHECK(quick.goal == full.goal);
            if (quick.steps < full.steps) ++stoppedEarly;
        }
        // The intended solution too: stopping must not cut a solving run short.
        const ScriptLoad intended = loadScriptFile(std::string(RUBE_GAME_LEVELS_DIR "/") + name + ".solution.toml",
                                                   level);
        REQUIRE(intended.script);
        CHECK(runCandidate(level, *intended.script, space.steps(), true).goal ==
              runCandidate(level, *intended.script, space.steps(), false).goal);
        CHECK(runCandidate(level, *intended.script, space.steps(), true).goal.has_value());
    }
    CHECK(stoppedEarly > 10); // and it does stop early: the comparison is not empty
}

TEST_CASE("two or three threads give the byte-identical result of one") {
    const SceneDesc level = loadLevel(RUBE_GAME_LEVELS_DIR "/ramp.toml");
    SolveOptions options;
    options.budget = 48;
    options.seed = 3;
    const std::string one = searchJson(level, options);
    options.jobs = 2;
    CHECK(searchJson(level, options) == one);
    options.jobs = 3;
    CHECK(searchJson(level, options) == one);
}

TEST_CASE("slices merged give the result of one run") {
    const auto check = [](const SceneDesc& level, SolveOptions options) {
        const SearchSpace space(level, options.space);
        const std::string whole = searchJson(level, options);
        for (const int count : {2, 3, 5}) {
            CAPTURE(count);
            std::vector<SearchResult> slices;
            for (int i = 0; i < count; ++i) {
                options.shardIndex = i;
                options.shardCount = count;
                std::string error;
                const SearchResult slice = searchLevel(level, space, options);
                std::optional<SearchResult> read = readResultJson(
                    reportJson(makeReport(slice, space, std::nullopt), space), error); // through the file format
                REQUIRE(read);
                slices.push_back(*read);
            }
            std::string error;
            std::reverse(slices.begin(), slices.end()); // the order they are given in does not matter
            const std::optional<SearchResult> merged = mergeResults(slices, error);
            REQUIRE(merged);
            CHECK(reportJson(makeReport(*merged, space, std::nullopt), space) == whole);
            slices.pop_back();
            CHECK_FALSE(mergeResults(slices, error));
            CHECK(error.find("missing") != std::string::npos);
        }
    };
    SolveOptions exhaustive;
    exhaustive.budget = 100000;
    check(dropLevel(0.5, 0.4), exhaustive);
    SolveOptions random;
    random.budget = 30;
    random.seed = 11;
    check(loadLevel(RUBE_GAME_LEVELS_DIR "/ramp.toml"), random);
}

TEST_CASE("the same level, budget and seed give byte-identical JSON, and another seed draws other candidates") {
    const SceneDesc level = loadLevel(RUBE_GAME_LEVELS_DIR "/ramp.toml");
    SolveOptions options;
    options.budget = 30;
    options.seed = 5;
    const std::string first = searchJson(level, options);
    CHECK(searchJson(level, options) == first);
    const SearchSpace space(level, {});
    int same = 0;
    for (std::uint64_t n = 0; n < 30; ++n)
        if (space.sample(1, 5, n) == space.sample(1, 6, n)) ++same;
    CHECK(same < 3);
    options.seed = 6;
    CHECK(searchJson(level, options) != first);
}

TEST_CASE("the budget is shared equally among the subsets, a small subset searched whole") {
    const SceneDesc level = loadLevel(RUBE_GAME_LEVELS_DIR "/trampoline.toml"); // none, bouncy, heavy, both
    const SearchSpace space(level, {});
    REQUIRE(space.subsetCount() == 4);
    for (const std::uint64_t budget : {3ull, 10ull, 400ull, 1000ull, 5000ull}) {
        CAPTURE(budget);
        const SearchPlan plan = planSearch(space, budget);
        CHECK(plan.total == std::min<std::uint64_t>(budget, space.size()));
        CHECK(plan.whole[0]); // placing nothing is one candidate, within any share
        std::uint64_t largestDrawn = 0, smallestDrawn = budget;
        for (int s = 0; s < 4; ++s) {
            if (plan.whole[static_cast<std::size_t>(s)])
                CHECK(plan.tries[static_cast<std::size_t>(s)] == space.subsetSize(s));
            else {
                largestDrawn = std::max(largestDrawn, plan.tries[static_cast<std::size_t>(s)]);
                smallestDrawn = std::min(smallestDrawn, plan.tries[static_cast<std::size_t>(s)]);
                // Drawn from only when larger than what it would get: a whole subset is never cut short.
                CHECK(space.subsetSize(s) > plan.tries[static_cast<std::size_t>(s)]);
            }
        }
        if (largestDrawn > 0) CHECK(largestDrawn - smallestDrawn <= 1);
    }
    CHECK(planSearch(space, space.size()).exhaustive());
    CHECK_FALSE(planSearch(space, space.size() - 1).exhaustive());
}

TEST_CASE("an index in the space and its candidate are one to one") {
    const SceneDesc level = loadLevel(RUBE_GAME_LEVELS_DIR "/trampoline.toml"); // two kinds: four subsets
    const SearchSpace space(level, {});
    std::set<Candidate> seen;
    const std::uint64_t step = std::max<std::uint64_t>(1, space.size() / 5000);
    for (std::uint64_t i = 0; i < space.size(); i += step) CHECK(seen.insert(space.at(i)).second);
    CHECK(space.at(0).digits.empty()); // the empty subset comes first
    CHECK(space.at(space.size() - 1).subset == 3);
}

TEST_CASE("a shortcut uses fewer parts than the intended solution, or parts or clicks it does not do") {
    PartsUsed intended;
    intended.parts = {{"bouncy", 1}, {"ramp", 1}};
    intended.acts = {"fire gun"};
    PartsUsed same = intended;
    CHECK(shortcutReason(same, intended).empty());
    PartsUsed fewer;
    fewer.parts = {{"ramp", 1}};
    CHECK(shortcutReason(fewer, intended).find("fewer parts") != std::string::npos);
    PartsUsed other;
    other.parts = {{"heavy", 1}, {"ramp", 1}};
    CHECK(shortcutReason(other, intended).find("heavy") != std::string::npos);
    PartsUsed click = intended;
    click.acts.insert("detonate tnt");
    CHECK(shortcutReason(click, intended).find("detonate tnt") != std::string::npos);
    CHECK(PartsUsed{}.label() == "nothing");
    CHECK(click.label() == "bouncy + ramp; detonate tnt, fire gun");
}

TEST_CASE("the JSON reader refuses what it cannot read, with a place") {
    std::string error;
    CHECK_FALSE(parseJson("{\"a\": [1, 2", error));
    CHECK(error.starts_with("1:"));
    CHECK_FALSE(parseJson("{\"a\": 1} x", error));
    const std::optional<JsonValue> value = parseJson(
        "{\"a\": [1, \"b\\\"c\", true, null], \"n\": 18446744073709551615}", error);
    REQUIRE(value);
    CHECK(value->find("a")->array[1].text == "b\"c");
    CHECK(value->find("n")->text == "18446744073709551615");
    CHECK_FALSE(readResultJson("{\"level\": \"x\"}", error));
}
