// The seesaw (issue 22): the lever law over a range of loads. Balls m1 at l1 left of the pivot and
// m2 at l2 right of it start the plank turning at alpha = g (m1 l1 - m2 l2) / I, I = I_plank + m1 l1^2
// + m2 l2^2 about the pivot (the balls as point loads): towards the larger moment, and not at all
// when the moments are equal. A heavy ball dropped on the raised arm throws the ball resting on the
// lowered one up, never higher than the dropped ball's energy allows.
#include "level_run.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

using namespace rube;
using namespace rube::game;

namespace {

constexpr double kHalfThickness = 0.06; // seesaw.cpp
constexpr double kG = 9.81, kStep = 0.01;

struct Ball {
    const char* kind;
    double mass, radius;
};
constexpr Ball kHeavy{"heavy", 8.0, 0.3}, kSteel{"steel", 4.0, 0.2}, kBouncy{"bouncy", 0.5, 0.25};

std::string seesaw(double length, double mass, double degrees, double limit) {
    std::ostringstream text;
    text.precision(17);
    text << "name = \"seesaw-test\"\n[world]\ntime_step = " << kStep
         << "\nbounds = { min = [-30, -30], max = [30, 30] }\n"
         << "[[item]]\nkind = \"seesaw\"\nposition = [0, 2]\nlength = " << length << "\nmass = " << mass
         << "\nangle = " << degrees << "\nlimit = " << limit << "\n";
    return text.str();
}

std::string ball(const Ball& b, double x, double y) {
    std::ostringstream text;
    text.precision(17);
    text << "[[item]]\nkind = \"" << b.kind << "\"\nposition = [" << x << ", " << y << "]\n";
    return text.str();
}

LevelRun load(const std::string& text) {
    const SceneLoad scene = parseScene(text, "seesaw-test.toml");
    INFO((scene.errors.empty() ? std::string() : scene.errors.front().format()));
    REQUIRE(scene.ok());
    return LevelRun(*scene.scene, {});
}

} // namespace

TEST_CASE("a seesaw tips towards the larger moment at g (m1 l1 - m2 l2) / I, and balances equal ones",
          "[parts][seesaw]") {
    struct Case {
        Ball left;
        double l1;
        Ball right;
        double l2;
    };
    const double length = 3.0, plankMass = 2.0;
    const double plankI = plankMass * (length * length + 4 * kHalfThickness * kHalfThickness) / 12.0;
    for (const Case c :
         {Case{kHeavy, 0.5, kSteel, 1.0}, Case{kSteel, 1.2, kHeavy, 0.6}, Case{kBouncy, 1.2, kSteel, 0.15},
          Case{kHeavy, 0.4, kSteel, 0.6}, Case{kSteel, 1.4, kHeavy, 0.5}, Case{kBouncy, 1.4, kSteel, 0.2},
          Case{kSteel, 0.3, kBouncy, 1.3}}) {
        INFO(c.left.kind << " at " << c.l1 << " left, " << c.right.kind << " at " << c.l2 << " right");
        const double top = 2.0 + kHalfThickness;
        LevelRun run = load(seesaw(length, plankMass, 0.0, 0.0) + ball(c.left, -c.l1, top + c.left.radius) +
                            ball(c.right, c.l2, top + c.right.radius));
        const double moment = c.left.mass * c.l1 - c.right.mass * c.l2; // kg m; counter-clockwise positive
        const double inertia = plankI + c.left.mass * c.l1 * c.l1 + c.right.mass * c.l2 * c.l2;
        const double expected = kG * moment / inertia;
        // The larger of the two loads' moments alone: the scale of "balanced".
        const double scale = kG * std::max(c.left.mass * c.l1, c.right.mass * c.l2) / inertia;
        const int steps = 10;
        for (int i = 0; i < steps; ++i) run.step();
        const double alpha = run.world().body(run.states()[0].body).angularVelocity / (steps * kStep);
        if (std::abs(moment) < 1e-12) {
            // Balanced: within 1 % of what the larger load alone would start (0.3 % to 2.7 % of that
            // 1 % measured: the soft contacts' settling).
            CHECK(std::abs(alpha) < 0.01 * scale);
        } else {
            // Tips the larger moment's way, at the lever law's rate within 5 % (1.2 % measured: the
            // balls roll a little as the arm tips).
            CHECK(alpha * moment > 0.0);
            CHECK(alpha == Approx(expected).epsilon(0.05));
        }
    }
}

TEST_CASE("a ball dropped on a seesaw's raised arm throws the ball on its lowered arm up", "[parts][seesaw]") {
    const double length = 3.0, limit = 15.0, l1 = 1.3, l2 = 0.8;
    const double s = std::sin(limit * std::numbers::pi / 180.0), c = std::cos(limit * std::numbers::pi / 180.0);
    for (const double drop : {0.5, 1.0, 1.5}) {
        INFO("dropped from " << drop << " m above the raised arm");
        // Tilted right end down; the bouncy ball rests on it at l2 (it rolls down the arm, but not off
        // its end, before the drop lands), the heavy one falls on the left at l1.
        const Vec2 lowered{l2 * c + s * (kHalfThickness + kBouncy.radius),
                           2.0 - l2 * s + c * (kHalfThickness + kBouncy.radius)};
        const Vec2 raised{-l1 * c, 2.0 + l1 * s + kHalfThickness + kHeavy.radius + drop};
        LevelRun run = load(seesaw(length, 2.0, -limit, limit) + ball(kHeavy, raised.x, raised.y) +
                            ball(kBouncy, lowered.x, lowered.y));
        const CircleId thrown = run.states()[2].circle;
        double apex = lowered.y;
        for (int i = 0; i < 300; ++i) {
            run.step();
            apex = std::max(apex, run.world().circle(thrown).position.y);
        }
        // Thrown up: at least 0.3 m above where it rested (1.9 to 2.8 m measured).
        CHECK(apex - lowered.y > 0.3);
        // Never higher than the heavy ball's fall onto the arm and with it (2 l1 sin limit) could lift it:
        // m2 g rise <= m1 g (drop + 2 l1 sin limit), energy conserved at best.
        CHECK(kBouncy.mass * (apex - lowered.y) <= kHeavy.mass * (drop + 2 * l1 * s));
    }
}

TEST_CASE("a seesaw's tilt stays within its limits", "[parts][seesaw]") {
    for (const double limit : {10.0, 25.0, 40.0}) {
        INFO("limit " << limit);
        LevelRun run = load(seesaw(3.0, 2.0, 0.0, limit) + ball(kHeavy, -1.3, 5.0));
        double most = 0.0;
        for (int i = 0; i < 300; ++i) {
            run.step();
            most = std::max(most, run.world().body(run.states()[0].body).angle);
        }
        // Held at the limit (soft: within half a degree, 0.39 degrees measured) once the heavy ball
        // lands on the left arm.
        CHECK(most * 180.0 / std::numbers::pi == Approx(limit).margin(0.5));
    }
}
