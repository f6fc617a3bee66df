// Lecture 3's blocks (fixed-rotation boxes): the point of impact of a block moving into a block
// (Assignment 3.3), Newton's v' = u - C (v - u) on the axis of impact only, resting stacks, and where
// each time-step method tunnels. Analytic answers against their formulas.
#include "rube/physics/block_collision.hpp"
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

// A dynamic block (box with fixed rotation) of `mass` kg.
RigidBodyDef block(Vec2 position, Vec2 velocity, Vec2 half, double mass = 1.0, double bounciness = 1.0) {
    RigidBodyDef def;
    def.shape = BodyShape::box;
    def.fixedRotation = true;
    def.position = position;
    def.velocity = velocity;
    def.halfExtents = half;
    def.mass = mass;
    def.material.bounciness = bounciness;
    return def;
}

WorldDef worldDef(Method method, Vec2 gravity = {0.0, -kG}) {
    WorldDef def;
    def.method = method;
    def.gravity = gravity;
    return def;
}

// Kinetic energy m v^2 / 2 of every dynamic block and circle.
double kineticEnergy(const World& world) {
    double e = 0.0;
    for (const RigidBody& b : world.bodies())
        if (b.inverseMass > 0.0) e += 0.5 * b.velocity.lengthSquared() / b.inverseMass;
    for (const Circle& c : world.circles())
        if (c.inverseMass > 0.0) e += 0.5 * c.velocity.lengthSquared() / c.inverseMass;
    return e;
}

Vec2 momentum(const World& world) {
    Vec2 p;
    for (const RigidBody& b : world.bodies())
        if (b.inverseMass > 0.0) p += b.velocity / b.inverseMass;
    for (const Circle& c : world.circles())
        if (c.inverseMass > 0.0) p += c.velocity / c.inverseMass;
    return p;
}

} // namespace

TEST_CASE("blocks: a block moving diagonally into a block hits at t = a / b with the point of impact on the face",
          "[blocks][lecture3]") {
    // Block 1 (1 m square at the origin) moves (4, 2) in one unit of time towards block 2 at (3, 1.5).
    // Assignment 3.3: the distance from its right side to the other's left side is a = 3 - 1 = 2 before
    // and 2 - 4 = -2 after the move, so t = a / (a - after) = 2 / 4 = 0.5; y already overlaps then.
    const BlockMotion moving{{0.0, 0.0}, {4.0, 2.0}, {0.5, 0.5}};
    const auto hit = blockBlockCollision(moving, {3.0, 1.5}, {0.5, 0.5}, 1.0);
    REQUIRE(hit);
    CHECK(hit->timeOfImpact == 0.5);
    CHECK(hit->pointOfImpact == Vec2{2.0, 1.0}); // POI = old position + t velocity
    CHECK(hit->normal == Vec2{-1.0, 0.0});
    // On block 2's left face x = 2.5, in the middle of the shared span y in [1, 1.5].
    CHECK(hit->contactPoint == Vec2{2.5, 1.25});

    // Higher up, x closes first (t = 0.5) while y does not overlap yet: the impact is on the bottom
    // face when y closes, t = (2.2 - 1) / 2 = 0.6.
    const auto under = blockBlockCollision(moving, {3.0, 2.2}, {0.5, 0.5}, 1.0);
    REQUIRE(under);
    CHECK(under->timeOfImpact == Approx(0.6).epsilon(1e-15));
    CHECK(under->normal == Vec2{0.0, -1.0});
    CHECK(approxEqual(under->pointOfImpact, Vec2{2.4, 1.2}, 1e-15));

    // Higher still they pass corner by corner: no impact in the step.
    CHECK_FALSE(blockBlockCollision(moving, {3.0, 3.0}, {0.5, 0.5}, 1.0));
}

TEST_CASE("blocks: a block against a circle hits the face offset by r, or the corner's circle", "[blocks][lecture3]") {
    // Face: the block's right face (x = 0.5) meets a ball of r = 0.25 at x = 2 when the block has moved 1.25.
    const auto face = blockCircleCollision({{0.0, 0.0}, {2.5, 0.0}, {0.5, 0.5}}, {2.0, 0.3}, 0.25, 1.0);
    REQUIRE(face);
    CHECK(face->timeOfImpact == 0.5);
    CHECK(face->normal == Vec2{-1.0, 0.0});
    CHECK_FALSE(face->lineCap);
    // Corner: the ball sits on the line through the corner at 45 degrees; the corner (0.5, 0.5) moving
    // along +x meets the circle of r = 0.25 around (2, 0.5 + 0.25 / sqrt 2) where the distance in x is
    // sqrt(r^2 - (r / sqrt 2)^2) = r / sqrt 2.
    const double d = 0.25 / std::sqrt(2.0);
    const auto corner = blockCircleCollision({{0.0, 0.0}, {1.0, 0.0}, {0.5, 0.5}}, {2.0, 0.5 + d}, 0.25, 2.0);
    REQUIRE(corner);
    CHECK(corner->lineCap);
    CHECK(corner->timeOfImpact == Approx(1.5 - d).epsilon(1e-14));
    CHECK(approxEqual(corner->normal, Vec2{-1.0, -1.0}.normalized(), 1e-12));
}

TEST_CASE("blocks: a block against a ramp touches with its lowest corner, against a floor with its side",
          "[blocks][lecture3]") {
    // A 45-degree ramp through the origin; the block's corner (-0.5, -0.5) leads. Its reach along the
    // normal (-1, 1)/sqrt 2 is (0.5 + 0.5)/sqrt 2, the centre starts at distance 3 / sqrt 2 (at (0, 3)).
    const auto ramp = blockSegmentCollision({{0.0, 3.0}, {0.0, -1.0}, {0.5, 0.5}}, {-5.0, -5.0}, {5.0, 5.0}, 0.0, 5.0);
    REQUIRE(ramp);
    // Distance 3/sqrt 2 closing at 1/sqrt 2 per second, reach 1/sqrt 2: t = (3 - 1) = 2.
    CHECK(ramp->timeOfImpact == Approx(2.0).epsilon(1e-14));
    CHECK(approxEqual(ramp->normal, Vec2{-1.0, 1.0}.normalized(), 1e-15));
    CHECK(approxEqual(ramp->contactPoint, Vec2{0.5, 0.5}, 1e-14)); // the block's corner (0.5, 0.5) then
    // A floor: the block's underside, normal +y, at t = (2 - 0.5) / 3.
    const auto floor = blockSegmentCollision({{1.0, 2.0}, {0.0, -3.0}, {0.5, 0.5}}, {-5.0, 0.0}, {5.0, 0.0}, 0.0, 1.0);
    REQUIRE(floor);
    CHECK(floor->timeOfImpact == 0.5);
    CHECK(floor->normal == Vec2{0.0, 1.0});
    // Past the floor's end, its line cap catches the block's corner region: the block's side at x = 5.
    const auto cap = blockSegmentCollision({{7.0, 0.0}, {-4.0, 0.0}, {0.5, 0.5}}, {-5.0, 0.0}, {5.0, 0.0}, 0.0, 1.0);
    REQUIRE(cap);
    CHECK(cap->lineCap);
    CHECK(cap->timeOfImpact == 0.375);
    CHECK(cap->normal == Vec2{1.0, 0.0});
}

TEST_CASE("blocks: a block dropped on a floor rebounds at C v and climbs to C^2 h under exact", "[blocks][exact]") {
    for (const double c : {1.0, 0.8, 0.5}) {
        INFO("C = " << c);
        World world(worldDef(Method::exact));
        world.addSegment(line({-10, 0}, {10, 0}));
        const double h = 10.0; // the block's underside starts 10 m above the floor
        world.addBody(block({0.0, h + 0.5}, {}, {0.5, 0.5}, 1.0, c));
        while (world.lastImpacts().empty()) world.step();
        const Impact impact = world.lastImpacts().front();
        const double v = std::sqrt(2.0 * kG * h);
        CHECK(impact.body == 0);
        CHECK(impact.circle == -1);
        CHECK(impact.otherKind == Other::segment);
        CHECK(impact.time == Approx(std::sqrt(2.0 * h / kG)).epsilon(1e-13));
        CHECK(std::fabs(impact.approachSpeed - v) < 1e-9);
        CHECK(impact.normal == Vec2{0.0, 1.0});
        // The motion is exact between impacts: at the step's end, speed and height give the rebound.
        const RigidBody& b = world.bodies()[0];
        const double height = b.position.y - 0.5;
        const double rebound = std::sqrt(b.velocity.y * b.velocity.y + 2.0 * kG * height);
        const double apex = height + b.velocity.y * b.velocity.y / (2.0 * kG);
        CHECK(std::fabs(rebound - c * v) < 1e-9);
        CHECK(std::fabs(apex - c * c * h) < 1e-9);
        // And the highest point it reaches, stepping on: within a step's travel of C^2 h, never above.
        double highest = height;
        for (int step = 0; step < 200; ++step) {
            world.step();
            if (!world.lastImpacts().empty()) break;
            highest = std::max(highest, world.bodies()[0].position.y - 0.5);
        }
        CHECK(highest <= c * c * h + 1e-9);
        CHECK(highest > c * c * h - 0.01);
        CHECK(b.position.x == 0.0);
    }
}

TEST_CASE("blocks: two equal blocks head-on with C = 1 exchange x velocities and keep momentum and energy",
          "[blocks][exact]") {
    for (const Method method : {Method::exact, Method::turnBased, Method::discrete}) {
        INFO(methodName(method));
        World world(worldDef(method, {}));
        // Offset in y (the faces still overlap): only the x components take part (lecture 3).
        world.addBody(block({-2.0, 0.0}, {3.0, 0.5}, {0.5, 0.5}));
        world.addBody(block({2.0, 0.3}, {-1.0, 0.5}, {0.5, 0.5}));
        const Vec2 p0 = momentum(world);
        const double e0 = kineticEnergy(world);
        for (int step = 0; step < 120; ++step) world.step();
        CHECK(world.stats().impacts == 1);
        CHECK(world.bodies()[0].velocity.x == Approx(-1.0).epsilon(1e-12));
        CHECK(world.bodies()[1].velocity.x == Approx(3.0).epsilon(1e-12));
        CHECK(world.bodies()[0].velocity.y == 0.5);
        CHECK(world.bodies()[1].velocity.y == 0.5);
        CHECK((momentum(world) - p0).length() < 1e-12);
        CHECK(std::fabs(kineticEnergy(world) - e0) < 1e-12);
    }
}

TEST_CASE("blocks: with C = 0 both blocks move on at the centre of mass's velocity u", "[blocks][exact]") {
    World world(worldDef(Method::exact, {}));
    world.addBody(block({-2.0, 0.0}, {3.0, 0.0}, {0.5, 0.5}, 1.0, 0.0));
    world.addBody(block({2.0, 0.0}, {-1.0, 0.0}, {0.5, 0.5}, 3.0, 0.0));
    for (int step = 0; step < 120; ++step) world.step();
    const double u = (1.0 * 3.0 + 3.0 * -1.0) / 4.0; // (m1 v1 + m2 v2) / (m1 + m2) = 0
    CHECK(world.bodies()[0].velocity.x == Approx(u).margin(1e-12));
    CHECK(world.bodies()[1].velocity.x == Approx(u).margin(1e-12));
    // Unequal masses, C = 0: u = (1 * 3 + 3 * 1) / 4 = 1.5.
    World chase(worldDef(Method::exact, {}));
    chase.addBody(block({-2.0, 0.0}, {3.0, 0.0}, {0.5, 0.5}, 1.0, 0.0));
    chase.addBody(block({0.0, 0.0}, {1.0, 0.0}, {0.5, 0.5}, 3.0, 0.0));
    for (int step = 0; step < 60; ++step) chase.step();
    CHECK(chase.bodies()[0].velocity.x == Approx(1.5).epsilon(1e-12));
    CHECK(chase.bodies()[1].velocity.x == Approx(1.5).epsilon(1e-12));
}

TEST_CASE("blocks: a ball striking a block keeps the momentum of the pair", "[blocks][exact]") {
    for (const Method method : {Method::exact, Method::turnBased, Method::discrete}) {
        INFO(methodName(method));
        World world(worldDef(method, {}));
        world.addBody(block({0.0, 0.0}, {1.0, 0.0}, {0.5, 0.5}, 1.0, 0.8));
        CircleDef b = ball({3.0, 0.2}, {-4.0, 0.0}, 0.25);
        b.mass = 2.0;
        world.addCircle(b);
        const Vec2 p0 = momentum(world);
        for (int step = 0; step < 60; ++step) world.step();
        REQUIRE(world.stats().impacts >= 1);
        CHECK((momentum(world) - p0).length() < 1e-12);
        // v' = u - C (v - u) along x, u = (1 * 1 + 2 * -4) / 3.
        const double u = -7.0 / 3.0;
        CHECK(world.bodies()[0].velocity.x == Approx(u - 0.8 * (1.0 - u)).epsilon(1e-12));
        CHECK(world.circles()[0].velocity.x == Approx(u - 0.8 * (-4.0 - u)).epsilon(1e-12));
    }
}

TEST_CASE("blocks: a stack of three blocks rests on a floor for 10 s without sinking or drifting", "[blocks][exact]") {
    World world(worldDef(Method::exact));
    world.addSegment(line({-10, 0}, {10, 0}));
    for (int i = 0; i < 3; ++i) world.addBody(block({0.0, 0.5 + i}, {}, {0.5, 0.5}, 1.0 + i, 0.5));
    double worstY = 0.0, worstX = 0.0, fastest = 0.0;
    for (int step = 0; step < 600; ++step) {
        world.step();
        for (int i = 0; i < 3; ++i) {
            const RigidBody& b = world.bodies()[i];
            worstY = std::max(worstY, std::fabs(b.position.y - (0.5 + i)));
            worstX = std::max(worstX, std::fabs(b.position.x));
            fastest = std::max(fastest, b.velocity.length());
        }
    }
    // Measured: 0 in x, 1.1e-16 m in y, speeds 0 at every step's end (g++ 12, x86-64).
    CHECK(worstX == 0.0);
    CHECK(worstY < 1e-12);
    CHECK(fastest < 1e-12);
}

TEST_CASE("blocks: a fast block never tunnels through a thin line under exact and turn-based", "[blocks][tunnel]") {
    const double half = 0.05, dt = 1.0 / 60;
    for (const Method method : {Method::exact, Method::turnBased}) {
        for (const double ratio : {0.5, 2.01, 10.0, 1000.0, 1e4}) { // speed x dt / halfExtent
            INFO(methodName(method) << ", speed x dt / h = " << ratio);
            const double speed = ratio * half / dt;
            int tunnels = 0;
            for (int phase = 0; phase < 100; ++phase) {
                World world(worldDef(method, {}));
                world.addSegment(line({-10, 0}, {10, 0}));
                const double start = half + speed * dt * (phase + 0.5) / 100.0;
                world.addBody(block({0.0, start}, {0.0, -speed}, {half, half}));
                for (int step = 0; step < 3; ++step) world.step();
                if (world.bodies()[0].position.y < 0.0) ++tunnels;
            }
            CHECK(tunnels == 0);
        }
    }
}

TEST_CASE("blocks: discrete tunnels through a thin line above speed x dt = 2 halfExtent, never below",
          "[blocks][tunnel]") {
    const double half = 0.05, dt = 1.0 / 60;
    const auto tunnelShare = [&](double ratio) {
        const double speed = ratio * half / dt;
        int tunnels = 0;
        for (int phase = 0; phase < 1000; ++phase) {
            World world(worldDef(Method::discrete, {}));
            world.addSegment(line({-10, 0}, {10, 0}));
            // Every way the crossing step can fall: the underside starts 0 to one step's travel above.
            const double start = half + speed * dt * (phase + 0.5) / 1000.0;
            world.addBody(block({0.0, start}, {0.0, -speed}, {half, half}));
            for (int step = 0; step < 3; ++step) world.step();
            if (world.bodies()[0].position.y < 0.0) ++tunnels;
        }
        return tunnels / 1000.0;
    };
    for (const double ratio : {0.1, 1.0, 1.9, 1.99, 1.999}) {
        INFO("speed x dt / h = " << ratio);
        CHECK(tunnelShare(ratio) == 0.0);
    }
    // The share that tunnels is (v dt - 2h) / v dt, as for circles with r.
    for (const double ratio : {2.01, 2.1, 3.0, 10.0}) {
        INFO("speed x dt / h = " << ratio);
        CHECK(tunnelShare(ratio) == Approx((ratio - 2.0) / ratio).margin(0.002));
    }
}
