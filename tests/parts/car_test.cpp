// The car (game/src/items/car.cpp): a wind-up toy car whose spring drives both wheels at omega = v / r.
// Its laws, over speeds, masses, tyres and slopes: rolling without slipping it holds the rim speed
// v = omega r; it speeds up at a = min(2 tau / (r (M + m_w)), mu g) (two driven discs of I = 1/2 m_w r^2,
// M the whole car; friction can push at most mu M g) and never faster than mu g; on a slope of angle
// theta it climbs while mu cos(theta) > sin(theta) and else slides back at g (sin(theta) - mu cos(theta));
// run down, it coasts to rest; waiting for a trigger, it stays put.
#include "level_run.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

using namespace rube;
using namespace rube::game;

namespace {

constexpr double kG = 9.81;
constexpr double kWheelRadius = 0.15; // the car's wheels, m
constexpr double kWheelMass = 0.25;   // each, kg

// A floor (friction 1, so a pair's mu is the tyres') tilted by `slope` degrees through the origin,
// and a car standing on it at `along` m from the origin with the car's own keys `keys`.
std::string carScene(double slope, double along, const std::string& keys) {
    const double a = slope * std::numbers::pi / 180.0;
    const Vec2 dir{std::cos(a), std::sin(a)}, up{-std::sin(a), std::cos(a)};
    const Vec2 from = dir * -10.0, to = dir * 40.0, at = dir * along + up * 0.24;
    std::ostringstream s;
    s.precision(17);
    s << "name = \"car\"\n[world]\ntime_step = 0.01\n[[segment]]\na = [" << from.x << ", " << from.y << "]\nb = ["
      << to.x << ", " << to.y << "]\nfriction = 1\n[[item]]\nkind = \"car\"\nname = \"car\"\nposition = [" << at.x
      << ", " << at.y << "]\nangle = " << slope << "\n"
      << keys;
    return s.str();
}

std::string firstError(const std::string& text) {
    const SceneLoad load = parseScene(text, "t.toml");
    return load.errors.empty() ? std::string("no error") : load.errors.front().format();
}

// The car's body and its first wheel.
const RigidBody& bodyOf(const LevelRun& run) { return run.world().body(run.states()[0].body); }
const Circle& wheelOf(const LevelRun& run) { return run.world().circle(run.states()[0].circle); }

} // namespace

TEST_CASE("car: on a level floor it reaches the rim speed v = omega r at no more than mu g, and holds it",
          "[parts][car]") {
    for (const double speed : {0.5, 1.5, 3.0}) {
        for (const double mass : {0.5, 1.0, 4.0}) {
            for (const double mu : {0.2, 0.5, 1.0}) {
                CAPTURE(speed, mass, mu);
                const std::string keys = "speed = " + std::to_string(speed) + "\nmass = " + std::to_string(mass) +
                                         "\nfriction = " + std::to_string(mu) + "\nrun = \"forever\"\n";
                const SceneLoad load = parseScene(carScene(0.0, 0.0, keys), "car.toml");
                REQUIRE(load.ok());
                LevelRun run(*load.scene, {});
                const double dt = 0.01, total = mass + 2.0 * kWheelMass;
                // The model: the spring's 0.5 N m on each wheel, unless friction allows less.
                const double aTorque = 2.0 * 0.5 / (kWheelRadius * (total + kWheelMass));
                const double aModel = std::min(aTorque, mu * kG);
                double previous = 0.0, fastest = 0.0, reached = -1.0;
                for (int i = 1; i <= 500; ++i) {
                    run.step();
                    const double v = bodyOf(run).velocity.x;
                    fastest = std::max(fastest, (v - previous) / dt);
                    if (reached < 0.0 && v >= 0.95 * speed) reached = i * dt;
                    previous = v;
                }
                // Friction limits the drive: the floor pushes at most mu M g (5 % for the solver's soft contacts).
                CHECK(fastest <= 1.05 * mu * kG);
                // It gets to 95 % of v about when the model says: 0.95 v / a, give or take 25 % and two steps.
                REQUIRE(reached > 0.0);
                CHECK(std::abs(reached - 0.95 * speed / aModel) <= 0.25 * (0.95 * speed / aModel) + 2.0 * dt);
                // Rolling without slipping at the rim speed: v = omega r, both to 2 % (a 4 kg car at 0.5 m/s creeps 1.7
                // % slow).
                CHECK(bodyOf(run).velocity.x == Approx(speed).epsilon(0.02));
                CHECK(-wheelOf(run).angularVelocity * kWheelRadius == Approx(speed).epsilon(0.02));
                CHECK(std::abs(bodyOf(run).angle) < 0.01); // level: it neither tips nor pops a wheelie
            }
        }
    }
}

TEST_CASE("car: on a slope it climbs while mu cos(theta) > sin(theta), else slides back at g (sin - mu cos)",
          "[parts][car]") {
    for (const double slope : {10.0, 20.0, 30.0}) {
        for (const double mu : {0.1, 0.3, 0.5, 0.8}) {
            const double theta = slope * std::numbers::pi / 180.0;
            const double margin = mu * std::cos(theta) - std::sin(theta);
            if (std::abs(margin) < 0.05) continue; // too near the boundary to call
            CAPTURE(slope, mu, margin);
            // A strong spring (5 N m a wheel) so that friction, not torque, is what limits it.
            const std::string keys = "friction = " + std::to_string(mu) + "\ntorque = 5\nrun = \"forever\"\n";
            const SceneLoad load = parseScene(carScene(slope, 0.0, keys), "car.toml");
            REQUIRE(load.ok());
            LevelRun run(*load.scene, {});
            const Vec2 dir{std::cos(theta), std::sin(theta)};
            const Vec2 start = bodyOf(run).position;
            for (int i = 0; i < 100; ++i) run.step();
            const double moved = (bodyOf(run).position - start).dot(dir);
            if (margin > 0.0) {
                CHECK(moved > 0.5); // up the slope
                CHECK(bodyOf(run).velocity.dot(dir) > 0.0);
            } else {
                // Sliding back with its wheels spinning uphill: s = 1/2 g (sin - mu cos) t^2 over 1 s, to 10 %.
                CHECK(-moved == Approx(0.5 * kG * -margin * 1.0).epsilon(0.1));
            }
        }
    }
}

TEST_CASE("car: after its run time it coasts to rest and stays there", "[parts][car]") {
    for (const double speed : {1.0, 2.0}) {
        for (const double runFor : {0.5, 1.5}) {
            CAPTURE(speed, runFor);
            const std::string keys = "speed = " + std::to_string(speed) + "\nrun = " + std::to_string(runFor) + "\n";
            const SceneLoad load = parseScene(carScene(0.0, 0.0, keys), "car.toml");
            REQUIRE(load.ok());
            LevelRun run(*load.scene, {});
            const int runSteps = static_cast<int>(std::lround(runFor / 0.01));
            for (int i = 0; i < runSteps; ++i) run.step();
            const double atRunDown = bodyOf(run).velocity.x;
            CHECK(atRunDown > 0.5 * speed);
            // The gearbox's drag, 0.2 N m a wheel, stops it in v (M + m_w) r / (2 x 0.2): 0.1 s to spare.
            const double stopping = atRunDown * (1.5 + kWheelMass) * kWheelRadius / 0.4;
            for (int i = 0; i < static_cast<int>(std::ceil((stopping + 0.1) / 0.01)); ++i) run.step();
            CHECK(std::abs(bodyOf(run).velocity.x) < 0.01);
            const Vec2 stopped = bodyOf(run).position;
            for (int i = 0; i < 200; ++i) run.step();
            CHECK((bodyOf(run).position - stopped).length() < 0.01);
        }
    }
}

TEST_CASE("car: waiting for a trigger it stays still, and triggered it drives", "[parts][car]") {
    for (const char* facing : {"right", "left"}) {
        CAPTURE(facing);
        const std::string keys = std::string("on = false\nfacing = \"") + facing + "\"\n";
        const SceneLoad load = parseScene(carScene(0.0, 0.0, keys), "car.toml");
        REQUIRE(load.ok());
        LevelRun run(*load.scene, {});
        const Vec2 start = bodyOf(run).position;
        for (int i = 0; i < 300; ++i) run.step();
        CHECK((bodyOf(run).position - start).length() < 1e-3);
        CHECK(run.items()[0].kind->waits(run.items()[0], run.states()[0]) == false);
        run.items()[0].kind->trigger(run, 0);
        for (int i = 0; i < 200; ++i) run.step();
        const double sign = std::string(facing) == "right" ? 1.0 : -1.0;
        CHECK(sign * bodyOf(run).velocity.x == Approx(1.5).epsilon(0.01));
    }
}

TEST_CASE("car: read like every [[item]], with its own keys only", "[parts][car]") {
    const std::string floor = "name = \"t\"\n[[segment]]\na = [-5, 0]\nb = [5, 0]\n";
    CHECK(firstError(floor + "[[item]]\nkind = \"car\"\nposition = [0, 1]\nsped = 2\n") ==
          "t.toml:8:1: unknown key 'sped' in [[item]] of kind 'car' (did you mean 'speed'?)");
    CHECK(firstError(floor + "[[item]]\nkind = \"car\"\nposition = [0, 1]\nfacing = \"up\"\n")
              .starts_with("t.toml:8:10: facing must be"));
    CHECK(firstError(floor + "[[item]]\nkind = \"car\"\nposition = [0, 1]\nrun = \"always\"\n")
              .starts_with("t.toml:8:7: run must be"));
    CHECK(firstError(floor + "[[item]]\nkind = \"car\"\nposition = [0, 1]\nrun = -1\n")
              .starts_with("t.toml:8:7: run must be"));
    CHECK(firstError(floor + "[[item]]\nkind = \"car\"\nposition = [0, 1]\nrun = \"forever\"\nfacing = \"left\"\n") ==
          "no error");
}
