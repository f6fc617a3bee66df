// The water wheel (issue 22): a ball falling on a paddle turns the wheel by the angular impulse of
// its push, r x J with J the ball's momentum change, r from the axle: the wheel's angular momentum
// about its axle grows by exactly what the ball's, r x m v, loses (the axle's push goes through the
// axle). Within 0.5 % (measured 0.11 % at worst, an 8 kg ball on 0.2 kg paddles: the solver's
// soft welds), over four balls (58 g to 8 kg), three drop heights (0.5 to 2 m) and either side of
// the axle; the wheel turns the way the ball pushes, clockwise when it falls right of the axle.
#include "level_run.hpp"
#include "scene_file.hpp"
#include "axle_momentum.hpp"
#include "scene_number.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>

using namespace rube;
using namespace rube::game;
using test::num;

namespace {

constexpr double kG = 9.81;

// A water wheel at the origin (disc 0.3 m, four paddles 0.5 m along the axes, so a ball at |x| >=
// 0.6 m meets the level one and no other first) and a ball above a paddle at `x`, falling at the speed a drop from
// `height` gives, sqrt(2 g h). Gravity is off so that only the impact changes the ball's angular momentum about the
// axle.
SceneDesc scene(const std::string& ball, double x, double height) {
    std::ostringstream text;
    text << "name = \"water-wheel-test\"\n[world]\ntime_step = 0.01\nmethod = \"auto\"\ngravity = [0, 0]\n"
         << "bounds = { min = [-20, -20], max = [20, 20] }\n"
         << "[[item]]\nkind = \"water-wheel\"\nname = \"wheel\"\nposition = [0, 0]\npaddles = 4\n"
         << "[[item]]\nkind = \"" << ball << "\"\nposition = [" << num(x) << ", 1.2]\nvelocity = [0, "
         << num(-std::sqrt(2.0 * kG * height)) << "]\n";
    const SceneLoad load = parseScene(text.str(), "water-wheel-test.toml");
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return *load.scene;
}

// The ball's angular momentum about the axle, r x m v, and its own spin's, I omega.
double ballMomentum(const LevelRun& run) {
    const Circle& c = run.world().circle(run.states()[1].circle);
    return c.position.cross(c.velocity) / c.inverseMass + c.angularVelocity / c.inverseInertia;
}

} // namespace

TEST_CASE("a ball on a water wheel's paddle turns it by r x its momentum change, the way it pushes",
          "[parts][water-wheel]") {
    for (const char* ball : {"tennis-ball", "bouncy", "steel", "heavy"})
        for (const double height : {0.5, 1.0, 2.0})
            for (const double x : {0.6, -0.6}) {
                INFO(ball << " from " << height << " m at x = " << x << " m");
                LevelRun run(scene(ball, x, height), {});
                const double before = ballMomentum(run);
                REQUIRE(test::angularMomentumAbout(run.world(), {}) == Approx(before).margin(1e-12));
                // Until 0.1 s after the first impact: the ball has left the paddle.
                int struck = -1;
                for (int i = 0; i < 200 && (struck < 0 || i < struck + 10); ++i) {
                    run.step();
                    if (struck < 0 && std::abs(ballMomentum(run) - before) > 1e-3 * std::abs(before)) struck = i;
                }
                REQUIRE(struck >= 0);
                // What the ball lost of r x m v, the wheel gained: its angular impulse r x J.
                const double wheel = test::angularMomentumAbout(run.world(), {}) - ballMomentum(run);
                CHECK(wheel == Approx(before - ballMomentum(run)).epsilon(0.005));
                // It turns the way the ball pushed: clockwise right of the axle, counter-clockwise left.
                const double spin = run.world().circle(run.states()[0].circle).angularVelocity;
                CHECK(spin * x < 0.0);
                CHECK(wheel * x < 0.0);
            }
}
