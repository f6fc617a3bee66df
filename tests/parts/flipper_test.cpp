// The flipper: a ball resting on the bat r from the hinge is carried up as the motor swings the bat
// and, when the bat stops at its upper limit, leaves along the bat's normal at the point's speed
// there, v_n = omega s (omega the bat's turn rate, s the ball's centre along the bat at the stop:
// the ball slides out while carried), within 20 % (a heavy ball 13 % short the worst measured) over three balls, three
// distances and three motor speeds; the bat stops at its upper limit (0.01 rad) over up, down and up
// again for both sides; untriggered, it stays at rest under a ball's blow; and its messages.
#include "level_run.hpp"
#include "part_text.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

using namespace rube;
using namespace rube::game;
using rube::test::firstError;
using rube::test::num;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kBatRadius = 0.1; // flipper.cpp

double radians(double degrees) { return degrees * kPi / 180.0; }

// A flipper named "bat" with hinge at the origin and `keys`, then `more` (balls, segments).
LevelRun flipperScene(const std::string& keys, const std::string& more = "") {
    const std::string text = "name = \"flipper-test\"\n[world]\ntime_step = 0.01\nbounds = { min = [-30, -30], max = "
                             "[30, 30] }\n[[item]]\nkind = \"flipper\"\nname = \"bat\"\nposition = [0, 0]\n" +
                             keys + more;
    const SceneLoad load = parseScene(text, "flipper-test.toml");
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return LevelRun(*load.scene, {});
}

// The bat's turn from its rest angle now, rad.
double turned(const LevelRun& run, double restDegrees) {
    return run.world().body(run.states()[0].body).angle - radians(restDegrees);
}

} // namespace

TEST_CASE("a ball carried up on a flipper leaves at the bat's speed where it lies, v_n = omega s", "[parts][flipper]") {
    struct Ball {
        const char* kind;
        double radius;
    };
    constexpr double kSwing = 45.0;
    for (const Ball ball : {Ball{"bouncy", 0.25}, Ball{"steel", 0.2}, Ball{"heavy", 0.3}}) {
        for (const double omega : {6.0, 10.0, 15.0}) {
            for (const double r : {0.3, 0.5, 0.7}) {
                INFO(ball.kind << " ball " << r << " m from the hinge, motor at " << omega << " rad/s");
                LevelRun run = flipperScene("angle = 0\nswing = " + num(kSwing) +
                                                "\nlength = 1.2\nspeed = " + num(omega) + "\ntrigger = \"switch\"\n",
                                            "[[item]]\nkind = \"" + std::string(ball.kind) + "\"\nposition = [" +
                                                num(r) + ", " + num(kBatRadius + ball.radius) + "]\n");
                for (int i = 0; i < 30; ++i) run.step(); // the ball settles on the bat
                const double rest = turned(run, 0.0);
                CHECK(std::abs(rest) < 0.01); // held on its rest by the motor, under the ball's weight
                run.toggle(0);
                // The step in which the bat reaches its upper limit: its turn rate, the ball's place
                // along it and the bat's normal as the step began.
                double omegaAtStop = 0.0, s = 0.0;
                Vec2 normal;
                int stop = -1;
                for (int i = 0; i < 100 && stop < 0; ++i) {
                    const RigidBody& bat = run.world().body(run.states()[0].body);
                    const double w = std::max(omegaAtStop, bat.angularVelocity), angle = bat.angle;
                    omegaAtStop = w;
                    const Vec2 at = run.world().circle(run.states()[1].circle).position;
                    run.step();
                    if (turned(run, 0.0) < radians(kSwing) - 0.01) continue;
                    stop = i;
                    s = at.dot(Vec2::fromAngle(angle));
                    normal = Vec2::fromAngle(angle + 0.5 * kPi);
                }
                REQUIRE(stop >= 0);
                CHECK(s < 1.2); // still on the bat when it stopped
                // Two steps on, in free flight: gravity's 2 dt taken back off its velocity.
                run.step();
                run.step();
                const Vec2 v = run.world().circle(run.states()[1].circle).velocity - run.world().def().gravity * 0.02;
                CHECK(v.dot(normal) == Approx(omegaAtStop * s).epsilon(0.2));
                CHECK(omegaAtStop <= 1.03 * omega); // never past its speed (2.1 % over, measured); a heavy ball slows
                                                    // it (to 0.54 omega at worst)
                CHECK(omegaAtStop > 0.5 * omega);
            }
        }
    }
}

TEST_CASE("a switched flipper swings to its upper limit and stays, and back down when switched again",
          "[parts][flipper]") {
    struct Case {
        const char* side;
        double rest, swing, speed;
    };
    for (const Case c :
         {Case{"left", -30.0, 60.0, 12.0}, Case{"right", 210.0, 60.0, 12.0}, Case{"left", 0.0, 30.0, 5.0},
          Case{"right", 180.0, 90.0, 25.0}, Case{"left", 150.0, 45.0, 8.0}}) {
        INFO(c.side << " flipper resting at " << c.rest << " degrees, swing " << c.swing << ", speed " << c.speed);
        LevelRun run = flipperScene("angle = " + num(c.rest) + "\nside = \"" + c.side + "\"\nswing = " + num(c.swing) +
                                    "\nspeed = " + num(c.speed) + "\ntrigger = \"switch\"\n");
        const double up = std::string(c.side) == "left" ? 1.0 : -1.0;
        for (int i = 0; i < 100; ++i) run.step();
        CHECK(std::abs(turned(run, c.rest)) < 0.01); // untriggered it stays down, whichever way gravity pulls
        for (int swing = 0; swing < 3; ++swing) {
            run.toggle(0);
            double furthest = 0.0;
            int steps = 0;
            for (; steps < 300 && up * turned(run, c.rest) < radians(c.swing) - 0.01; ++steps) run.step();
            // Up at the motor's speed: swing / speed, give or take the start and a step or two.
            CHECK(steps * 0.01 == Approx(radians(c.swing) / c.speed).margin(0.03));
            for (int i = 0; i < 100; ++i) {
                run.step();
                furthest = std::max(furthest, up * turned(run, c.rest));
            }
            CHECK(up * turned(run, c.rest) == Approx(radians(c.swing)).margin(0.01));
            CHECK(furthest < radians(c.swing) + 0.01);
            run.toggle(0);
            for (int i = 0; i < 100; ++i) run.step();
            CHECK(std::abs(turned(run, c.rest)) < 0.01);
        }
    }
}

TEST_CASE("a flipper swings up when a ball strikes it with trigger impact, and only then", "[parts][flipper]") {
    for (const char* trigger : {"impact", "switch"}) {
        INFO("trigger " << trigger);
        // A steel ball dropped 1 m onto the bat 0.6 m from the hinge.
        LevelRun run = flipperScene("angle = 0\ntrigger = \"" + std::string(trigger) + "\"\n",
                                    "[[item]]\nkind = \"steel\"\nposition = [0.6, 1.3]\n");
        double highest = 0.0;
        for (int i = 0; i < 200; ++i) {
            run.step();
            highest = std::max(highest, turned(run, 0.0));
        }
        if (std::string(trigger) == "impact") CHECK(turned(run, 0.0) == Approx(radians(60.0)).margin(0.01));
        else CHECK(highest < 0.01); // struck but not switched: it does not move
    }
    // Nothing touches it: it stays down.
    LevelRun alone = flipperScene("angle = -30\n");
    for (int i = 0; i < 300; ++i) alone.step();
    CHECK(std::abs(turned(alone, -30.0)) < 0.01);
}

TEST_CASE("flipper: read like every [[item]], with its own keys only", "[parts][flipper]") {
    const std::string head = "name = \"t\"\n[[item]]\nkind = \"flipper\"\nposition = [0, 1]\n";
    CHECK(firstError(head + "angle = 15\nside = \"right\"\nswing = 45\nspeed = 10\ntrigger = \"switch\"\n") ==
          "no error");
    CHECK(firstError(head + "swnig = 45\n") ==
          "t.toml:5:1: unknown key 'swnig' in [[item]] of kind 'flipper' (did you mean 'swing'?)");
    CHECK(firstError(head + "side = \"up\"\n").starts_with("t.toml:5:8: side must be one of"));
    CHECK(firstError(head + "trigger = \"touch\"\n").starts_with("t.toml:5:11: trigger must be one of"));
    CHECK(firstError(head + "swing = 0\n").starts_with("t.toml:5:9: swing must be"));
    CHECK(firstError(head + "speed = -3\n").starts_with("t.toml:5:9: speed must be"));
    CHECK(firstError(head + "length = 0\n").starts_with("t.toml:5:10: length must be"));
}
