// The pulley (issue 22): two loads on a rope over a wheel accelerate at Atwood's
// a = g (m2 - m1) / (m1 + m2) within 0.5 %, over a range of masses and both kinds of load, the rope
// keeps its length (taut within 1 um of left_drop + right_drop), and a bucket that
// catches a ball outweighs the counterweight on the floor and sinks, lifting it.
#include "level_run.hpp"
#include "scene_file.hpp"
#include "scene_number.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

using namespace rube;
using namespace rube::game;
using test::num;

namespace {

constexpr double kG = 9.81;

SceneDesc scene(const std::string& body) {
    std::ostringstream text;
    text << "name = \"pulley-test\"\n[world]\ntime_step = 0.01\nmethod = \"auto\"\ngravity = [0, " << num(-kG)
         << "]\nbounds = { min = [-20, -20], max = [20, 20] }\n"
         << body;
    const SceneLoad load = parseScene(text.str(), "pulley-test.toml");
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return *load.scene;
}

std::string pulley(const std::string& left, double m1, const std::string& right, double m2, double drop = 3.0) {
    return "[[item]]\nkind = \"pulley\"\nname = \"p\"\nposition = [0, 5]\nleft = \"" + left +
           "\"\nleft_mass = " + num(m1) + "\nleft_drop = " + num(drop) + "\nright = \"" + right +
           "\"\nright_mass = " + num(m2) + "\nright_drop = " + num(drop) + "\n";
}

// The rope's length now: from each load's hook to its side of the wheel.
double ropeLength(const LevelRun& run) {
    const JointDef& d = run.world().joint(run.states()[0].joints.back()).def;
    return run.world().worldPoint(d.a, d.localAnchorA).distance(d.groundA) +
           run.world().worldPoint(d.b, d.localAnchorB).distance(d.groundB);
}

// The height of the body the rope holds on the right.
double rightHeight(const LevelRun& run) {
    const JointDef& d = run.world().joint(run.states()[0].joints.back()).def;
    return run.world().worldPoint(d.b, d.localAnchorB).y;
}

} // namespace

TEST_CASE("a pulley's loads accelerate at Atwood's g (m2 - m1) / (m1 + m2) and its rope keeps its length",
          "[parts][pulley]") {
    struct Case {
        const char *left, *right;
        double m1, m2;
    };
    for (const Case c :
         {Case{"weight", "weight", 1.0, 3.0}, Case{"weight", "weight", 2.0, 2.5}, Case{"weight", "weight", 4.0, 1.0},
          Case{"bucket", "weight", 0.5, 2.0}, Case{"bucket", "bucket", 3.0, 0.7}, Case{"weight", "bucket", 0.2, 5.0}}) {
        INFO(c.left << " " << c.m1 << " kg, " << c.right << " " << c.m2 << " kg");
        LevelRun run(scene(pulley(c.left, c.m1, c.right, c.m2)), {});
        const double length = 6.0, start = rightHeight(run);
        REQUIRE(ropeLength(run) == Approx(length).margin(1e-12));
        // The right side sinks at a = g (m2 - m1) / (m1 + m2) (a light wheel, a rope without mass):
        // after t, it has gone down a t^2 / 2. 0.6 s: the loads stay clear of the wheel and each other.
        const double a = kG * (c.m2 - c.m1) / (c.m1 + c.m2);
        double longest = 0.0, shortest = 1e9;
        for (int i = 0; i < 60; ++i) {
            run.step();
            longest = std::max(longest, ropeLength(run));
            shortest = std::min(shortest, ropeLength(run));
        }
        const double t = run.world().time();
        CHECK(start - rightHeight(run) == Approx(0.5 * a * t * t).epsilon(0.005));
        // Taut the whole time: its length within 1 um of left_drop + right_drop (measured: 2e-14 m).
        CHECK(longest <= length + 1e-6);
        CHECK(shortest >= length - 1e-6);
    }
}

TEST_CASE("a ball caught in a pulley's bucket sinks it and lifts the counterweight off the floor", "[parts][pulley]") {
    for (const char* ball : {"", "steel", "heavy"}) {
        INFO("a ball: " << (*ball ? ball : "none") << ", a 2 kg counterweight");
        // The counterweight (2 kg) stands on the floor, its hook 3 m up; the empty bucket (0.5 kg)
        // hangs with its floor 1.05 m above the floor. Its rope: 1 + 2 m. The ball drops in from
        // below the wheel, 0.5 m above the bucket's rim.
        std::string body =
            "[[item]]\nkind = \"pulley\"\nname = \"p\"\nposition = [0, 5]\nleft_drop = 1\n"
            "left_mass = 0.5\nright_drop = 2\nright_mass = 2\n[[segment]]\na = [-5, 2.5]\nb = [5, 2.5]\n";
        if (*ball) body += std::string("[[item]]\nkind = \"") + ball + "\"\nposition = [-0.6, 4.5]\nradius = 0.2\n";
        LevelRun run(scene(body), {});
        for (int i = 0; i < 300; ++i) run.step();
        CHECK(ropeLength(run) <= 3.0 + 1e-3);
        if (!*ball) {
            // Nothing in the bucket: 0.5 kg cannot lift 2 kg, which stays on the floor.
            CHECK(rightHeight(run) == Approx(3.0).margin(0.01));
            continue;
        }
        // The ball (4 or 8 kg) outweighs the weight: the bucket sinks to the floor (1.05 m) and the
        // rope lifts the weight by as much.
        CHECK(rightHeight(run) == Approx(3.0 + 1.05).margin(0.05));
    }
}
