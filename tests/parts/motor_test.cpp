// The motor, the wheel and the belt (issue 22): a motor reaches its speed with an angular
// acceleration of at most tau_max / I, a switch powers it and switches it off, and a belt turns its
// second wheel the same way at r1 / r2 of the first within 0.5 %, over a range of radii.
#include "level_run.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>

using namespace rube;
using namespace rube::game;

namespace {

SceneDesc scene(const std::string& items, double gravity = 0.0) {
    std::ostringstream text;
    text << "name = \"motor-test\"\n[world]\ntime_step = 0.01\nmethod = \"auto\"\ngravity = [0, " << gravity
         << "]\nbounds = { min = [-20, -20], max = [20, 20] }\n"
         << items;
    const SceneLoad load = parseScene(text.str(), "motor-test.toml");
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return *load.scene;
}

std::string motor(double radius, double mass, double speed, double torque, bool on = true) {
    std::ostringstream s;
    s << "[[item]]\nkind = \"motor\"\nname = \"drive\"\nposition = [-3, 1]\nradius = " << radius << "\nmass = " << mass
      << "\nspeed = " << speed << "\ntorque = " << torque << "\non = " << (on ? "true" : "false") << "\n";
    return s.str();
}

double spin(const LevelRun& run, int item) { return run.world().circle(run.states()[item].circle).angularVelocity; }
double turned(const LevelRun& run, int item) { return run.world().circle(run.states()[item].circle).angle; }

} // namespace

TEST_CASE("a motor reaches its speed, never turning faster than tau_max / I allows", "[parts][motor]") {
    struct Case {
        double radius, mass, speed, torque;
    };
    for (const Case c :
         {Case{0.4, 2.0, 3.0, 20.0}, Case{0.4, 2.0, 3.0, 0.5}, Case{0.8, 5.0, -6.0, 4.0}, Case{0.25, 0.5, 10.0, 0.1}}) {
        INFO("r " << c.radius << " m " << c.mass << " speed " << c.speed << " torque " << c.torque);
        LevelRun run(scene(motor(c.radius, c.mass, c.speed, c.torque)), {});
        // A solid disc: I = 1/2 m r^2, so the motor's torque turns it at most alpha = tau / I.
        const double alpha = c.torque / (0.5 * c.mass * c.radius * c.radius);
        const double dt = run.world().def().timeStep;
        const double rampTime = std::abs(c.speed) / alpha; // at full torque the whole way
        double before = spin(run, 0), fastest = 0.0;
        const int steps = static_cast<int>(std::ceil(rampTime / dt)) + 100;
        for (int i = 0; i < steps; ++i) {
            run.step();
            const double now = spin(run, 0);
            fastest = std::max(fastest, std::abs(now - before) / dt);
            before = now;
        }
        CHECK(fastest <= alpha * (1.0 + 1e-9));
        CHECK(spin(run, 0) == Approx(c.speed).epsilon(1e-3));
        // Not slower than the limit either: the speed is reached within a step of speed / alpha.
        if (rampTime > 5 * dt) CHECK(fastest == Approx(alpha).epsilon(1e-3));
        // The axle holds the disc where it was placed.
        CHECK(run.itemPosition(0).distance({-3.0, 1.0}) < 1e-6);
    }
}

TEST_CASE("a switch powers a motor that starts off, and a second trigger switches it off", "[parts][motor]") {
    const std::string items = motor(0.4, 2.0, 4.0, 2.0, false) + R"(
[[item]]
kind = "switch"
name = "button"
position = [3, 1]
triggers = "drive"
)";
    LevelRun run(scene(items, -9.81), {});
    for (int i = 0; i < 100; ++i) run.step();
    CHECK(spin(run, 0) == 0.0); // unpowered, under gravity, on a centred axle: nothing turns it
    run.toggle(1);              // the switch, as a click would press it
    for (int i = 0; i < 20; ++i) run.step();
    const double alpha = 2.0 / (0.5 * 2.0 * 0.4 * 0.4);
    CHECK(spin(run, 0) == Approx(20 * 0.01 * alpha).epsilon(1e-3)); // full torque the whole 0.2 s
    run.toggle(0); // the motor itself: off again, it coasts (no friction on the axle)
    const double coasting = spin(run, 0);
    for (int i = 0; i < 50; ++i) run.step();
    CHECK(spin(run, 0) == Approx(coasting).epsilon(1e-9));
}

TEST_CASE("a belt turns its second wheel the same way at r1 / r2 of the first, within 0.5 %", "[parts][belt]") {
    for (const double r1 : {0.2, 0.4, 0.8}) {
        for (const double r2 : {0.15, 0.4, 1.0}) {
            INFO("r1 " << r1 << " r2 " << r2);
            std::ostringstream items;
            // The belt is listed first: it names wheels listed after it.
            items << "[[item]]\nkind = \"belt\"\nposition = [0, 3]\nfrom = \"drive\"\nto = \"driven\"\n"
                  << motor(r1, 2.0, 3.0, 50.0)
                  << "[[item]]\nkind = \"wheel\"\nname = \"driven\"\nposition = [3, 1]\nradius = " << r2
                  << "\npaddles = 2\n";
            LevelRun run(scene(items.str(), -9.81), {});
            const double start1 = turned(run, 1), start2 = turned(run, 2);
            for (int i = 0; i < 300; ++i) run.step();
            CHECK(spin(run, 1) ==
                  Approx(3.0).epsilon(0.01)); // the motor holds its speed against the load (soft joints: within 1 %)
            CHECK(spin(run, 2) == Approx(spin(run, 1) * r1 / r2).epsilon(0.005));
            // The turns too: theta2 - theta2(0) = (r1 / r2)(theta1 - theta1(0)), the rims run together.
            CHECK(turned(run, 2) - start2 == Approx((turned(run, 1) - start1) * r1 / r2).epsilon(0.005));
            CHECK(run.itemPosition(2).distance({3.0, 1.0}) < 1e-4); // the axle holds under the paddles' weight
        }
    }
}
