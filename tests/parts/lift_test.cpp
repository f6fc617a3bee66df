// The lift (game/src/items/lift.cpp): still until switched, then its platform rides its travel at
// its speed, arriving |travel| / speed after the switch (within one step) and staying; a ball
// standing on it is carried up by the travel's rise (within 2 cm once it has settled).
#include "level_run.hpp"
#include "part_text.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace rube;
using namespace rube::game;
using rube::test::num;

namespace {

constexpr double kBoard = 0.05; // the platform's half thickness, m

std::string liftLevel(double dt, double rise, double speed) {
    return "name = \"t\"\n[world]\ntime_step = " + num(dt) + "\n" +
           "[[item]]\nkind = \"lift\"\nname = \"up\"\nposition = [0, 0]\nwidth = 2\ntravel = [0, " + num(rise) +
           "]\nspeed = " + num(speed) + "\n" + "[[item]]\nkind = \"heavy\"\nposition = [0, " + num(kBoard + 0.3) +
           "]\n";
}

// The platform's height now: the World's only segment.
double platformY(const LevelRun& run) { return run.world().segments()[0].a.y; }

} // namespace

TEST_CASE("lift: rides its travel at its speed once switched, carrying the ball on it up by the rise",
          "[parts][lift]") {
    for (const double dt : {0.01, 1.0 / 60.0}) {
        for (const double rise : {1.0, 2.5}) {
            for (const double speed : {0.5, 1.0, 2.0}) {
                for (const int switchAt : {0, 37}) {
                    CAPTURE(dt, rise, speed, switchAt);
                    const SceneLoad load = parseScene(liftLevel(dt, rise, speed), "t.toml");
                    REQUIRE(load.ok());
                    LevelRun run(*load.scene, {});
                    const double ride = rise / speed;
                    std::optional<std::int64_t> arrived;
                    const auto steps = static_cast<std::int64_t>((ride + 2.5) / dt) + switchAt;
                    for (std::int64_t i = 0; i < steps; ++i) {
                        if (i == switchAt) run.toggle(0);
                        if (i < switchAt) CHECK(platformY(run) == 0.0); // still until switched
                        run.step();
                        if (!arrived && std::abs(platformY(run) - rise) < 1e-9) arrived = run.steps();
                    }
                    REQUIRE(arrived);
                    const double at = static_cast<double>(*arrived - switchAt) * dt; // seconds after the switch
                    CHECK(at >= ride - 1e-9);
                    CHECK(at < ride + dt + 1e-9);
                    CHECK(platformY(run) == Approx(rise).margin(1e-12)); // and stays
                    const Circle& ball = run.world().circles()[0];
                    CHECK(ball.position.y == Approx(rise + kBoard + 0.3).margin(0.02));
                    CHECK(std::abs(ball.position.x) < 1e-9); // straight up: not thrown aside
                }
            }
        }
    }
}
