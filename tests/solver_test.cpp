// The `solver` method through the public World API: the 1000-ball pile, bullets against thin and
// moving shapes, resting stacks, momentum, restitution, impact records and determinism.
#include "rube/physics/collision.hpp"
#include "rube/physics/world.hpp"
#include "scene_builders.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace rube;
using rube::test::line;

namespace {

WorldDef solverDef() {
    WorldDef def;
    def.method = Method::solver;
    return def;
}

/// A static line from a to b (radius 0, default material).
/// The largest overlap between any two circles and between any circle and segment.
double largestOverlap(const World& world) {
    const auto circles = world.circles();
    double worst = 0.0;
    for (std::size_t i = 0; i < circles.size(); ++i) {
        for (std::size_t j = i + 1; j < circles.size(); ++j) {
            const double reach = circles[i].radius + circles[j].radius;
            const double d2 = (circles[i].position - circles[j].position).lengthSquared();
            if (d2 < reach * reach) worst = std::max(worst, reach - std::sqrt(d2));
        }
        for (const Segment& s : world.segments())
            worst = std::max(worst,
                             circles[i].radius + s.radius -
                                 circles[i].position.distance(closestPointOnSegment(circles[i].position, s.a, s.b)));
    }
    return worst;
}

double fastestSpeed(const World& world) {
    double v = 0.0;
    for (const Circle& c : world.circles()) v = std::max(v, c.velocity.length());
    return v;
}

/// The acceptance pile: 1000 balls of radius 0.1 m dropped from a loose grid into a 5 m x 20 m box.
World makePile() {
    WorldDef def = solverDef();
    def.bounds = Aabb{{-2.6, -0.5}, {2.6, 20.5}};
    World world(def);
    world.addSegment(line({-2.5, 0.0}, {2.5, 0.0}));
    world.addSegment(line({-2.5, 0.0}, {-2.5, 20.0}));
    world.addSegment(line({2.5, 0.0}, {2.5, 20.0}));
    for (int i = 0; i < 1000; ++i) {
        CircleDef c;
        c.radius = 0.1;
        c.mass = 1.0;
        // 20 columns, 50 rows; a small deterministic sideways jitter so the columns do not stand.
        c.position = {-2.28 + (i % 20) * 0.24 + ((i * 7919) % 13 - 6) * 0.003, 8.0 + (i / 20) * 0.24};
        c.material.bounciness = 0.1 + 0.2 * ((i * 37) % 11) / 10.0;
        world.addCircle(c);
    }
    return world;
}

/// A ball of radius 0.5 dropped from centre height `height` onto a floor line, no sideways motion.
World makeDrop(double height, double bounciness) {
    World world(solverDef());
    world.addSegment(line({-20.0, 0.0}, {20.0, 0.0}));
    CircleDef c;
    c.position = {0.0, height};
    c.material.bounciness = bounciness;
    world.addCircle(c);
    return world;
}

} // namespace

TEST_CASE("the 1000-ball pile settles with at most 5 mm overlap and no escapes", "[solver][pile]") {
    World world = makePile();
    double worst = 0.0;
    for (int step = 0; step < 600; ++step) {
        world.step();
        if (step >= 540) worst = std::max(worst, largestOverlap(world)); // the last simulated second
    }
    INFO("largest overlap in the last second: " << worst << " m");
    CHECK(worst <= 0.005);
    CHECK(world.stats().escapes == 0);
    CHECK_FALSE(world.stats().nonFinite);
    CHECK(fastestSpeed(world) < 0.01); // settled
    for (const Circle& c : world.circles()) {
        REQUIRE(std::fabs(c.position.x) <= 2.5 - 0.1 + 0.005);
        REQUIRE(c.position.y >= 0.1 - 0.005);
    }
}

TEST_CASE("pile timing (median ms per step)", "[.bench][solver]") {
    World world = makePile();
    std::vector<double> ms;
    for (int step = 0; step < 600; ++step) {
        const auto t0 = std::chrono::steady_clock::now();
        world.step();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(ms.begin(), ms.end());
    std::printf("solver pile: median %.3f ms/step, p90 %.3f ms/step\n", ms[ms.size() / 2], ms[ms.size() * 9 / 10]);
    CHECK(world.stats().escapes == 0);
}

TEST_CASE("a 0.05 m bullet never tunnels through a thin static line", "[solver][continuous]") {
    const double speed = GENERATE(5.0, 17.0, 50.0, 500.0, 1234.5, 5000.0);
    const Vec2 direction = GENERATE(Vec2{1.0, 0.0}, Vec2{1.0, 0.7}, Vec2{1.0, -3.0});
    World world(solverDef());
    world.addSegment(line({0.0, -50.0}, {0.0, 50.0})); // radius 0: the lecture's line
    CircleDef c;
    c.radius = 0.05;
    c.position = {-1.0, 0.0};
    c.velocity = direction.normalized() * speed;
    world.addCircle(c);
    INFO("speed " << speed << " m/s, direction (" << direction.x << ", " << direction.y << ")");
    for (int step = 0; step < 120; ++step) {
        world.step();
        REQUIRE(world.circles()[0].position.x < -0.05 + 1e-3); // on its starting side, not inside the line
    }
    CHECK(world.stats().impacts >= 1);
    CHECK(world.circles()[0].velocity.x < 0.0); // it bounced back
}

TEST_CASE("a 0.05 m bullet never tunnels through a 2 cm segment moving towards it", "[solver][continuous]") {
    const double speed = GENERATE(5.0, 17.0, 50.0, 500.0, 1234.5, 5000.0);
    const Vec2 direction = GENERATE(Vec2{1.0, 0.0}, Vec2{1.0, 0.7}, Vec2{1.0, -3.0});
    World world(solverDef());
    KinematicPath path;
    path.keys = {{0.0, {0.0, 0.0}}, {10.0, {-20.0, 0.0}}}; // 2 m/s towards the ball
    SegmentDef wall;
    wall.a = {0.0, -50.0};
    wall.b = {0.0, 50.0};
    wall.radius = 0.01;
    wall.path = world.addPath(path);
    world.addSegment(wall);
    CircleDef c;
    c.radius = 0.05;
    c.position = {-1.0, 0.0};
    c.velocity = direction.normalized() * speed;
    world.addCircle(c);
    INFO("speed " << speed << " m/s, direction (" << direction.x << ", " << direction.y << ")");
    for (int step = 0; step < 120; ++step) {
        world.step();
        const double wallX = world.segments()[0].a.x;
        REQUIRE(world.circles()[0].position.x < wallX - 0.06 + 1e-3);
    }
    CHECK(world.stats().impacts >= 1);
}

TEST_CASE("a stack of balls at rest stays at rest without sinking", "[solver][resting]") {
    World world(solverDef());
    world.addSegment(line({-5.0, 0.0}, {5.0, 0.0}));
    for (int i = 0; i < 10; ++i) {
        CircleDef c;
        c.radius = 0.5;
        c.position = {0.0, 0.5 + i * 1.0}; // touching, straight up
        c.material.bounciness = 0.5;
        world.addCircle(c);
    }
    for (int step = 0; step < 300; ++step) world.step();
    for (int i = 0; i < 10; ++i) {
        const Circle& c = world.circles()[i];
        INFO("ball " << i);
        CHECK(std::fabs(c.position.y - (0.5 + i * 1.0)) < 0.005);
        CHECK(c.position.x == 0.0);
        CHECK(c.velocity.length() < 0.01);
    }
    CHECK(largestOverlap(world) < 0.005);
    CHECK(world.stats().impacts == 0); // resting from the start: nothing fast enough to count as an impact
}

TEST_CASE("a free collision of two balls conserves momentum (and energy when C = 1)", "[solver][momentum]") {
    const double bounciness = GENERATE(1.0, 0.5, 0.0);
    WorldDef def = solverDef();
    def.gravity = {0.0, 0.0};
    World world(def);
    CircleDef a;
    a.position = {-1.0, 0.0};
    a.velocity = {4.0, 0.0};
    a.radius = 0.3;
    a.mass = 1.0;
    a.material.bounciness = bounciness;
    CircleDef b = a;
    b.position = {1.0, 0.25}; // off-centre: an oblique hit
    b.velocity = {-1.0, 0.0};
    b.radius = 0.4;
    b.mass = 3.0;
    world.addCircle(a);
    world.addCircle(b);
    const auto momentum = [&] {
        const auto cs = world.circles();
        return cs[0].velocity * a.mass + cs[1].velocity * b.mass;
    };
    const auto energy = [&] {
        const auto cs = world.circles();
        return 0.5 * a.mass * cs[0].velocity.lengthSquared() + 0.5 * b.mass * cs[1].velocity.lengthSquared();
    };
    const Vec2 p0 = momentum();
    const double e0 = energy();
    for (int step = 0; step < 120; ++step) {
        world.step();
        REQUIRE(world.circles()[0].position.distance(world.circles()[1].position) > 0.7 - 0.005);
    }
    INFO("C = " << bounciness);
    CHECK(world.stats().impacts == 1);
    CHECK(world.circles()[1].velocity.x > -1.0 + 0.1); // the collision happened
    CHECK(approxEqual(momentum(), p0, 1e-12));
    if (bounciness == 1.0) CHECK(energy() == Approx(e0).epsilon(1e-9));
    else CHECK(energy() < e0);
}

TEST_CASE("balls do not pass through each other", "[solver][continuous]") {
    SECTION("a fast ball hits a resting one") {
        const double speed = GENERATE(20.0, 200.0, 2000.0);
        WorldDef def = solverDef();
        def.gravity = {0.0, 0.0};
        World world(def);
        CircleDef a;
        a.radius = 0.05;
        a.position = {-1.0, 0.0};
        a.velocity = {speed, 0.0};
        world.addCircle(a);
        CircleDef b = a;
        b.position = {0.0, 0.02};
        b.velocity = {};
        world.addCircle(b);
        INFO("speed " << speed << " m/s");
        for (int step = 0; step < 30; ++step) {
            world.step();
            REQUIRE(largestOverlap(world) < 1e-3);
        }
        CHECK(world.circles()[0].position.x < world.circles()[1].position.x); // still in order
        CHECK(world.circles()[1].velocity.x > 0.5 * speed);                   // it was hit
    }
    SECTION("a struck row of balls against a wall") {
        const double speed = GENERATE(10.0, 30.0, 100.0);
        const double gap = GENERATE(0.0, 0.03);
        World world(solverDef());
        world.addSegment(line({-10.0, 0.0}, {10.0, 0.0}));
        world.addSegment(line({3.0, 0.0}, {3.0, 3.0}));
        for (int i = 0; i < 10; ++i) {
            CircleDef c;
            c.radius = 0.1;
            c.position = {2.9 - gap - i * (0.2 + gap), 0.1};
            c.material.bounciness = 0.5;
            world.addCircle(c);
        }
        CircleDef striker;
        striker.radius = 0.1;
        striker.position = {-2.0, 0.1};
        striker.velocity = {speed, 0.0};
        striker.material.bounciness = 0.5;
        world.addCircle(striker);
        INFO("speed " << speed << " m/s, gap " << gap << " m");
        double worst = 0.0;
        for (int step = 0; step < 120; ++step) {
            world.step();
            worst = std::max(worst, largestOverlap(world));
            for (const Circle& c : world.circles()) REQUIRE(c.position.x < 3.0); // none through the wall
        }
        CHECK(worst < 0.025);                                    // a quarter radius at 100 m/s: squeezed, never through
        for (std::size_t i = 1; i < world.circles().size(); ++i) // the row keeps its order
            CHECK(world.circles()[i].position.x < world.circles()[i - 1].position.x);
    }
}

TEST_CASE("restitution: C = 0 stops on the floor, C = 1 bounces back to the same height", "[solver][restitution]") {
    SECTION("C = 0 lands and stays") {
        World world = makeDrop(10.0, 0.0);
        bool landed = false;
        for (int step = 0; step < 300; ++step) {
            world.step();
            const double y = world.circles()[0].position.y;
            if (y < 0.51) landed = true;
            if (landed) REQUIRE(y < 0.5 + 1e-3);
        }
        CHECK(landed);
        CHECK(world.circles()[0].position.y == Approx(0.5).margin(1e-3));
        CHECK(world.circles()[0].velocity.length() < 1e-3);
        CHECK(world.stats().impacts == 1);
        CHECK(world.stats().restingContacts > 0);
    }
    SECTION("C = 1 keeps every apex within 0.5 % of 10 m for 20 s") {
        World world = makeDrop(10.0, 1.0);
        double previous = 10.0, beforePrevious = 10.0;
        int apexes = 0;
        for (int step = 0; step < 1200; ++step) {
            world.step();
            const double y = world.circles()[0].position.y;
            if (step > 1 && previous > y && previous >= beforePrevious) {
                ++apexes;
                INFO("apex " << apexes << " at " << previous << " m");
                CHECK(previous == Approx(10.0).epsilon(0.005));
            }
            beforePrevious = previous;
            previous = y;
        }
        CHECK(apexes == 7);
    }
}

TEST_CASE("an impact is recorded with its time, point, normal and approach speed", "[solver][impacts]") {
    World world = makeDrop(10.0, 0.5);
    std::vector<Impact> impacts;
    for (int step = 0; step < 100 && impacts.empty(); ++step) {
        world.step();
        impacts.assign(world.lastImpacts().begin(), world.lastImpacts().end());
    }
    REQUIRE(impacts.size() == 1);
    const Impact& hit = impacts[0];
    const double fallTime = std::sqrt(2.0 * 9.5 / 9.81); // free fall of 9.5 m to the touching height
    CHECK(hit.circle == 0);
    CHECK(hit.otherKind == Other::segment);
    CHECK(hit.other == 0);
    CHECK(hit.time == Approx(fallTime).margin(1.0 / 60));
    CHECK(approxEqual(hit.pointOfImpact, {0.0, 0.0}, 1e-3));
    CHECK(approxEqual(hit.normal, {0.0, 1.0}, 1e-12));
    CHECK(hit.approachSpeed == Approx(9.81 * fallTime).epsilon(0.01));
    CHECK(world.stats().impacts == 1);
    // Bounced at its time of impact (v' = C u, lecture 3), then falling for the rest of the step.
    CHECK(world.circles()[0].velocity.y ==
          Approx(0.5 * hit.approachSpeed - 9.81 * (world.time() - hit.time)).epsilon(0.01));
}

TEST_CASE("large and long shapes are found by the grid", "[solver][broadphase]") {
    SECTION("a big ball lands on a bed of small ones without sinking into it") {
        World world(solverDef());
        world.addSegment(line({-2.0, 0.0}, {2.0, 0.0}));
        world.addSegment(line({-2.0, 0.0}, {-2.0, 6.0}));
        world.addSegment(line({2.0, 0.0}, {2.0, 6.0}));
        for (int i = 0; i < 40; ++i) {
            CircleDef small;
            small.radius = 0.1;
            small.position = {-1.9 + (i % 20) * 0.2, 0.1 + (i / 20) * 0.18};
            world.addCircle(small);
        }
        CircleDef big;
        big.radius = 1.0;
        big.mass = 20.0;
        big.position = {0.05, 4.0};
        world.addCircle(big);
        for (int step = 0; step < 240; ++step) world.step();
        CHECK(largestOverlap(world) < 0.005);
        CHECK(world.circles()[40].position.y > 0.2 + 1.0);
    }
    SECTION("a ball slides down a 140 m long diagonal line without falling through") {
        World world(solverDef());
        world.addSegment(line({-50.0, 50.0}, {50.0, -50.0}));
        CircleDef c;
        c.radius = 0.2;
        c.position = {10.0, -9.0};
        world.addCircle(c);
        const Vec2 normal = Vec2{100.0, -100.0}.normal(); // the line's upper side
        for (int step = 0; step < 240; ++step) {
            world.step();
            REQUIRE((world.circles()[0].position - Vec2{0.0, 0.0}).dot(normal) > 0.2 - 0.005);
        }
        CHECK(world.circles()[0].position.x > 12.0); // it slid down and to the right
    }
}

TEST_CASE("the solver is deterministic: the same scene twice gives the same state hash", "[solver][determinism]") {
    const auto run = [] {
        WorldDef def = solverDef();
        World world(def);
        world.addSegment(line({-3.0, 0.0}, {3.0, 0.0}));
        world.addSegment(line({-3.0, 0.0}, {-3.0, 8.0}));
        world.addSegment(line({3.0, 0.0}, {3.0, 8.0}));
        KinematicPath sweep;
        sweep.keys = {{0.0, {0.0, 0.0}}, {1.0, {2.0, 0.0}}, {2.0, {0.0, 0.0}}};
        sweep.loop = true;
        SegmentDef paddle;
        paddle.a = {-2.0, 1.0};
        paddle.b = {-1.0, 2.0};
        paddle.radius = 0.05;
        paddle.path = world.addPath(sweep);
        world.addSegment(paddle);
        for (int i = 0; i < 200; ++i) {
            CircleDef c;
            c.radius = 0.08 + 0.04 * (i % 3);
            c.mass = 0.5 + 0.25 * (i % 4);
            c.position = {-2.6 + (i % 18) * 0.3, 3.0 + (i / 18) * 0.35};
            c.velocity = {((i * 31) % 7 - 3) * 0.5, 0.0};
            c.material.bounciness = 0.2 * (i % 5);
            world.addCircle(c);
        }
        for (int step = 0; step < 180; ++step) world.step();
        return std::pair{stateHash(world), world.stats().impacts};
    };
    const auto first = run();
    const auto second = run();
    CHECK(first.first == second.first);
    CHECK(first.second == second.second);
    CHECK(first.second > 0);
}
