// The hammer (issue 22): a compound pendulum. Released from its handle's angle theta0 it reaches the
// bottom turning at omega = sqrt(2 M g h / I), h = d (sin theta0 + 1) the fall of its centre of mass
// (d from the pivot) and I = sum of m k^2 + m r^2 over handle and head (parallel-axis theorem), within
// 0.1 %, over five start angles and three lengths; the head stays on its handle within 1 mm over the
// swing and over blows on three balls; latched, it holds until released.
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

constexpr double kHandleRadius = 0.04, kHandleMass = 0.3; // hammer.cpp
constexpr Vec2 kHeadHalf{0.12, 0.22};
constexpr double kG = 9.81;

LevelRun hammer(double degrees, double length, double mass, bool latched, const std::string& more = "") {
    std::ostringstream text;
    text.precision(17);
    text << "name = \"hammer-test\"\n[world]\ntime_step = 0.01\nbounds = { min = [-30, -30], max = [30, 30] }\n"
         << more << "[[item]]\nkind = \"hammer\"\nname = \"mallet\"\nposition = [0, 3]\nangle = " << degrees
         << "\nlength = " << length << "\nmass = " << mass << "\nlatched = " << (latched ? "true" : "false") << "\n";
    const SceneLoad load = parseScene(text.str(), "hammer-test.toml");
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return LevelRun(*load.scene, {});
}

// How far the head's centre is from the handle's end it is welded to, m.
double headOffHandle(const LevelRun& run, double length, int item = 0) {
    const ItemState& state = run.states()[static_cast<std::size_t>(item)];
    const RigidBody& handle = run.world().body(state.body);
    // The head: the weld's (joint 1's) other end.
    const RigidBody& head = run.world().bodies()[static_cast<std::size_t>(run.world().joint(state.joints[1]).bodyB)];
    const Vec2 end = handle.position + Vec2::fromAngle(handle.angle) * (0.5 * length);
    return end.distance(head.position);
}

} // namespace

TEST_CASE("a released hammer reaches the bottom at omega = sqrt(2 M g h / I), its head staying on its handle",
          "[parts][hammer]") {
    for (const double length : {0.6, 1.0, 1.5}) {
        for (const double degrees : {-45.0, 0.0, 45.0, 120.0, 170.0}) {
            const double mass = 2.0;
            INFO("length " << length << ", released at " << degrees << " degrees");
            LevelRun run = hammer(degrees, length, mass, false);
            // I about the pivot: the handle (a capsule about its middle, L / 2 away) and the head (a
            // box about its centre, L away).
            const double inertia = momentOfInertia(BodyShape::capsule, {0.5 * length, kHandleRadius}, kHandleMass) +
                                   kHandleMass * 0.25 * length * length +
                                   momentOfInertia(BodyShape::box, kHeadHalf, mass) + mass * length * length;
            const double total = kHandleMass + mass;
            const double d = (kHandleMass * 0.5 * length + mass * length) / total;
            const double h = d * (std::sin(degrees * std::numbers::pi / 180.0) + 1.0);
            const double expected = std::sqrt(2.0 * total * kG * h / inertia);
            double fastest = 0.0, off = 0.0;
            for (int i = 0; i < 300; ++i) {
                run.step();
                fastest = std::max(fastest, std::abs(run.world().body(run.states()[0].body).angularVelocity));
                off = std::max(off, headOffHandle(run, length));
            }
            // The fastest it turns is at the bottom, where all of M g h is kinetic: within 0.1 % (0.007 %
            // measured).
            CHECK(fastest == Approx(expected).epsilon(0.001));
            CHECK(off < 1e-3);
        }
    }
}

TEST_CASE("a hammer's head stays on its handle when it strikes a ball, and a latched one holds until released",
          "[parts][hammer]") {
    struct Ball {
        const char* kind;
        double radius;
    };
    for (const double mass : {0.5, 2.0, 8.0}) {
        for (const Ball ball : {Ball{"bouncy", 0.25}, Ball{"steel", 0.2}, Ball{"heavy", 0.3}}) {
            INFO("head " << mass << " kg, striking the " << ball.kind << " ball");
            // The ball on a ledge just past the bottom of the swing, its centre at the head's height there.
            std::ostringstream more;
            more << "[[segment]]\na = [-0.5, " << 2.0 - ball.radius << "]\nb = [3, " << 2.0 - ball.radius
                 << "]\n[[item]]\nkind = \"" << ball.kind << "\"\nposition = [" << kHeadHalf.y + ball.radius + 0.05
                 << ", 2]\n";
            LevelRun run = hammer(150.0, 1.0, mass, true, more.str());
            for (int i = 0; i < 100; ++i) run.step();
            CHECK(std::abs(run.world().body(run.states()[1].body).angle - 150.0 * std::numbers::pi / 180.0) < 0.01);
            run.toggle(1);
            double off = 0.0;
            for (int i = 0; i < 300; ++i) {
                run.step();
                off = std::max(off, headOffHandle(run, 1.0, 1));
            }
            // Struck: the ball is sent off along the ledge.
            CHECK(run.world().circle(run.states()[0].circle).position.x > 1.0);
            CHECK(off < 1e-3);
        }
    }
}
