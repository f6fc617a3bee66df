// The `auto` method: it must take the exact method's steps bit for bit while a scene is sparse,
// hand piles, crowds and friction to the solver, and keep what both promise: no tunnel at any
// speed, no overlap beyond a few per cent of a radius, no event cap hit.
#include "rube/physics/collision.hpp"
#include "rube/physics/world.hpp"
#include "scene_builders.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace rube;
using rube::test::ball;
using rube::test::line;

namespace {

WorldDef defWith(Method method) {
    WorldDef def;
    def.method = method;
    return def;
}

// A pool rack: 15 balls in a triangle and a cue ball, no gravity.
void addRack(World& world) {
    const double r = 0.1;
    for (int row = 0; row < 5; ++row)
        for (int i = 0; i <= row; ++i)
            world.addCircle(ball({1.0 + row * r * std::sqrt(3.0), (i - row / 2.0) * 2.0 * r}, {}, r));
    world.addCircle(ball({-1.0, 0.01}, {6.0, 0.0}, r));
    world.addSegment(line({-3, -2}, {3, -2}));
    world.addSegment(line({-3, 2}, {3, 2}));
    world.addSegment(line({-3, -2}, {-3, 2}));
    world.addSegment(line({3, -2}, {3, 2}));
}

// `columns` x `rows` balls of radius 0.1 m dropped into a box 2 m wide: a pile.
void addPile(World& world, int columns, int rows) {
    world.addSegment(line({-1, 0}, {1, 0}));
    world.addSegment(line({-1, 0}, {-1, 10}));
    world.addSegment(line({1, 0}, {1, 10}));
    for (int row = 0; row < rows; ++row)
        for (int col = 0; col < columns; ++col) {
            CircleDef c = ball({-0.8 + 0.24 * col + (row % 2) * 0.06, 0.5 + 0.24 * row}, {}, 0.1);
            c.mass = 0.1;
            c.material.bounciness = 0.3;
            world.addCircle(c);
        }
}

double largestOverlap(const World& world) {
    double worst = 0.0;
    const auto circles = world.circles();
    for (std::size_t i = 0; i < circles.size(); ++i) {
        for (std::size_t j = i + 1; j < circles.size(); ++j)
            worst = std::max(worst,
                             circles[i].radius + circles[j].radius - circles[i].position.distance(circles[j].position));
        for (const Segment& s : world.segments())
            worst = std::max(worst,
                             circles[i].radius + s.radius -
                                 circles[i].position.distance(closestPointOnSegment(circles[i].position, s.a, s.b)));
    }
    return worst;
}

} // namespace

TEST_CASE("auto: a sparse scene takes the exact method's steps, bit for bit", "[auto]") {
    SECTION("a bouncing ball") {
        World exact(defWith(Method::exact)), automatic(defWith(Method::automatic));
        for (World* w : {&exact, &automatic}) {
            w->addSegment(line({-10, 0}, {10, 0}));
            w->addCircle(ball({0, 10}, {}, 0.5));
        }
        for (int i = 0; i < 1200; ++i) {
            exact.step();
            automatic.step();
        }
        CHECK(automatic.stats().autoSolverSteps == 0);
        CHECK(stateHash(automatic) == stateHash(exact));
    }
    SECTION("a pool break") {
        WorldDef e = defWith(Method::exact), a = defWith(Method::automatic);
        e.gravity = a.gravity = {};
        World exact(e), automatic(a);
        addRack(exact);
        addRack(automatic);
        for (int i = 0; i < 240; ++i) {
            exact.step();
            automatic.step();
        }
        CHECK(exact.stats().impacts > 20);
        CHECK(automatic.stats().autoSolverSteps == 0);
        CHECK(stateHash(automatic) == stateHash(exact));
    }
}

TEST_CASE("auto: a pile too big for exact's search is the solver's from the first step", "[auto]") {
    World solver(defWith(Method::solver)), automatic(defWith(Method::automatic));
    addPile(solver, 8, 20); // 160 balls: 160 x 163 pair tests a search, so not even 16 events fit the budget
    addPile(automatic, 8, 20);
    for (int i = 0; i < 120; ++i) {
        solver.step();
        automatic.step();
    }
    CHECK(automatic.stats().autoSolverSteps == 120);
    CHECK(stateHash(automatic) == stateHash(solver));
}

TEST_CASE("auto: a small crowd starts exact and falls back to the solver when the events pile up", "[auto]") {
    World automatic(defWith(Method::automatic));
    addPile(automatic, 7, 8); // 56 balls: exact can afford 19 events a step, and a settling pile needs more
    double worstLate = 0.0;
    for (int i = 0; i < 300; ++i) {
        automatic.step();
        if (i >= 240) worstLate = std::max(worstLate, largestOverlap(automatic));
    }
    const StepStats& s = automatic.stats();
    CHECK(s.autoSolverSteps > 0);
    CHECK(s.autoSolverSteps < 300); // the fall before the first contacts is exact's
    CHECK(s.capsHit == 0);          // a failed trial is put back, not counted
    CHECK(s.escapes == 0);
    CHECK(worstLate < 0.05 * 0.1); // the solver's promise: overlaps under 5 % of a radius
}

TEST_CASE("auto: friction on both sides of a contact is the solver's (exact has none)", "[auto]") {
    const double theta = 20.0 * std::numbers::pi / 180.0;
    const Vec2 down{std::cos(theta), -std::sin(theta)};
    const Vec2 normal{std::sin(theta), std::cos(theta)};
    World world(defWith(Method::automatic));
    SegmentDef slope = line(down * -50.0, down * 50.0);
    slope.material = {0.0, 0.8};
    world.addSegment(slope);
    CircleDef disc = ball(normal * 0.5, {}, 0.5);
    disc.material = {0.0, 0.8};
    world.addCircle(disc);
    for (int i = 0; i < 30; ++i) world.step();
    const double v0 = world.circles()[0].velocity.dot(down);
    const double t0 = world.time();
    for (int i = 0; i < 60; ++i) world.step();
    const double acceleration = (world.circles()[0].velocity.dot(down) - v0) / (world.time() - t0);
    CHECK(world.stats().autoSolverSteps == 90);
    CHECK(acceleration == Approx(2.0 / 3.0 * 9.81 * std::sin(theta)).epsilon(0.01));
}

TEST_CASE("auto: no tunnelling of a 0.05 m ball at 5 to 5000 m/s, through a line or into a pile", "[auto][tunnel]") {
    for (int k = 0; k <= 30; ++k) {
        const double speed = 5.0 * std::pow(1000.0, k / 30.0);
        INFO("speed " << speed << " m/s");
        World wall(defWith(Method::automatic));
        wall.addSegment(line({1, -1e5}, {1, 1e5}));
        wall.addCircle(ball({0, 0}, Vec2::fromAngle(0.35) * speed, 0.05));
        for (int step = 0; step < 60; ++step) {
            wall.step();
            REQUIRE(wall.circles()[0].position.x <= 0.95 + 1e-9);
        }
        // The same bullet fired at the wall of a box holding a pile: the solver's steps, swept.
        World crowded(defWith(Method::automatic));
        addPile(crowded, 8, 20);
        crowded.addSegment(line({3, -1e5}, {3, 1e5}));
        const int bullet = crowded.slot(crowded.addCircle(ball({2, 5}, Vec2::fromAngle(0.35) * speed, 0.05)));
        for (int step = 0; step < 30; ++step) {
            crowded.step();
            REQUIRE(crowded.circles()[static_cast<std::size_t>(bullet)].position.x <= 2.95 + 1e-6);
        }
        CHECK(crowded.stats().autoSolverSteps == 30);
    }
}
