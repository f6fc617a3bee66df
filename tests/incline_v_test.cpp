// Resting and sliding contact on inclines and in a V of two lines (issue 19, parts 1 and 3): a
// frictionless ball slides down an incline at g sin(theta) under turn-based, and comes to rest in a V
// under exact, checked against the formulas over the range of angles and bouncinesses.
#include "rube/physics/world.hpp"
#include "scene_builders.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace rube;
using rube::test::ball;
using rube::test::line;

namespace {

constexpr double kG = 9.81;
constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 0.25;

World makeWorld(Method method) {
    WorldDef def;
    def.method = method;
    def.gravity = {0.0, -kG};
    def.timeStep = 1.0 / 60;
    return World(def);
}

// g y + v^2 / 2 per kilogram: a frictionless ball with C <= 1 may only lose it.
double energy(const Circle& c) { return kG * c.position.y + 0.5 * c.velocity.lengthSquared(); }

// A V of two static lines with rounded caps meeting at the origin, each `halfAngle` from the vertical
// axis (the V's axis), 5 m long, of bounciness C. The ball rests touching both with its centre on the
// axis at r / sin(halfAngle).
void addV(World& world, double halfAngle, double bounciness) {
    const double length = 5.0;
    for (const double side : {-1.0, 1.0}) {
        SegmentDef def = line({0, 0}, {side * length * std::sin(halfAngle), length * std::cos(halfAngle)});
        def.material = {bounciness, 0.0};
        world.addSegment(def);
    }
}

// The distances from the ball's surface to the two lines of addV (positive: a gap).
std::pair<double, double> gaps(const Circle& c, double halfAngle) {
    const double across = c.position.x * std::cos(halfAngle), up = c.position.y * std::sin(halfAngle);
    return {std::abs(up + across) - c.radius, std::abs(up - across) - c.radius};
}

} // namespace

TEST_CASE("turn-based: a frictionless ball slides down an incline at g sin(theta)", "[turn-based][incline]") {
    for (const double degrees : {0.05, 0.5, 1.0, 5.0, 15.0, 30.0, 36.87, 45.0, 60.0}) {
        INFO("incline " << degrees << " degrees");
        const double theta = degrees * kPi / 180.0;
        World world = makeWorld(Method::turnBased);
        const Vec2 down{std::cos(theta), -std::sin(theta)};
        const Vec2 normal{std::sin(theta), std::cos(theta)};
        world.addSegment(line(down * -600.0, down * 600.0));
        const Vec2 start = down * -300.0 + normal * kRadius; // touching the line, at rest
        world.addCircle(ball(start, {}, kRadius));
        const double e0 = energy(world.circles()[0]);
        Vec2 before = start;
        double worstStep = 0.0, worstRise = 0.0, worstOff = 0.0;
        for (int step = 1; step <= 600; ++step) {
            world.step();
            const Circle& c = world.circles()[0];
            // Semi-implicit Euler (lecture 3): the step's move is the velocity it integrated times dt.
            worstStep = std::max(worstStep, ((c.position - before) - c.velocity * world.def().timeStep).length());
            worstRise = std::max(worstRise, energy(c) - e0);
            worstOff = std::max(worstOff, std::abs((c.position - start).dot(normal)));
            before = c.position;
        }
        const Circle& c = world.circles()[0];
        const double t = world.time(), gAlong = kG * std::sin(theta);
        // v = g sin(theta) t; x = g sin(theta) t^2 / 2, within 1 % (Euler's x is (n + 1) / n of it: 0.17 %).
        CHECK(c.velocity.dot(down) == Approx(gAlong * t).epsilon(1e-9));
        CHECK((c.position - start).dot(down) == Approx(0.5 * gAlong * t * t).epsilon(0.01));
        CHECK(worstStep < 1e-9);
        CHECK(worstOff < 1e-9); // it neither sinks into the line nor leaves it
        CHECK(worstRise <= 1e-9 * std::abs(e0));
    }
}

TEST_CASE("turn-based: a ball dropped into a V never gains energy", "[turn-based][v]") {
    for (int degrees = 5; degrees <= 80; degrees += 5) {
        for (const double bounciness : {0.0, 0.3, 0.6, 0.9}) {
            for (const double drop : {0.1, 0.5}) {
                INFO("half-angle " << degrees << " degrees, C = " << bounciness << ", drop " << drop << " m");
                const double halfAngle = degrees * kPi / 180.0;
                World world = makeWorld(Method::turnBased);
                addV(world, halfAngle, bounciness);
                const double y = kRadius / std::sin(halfAngle) + drop;
                const double room = (y * std::sin(halfAngle) - kRadius) / std::cos(halfAngle);
                CircleDef def = ball({0.3 * room, y}, {}, kRadius);
                def.material = {bounciness, 0.0};
                world.addCircle(def);
                const double e0 = energy(world.circles()[0]);
                double worstRise = 0.0;
                for (int step = 0; step < 600; ++step) {
                    world.step();
                    worstRise = std::max(worstRise, energy(world.circles()[0]) - e0);
                }
                CHECK(worstRise <= 1e-9 * e0);
            }
        }
    }
}

TEST_CASE("exact: a ball dropped into a V comes to rest touching both lines", "[exact][v]") {
    // Held by two lines at an angle, a resting ball has nowhere to go: it must stop, not cycle.
    for (int degrees = 5; degrees <= 80; degrees += 5) {
        for (const double bounciness : {0.0, 0.3, 0.6, 0.9}) {
            for (const double offset : {0.0, 0.1, 0.3}) {
                INFO("half-angle " << degrees << " degrees, C = " << bounciness << ", offset " << offset
                                   << " of the room");
                const double halfAngle = degrees * kPi / 180.0;
                World world = makeWorld(Method::exact);
                addV(world, halfAngle, bounciness);
                // Dropped from 0.1 m above its resting height, `offset` of the way from the axis to a line.
                const double rest = kRadius / std::sin(halfAngle), y = rest + 0.1;
                const double room = (y * std::sin(halfAngle) - kRadius) / std::cos(halfAngle);
                CircleDef def = ball({offset * room, y}, {}, kRadius);
                def.material = {bounciness, 0.0};
                world.addCircle(def);
                for (int step = 0; step < 300; ++step) world.step(); // 5 s
                const Circle& c = world.circles()[0];
                const auto [gapA, gapB] = gaps(c, halfAngle);
                CHECK(std::abs(gapA) < 1e-9);
                CHECK(std::abs(gapB) < 1e-9);
                CHECK(std::abs(c.position.x) < 1e-9);
                CHECK(std::abs(c.position.y - rest) < 1e-9);
                CHECK(c.velocity.length() < 1e-9);
                CHECK(world.stats().capsHit == 0);
            }
        }
    }
}
