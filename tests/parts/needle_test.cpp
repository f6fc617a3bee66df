// The needle (game/src/items/needle.cpp): a balloon rising into its point pops on the step it touches.
// Released at rest with its top d below the point, a balloon rises at g (lift 2 |g| against gravity's
// |g|), so it touches at t = sqrt(2 d / g); it must be gone after the step that holds t (within one
// step), and whole before. Other balls bounce off the point, and a balloon meeting the shaft bounces.
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

constexpr double kPoint = 0.02, kBalloon = 0.35, kDt = 0.01;

std::string needleAndBall(double angle, Vec2 tip, const std::string& ball, Vec2 at) {
    return "name = \"pop\"\n[world]\ntime_step = " + num(kDt) + "\n[[item]]\nkind = \"needle\"\nposition = [" +
           num(tip.x) + ", " + num(tip.y) + "]\nangle = " + num(angle) + "\n[[item]]\nkind = \"" + ball +
           "\"\nposition = [" + num(at.x) + ", " + num(at.y) + "]\n";
}

// Steps until the ball's circle is gone (or `limit` steps); returns the step it went, or -1.
int stepPopped(LevelRun& run, int limit) {
    for (int k = 1; k <= limit; ++k) {
        run.step();
        if (run.states()[1].circle.isNull()) return k;
    }
    return -1;
}

} // namespace

TEST_CASE("needle: a balloon rising into its point pops on the step it touches", "[parts][needle]") {
    for (const double angle : {-90.0, -60.0, -120.0}) {
        for (const double gap : {0.05, 0.3, 1.0, 2.5}) {
            CAPTURE(angle, gap);
            const Vec2 tip{0.0, 5.0};
            const SceneLoad load = parseScene(
                needleAndBall(angle, tip, "balloon", {0.0, tip.y - kPoint - kBalloon - gap}), "pop.toml");
            REQUIRE(load.ok());
            LevelRun run(*load.scene, {});
            const double g = -run.world().def().gravity.y;
            const double contact = std::sqrt(2.0 * gap / g); // s
            const int popped = stepPopped(run, 1000);
            REQUIRE(popped > 0);
            CHECK(std::abs(popped * kDt - contact) <= kDt);
            CHECK(run.world().circles().size() == 1); // only the needle's point is left
        }
    }
}

TEST_CASE("needle: other balls bounce off its point, and a balloon meeting its shaft bounces", "[parts][needle]") {
    for (const char* ball : {"tennis-ball", "bouncy", "heavy"}) {
        CAPTURE(ball);
        const SceneLoad load = parseScene(needleAndBall(90.0, {0.0, 0.0}, ball, {0.0, 1.0}), "pop.toml");
        REQUIRE(load.ok());
        LevelRun run(*load.scene, {});
        CHECK(stepPopped(run, 300) == -1);
        CHECK(run.world().circles().size() == 2);
    }
    // A needle lying flat, pointing right: a balloon rising under the middle of its shaft stays whole.
    const SceneLoad load = parseScene(needleAndBall(0.0, {0.0, 3.0}, "balloon", {-0.25, 2.0}), "pop.toml");
    REQUIRE(load.ok());
    LevelRun run(*load.scene, {});
    CHECK(stepPopped(run, 300) == -1);
}
