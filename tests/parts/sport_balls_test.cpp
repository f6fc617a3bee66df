// The sport balls (game/src/items/bowling_ball.cpp, tennis_ball.cpp, basketball.cpp): their radii and
// masses lie inside the rules' ranges, and dropped on a floor of bounciness 1 each climbs back to
// h1 = C^2 h0 (a drop of h0 lands at sqrt(2 g h0) and leaves at C times it, lecture 3), where C
// passes the rules' own drop test: the ITF's 254 cm to 135-147 cm for the tennis ball, FIBA's
// 1800 mm (to the ball's bottom) to 1200-1400 mm (to its top) for the basketball.
#include "level_run.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

using namespace rube;
using namespace rube::game;

namespace {

struct Ball {
    const char* kind;
    double radius, mass, bounciness; // what the descriptor says
    double minRadius, maxRadius;     // the rules' range, m
    double minMass, maxMass;         // kg
};

// USBC: at most 16 lb, 8.500-8.595 in across; ITF: 56.0-59.4 g, 6.541-6.858 cm; FIBA size 7: 567-650 g,
// 749-780 mm round.
constexpr double kInch = 0.0254, kPi = 3.14159265358979323846;
const Ball kBowling{"bowling-ball", 0.1086, 7.257, 0.2, 4.25 * kInch, 4.2975 * kInch, 0.0, 16 * 0.45359237};
const Ball kTennis{"tennis-ball", 0.0335, 0.0577, 0.745, 0.06541 / 2, 0.06858 / 2, 0.0560, 0.0594};
const Ball kBasketball{"basketball", 0.1218, 0.609, 0.766, 0.749 / (2 * kPi), 0.780 / (2 * kPi), 0.567, 0.650};

// A ball of `kind` whose bottom is `drop` m above a floor at y = 0 (bounciness 1, the default).
std::string dropOnFloor(const Ball& ball, double drop) {
    return "name = \"drop\"\n[world]\ntime_step = 0.01\n[[segment]]\na = [-5, 0]\nb = [5, 0]\n[[item]]\nkind = \"" +
           std::string(ball.kind) + "\"\nposition = [0, " + std::to_string(ball.radius + drop) + "]\n";
}

} // namespace

TEST_CASE("sport balls: radius and mass as the descriptor says, inside the rules' ranges", "[parts][balls]") {
    for (const Ball& ball : {kBowling, kTennis, kBasketball}) {
        CAPTURE(ball.kind);
        const SceneLoad load = parseScene(dropOnFloor(ball, 1.0), "balls.toml");
        REQUIRE(load.ok());
        LevelRun run(*load.scene, {});
        const Circle& c = run.world().circle(run.states()[0].circle);
        CHECK(c.radius == ball.radius);
        CHECK(1.0 / c.inverseMass == Approx(ball.mass).epsilon(1e-12));
        CHECK(c.material.bounciness == ball.bounciness);
        CHECK(c.motion == Motion::dynamic);
        CHECK(ball.radius >= ball.minRadius);
        CHECK(ball.radius <= ball.maxRadius);
        CHECK(ball.mass >= ball.minMass);
        CHECK(ball.mass <= ball.maxMass);
    }
}

TEST_CASE("sport balls: C passes the rules' drop tests", "[parts][balls]") {
    // ITF: from 254 cm, back to 135-147 cm: C^2 = h1 / h0.
    CHECK(kTennis.bounciness * kTennis.bounciness >= 1.35 / 2.54);
    CHECK(kTennis.bounciness * kTennis.bounciness <= 1.47 / 2.54);
    // FIBA: its bottom from 1.8 m; its top back to 1.2-1.4 m, so its bottom to that less its diameter.
    const double d = 2.0 * kBasketball.radius;
    CHECK(kBasketball.bounciness * kBasketball.bounciness >= (1.2 - d) / 1.8);
    CHECK(kBasketball.bounciness * kBasketball.bounciness <= (1.4 - d) / 1.8);
}

TEST_CASE("sport balls: dropped on a floor each climbs back to C^2 of the drop, over heights", "[parts][balls]") {
    for (const Ball& ball : {kBowling, kTennis, kBasketball}) {
        for (const double drop : {0.3, 0.8, 1.8, 2.54, 5.0}) {
            CAPTURE(ball.kind, drop);
            const SceneLoad load = parseScene(dropOnFloor(ball, drop), "balls.toml");
            REQUIRE(load.ok());
            LevelRun run(*load.scene, {});
            const CircleId id = run.states()[0].circle;
            const double g = -run.world().def().gravity.y, dt = run.world().def().timeStep;
            const double expected = ball.bounciness * ball.bounciness * drop; // h1 = C^2 h0
            // In free flight after the bounce, the height the bottom climbs to is
            // y_bottom + v^2 / (2 g) whenever it is measured: exact, not sampled at an apex.
            bool bounced = false;
            double highest = 0.0; // the bottom's highest point at a step's end, after the bounce
            for (int i = 0; i < 2000; ++i) {
                run.step();
                const Circle& c = run.world().circle(id);
                const double bottom = c.position.y - c.radius;
                if (!bounced && c.velocity.y > 0.0) {
                    bounced = true;
                    CHECK(bottom + c.velocity.y * c.velocity.y / (2.0 * g) == Approx(expected).epsilon(1e-9));
                }
                if (bounced) {
                    highest = std::max(highest, bottom);
                    if (c.velocity.y < 0.0) break; // past its apex
                }
            }
            REQUIRE(bounced);
            // Sampled at the ends of steps, the apex is seen at most g dt^2 / 2 below the true one.
            CHECK(highest <= expected + 1e-12);
            CHECK(highest >= expected - 0.5 * g * dt * dt);
        }
    }
}
