// The scissors (game/src/items/scissors.cpp): they cut the rope they name on the step a ball strikes
// them, or the step a switch naming them is struck. A ball dropped from d above them strikes at
// t = sqrt(2 d / g): the rope is whole after every step before that one and cut after it.
#include "level_run.hpp"
#include "scene_file.hpp"
#include "scene_number.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace rube;
using namespace rube::game;
using test::num;

namespace {

constexpr double kDt = 0.01;

// A bob hanging at rest on a rope "cord", scissors "shears" at the origin (radius 0.2) that cut it, and
// `extra` items; then a ball of `kind` (radius r) whose bottom is d above the top of `under`.
std::string scene(const std::string& extra, const std::string& kind, double r, Vec2 under, double d) {
    return "name = \"cut\"\n[world]\ntime_step = " + num(kDt) +
           "\n[[circle]]\nname = \"bob\"\nposition = [4, 3]\nradius = 0.2\n[[rope]]\nname = \"cord\"\ncircle = "
           "\"bob\"\nanchor = [4, 5]\nlength = 2\n[[item]]\nkind = \"scissors\"\nname = \"shears\"\nposition = [0, "
           "0]\ncuts = \"cord\"\n" +
           extra + "[[item]]\nkind = \"" + kind + "\"\nposition = [" + num(under.x) + ", " +
           num(under.y + 0.2 + r + d) + "]\n";
}

// Steps until the rope is cut; returns that step, or -1 when it is not cut within `limit` steps.
int stepCut(LevelRun& run, int limit) {
    for (int k = 1; k <= limit; ++k) {
        run.step();
        if (run.world().ropes()[0].cut) return k;
    }
    return -1;
}

} // namespace

TEST_CASE("scissors: the rope is cut on the step a ball strikes them", "[parts][scissors]") {
    for (const char* kind : {"heavy", "tennis-ball", "steel"}) {
        const double r = std::string(kind) == "heavy" ? 0.3 : std::string(kind) == "steel" ? 0.2 : 0.0335;
        for (const double d : {0.1, 0.7, 2.0}) {
            CAPTURE(kind, d);
            const SceneLoad load = parseScene(scene("", kind, r, {0.0, 0.0}, d), "cut.toml");
            REQUIRE(load.ok());
            LevelRun run(*load.scene, {});
            const double g = -run.world().def().gravity.y;
            const int cut = stepCut(run, 1000);
            REQUIRE(cut > 0);
            // The step of the cut is the step of the strike: it holds the ball's first impact.
            CHECK(run.world().lastImpacts().size() >= 1);
            CHECK(std::abs(cut * kDt - std::sqrt(2.0 * d / g)) <= kDt);
            CHECK(run.events().front().item == "shears");
            CHECK(run.events().front().step == cut);
        }
    }
}

TEST_CASE("scissors: a switch that names them cuts the rope on the step it is struck", "[parts][scissors]") {
    const std::string button = "[[item]]\nkind = \"switch\"\nname = \"button\"\nposition = [-3, 0]\ntriggers = "
                               "\"shears\"\n";
    for (const double d : {0.2, 1.5}) {
        CAPTURE(d);
        const SceneLoad load = parseScene(scene(button, "heavy", 0.3, {-3.0, 0.0}, d), "cut.toml");
        REQUIRE(load.ok());
        LevelRun run(*load.scene, {});
        const double g = -run.world().def().gravity.y;
        const int cut = stepCut(run, 1000);
        REQUIRE(cut > 0);
        CHECK(std::abs(cut * kDt - std::sqrt(2.0 * d / g)) <= kDt);
        REQUIRE(!run.events().empty());
        CHECK(run.events().front().item == "button");
        CHECK(run.events().front().step == cut);
    }
}

TEST_CASE("scissors: they name a rope the level has", "[parts][scissors]") {
    const SceneLoad load = parseScene(
        "name = \"t\"\n[[item]]\nkind = \"scissors\"\nposition = [0, 0]\ncuts = \"crod\"\n", "t.toml");
    REQUIRE(!load.ok());
    CHECK(load.errors.front().format() == "t.toml:5:8: unknown rope 'crod' (the level has no named rope)");
}
