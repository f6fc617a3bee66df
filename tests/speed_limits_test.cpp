// Speed limits and isolation (issue 27): under solver and auto a rigid body never moves more than
// WorldDef::maxTranslation nor turns more than maxRotation in a step, each cut is counted, and a
// body whose state goes non-finite is frozen where it last was finite without touching the others.
#include "rube/physics/world.hpp"
#include "scene_builders.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace rube;

namespace {

RigidBodyDef capsule(Vec2 position, double omega, Vec2 velocity = {}) {
    RigidBodyDef d;
    d.shape = BodyShape::capsule;
    d.position = position;
    d.halfExtents = {0.3, 0.1};
    d.angularVelocity = omega;
    d.velocity = velocity;
    return d;
}

} // namespace

TEST_CASE("limits: a turning body's spin and speed are cut to maxRotation and maxTranslation a step, and counted",
          "[limits][robustness]") {
    for (const Method method : {Method::solver, Method::automatic}) {
        for (const double dt : {1.0 / 240, 1.0 / 60, 0.05}) {
            for (const double excess : {1.5, 10.0, 1e6}) {
                INFO(methodName(method) << ", dt " << dt << ", excess x" << excess);
                WorldDef def;
                def.method = method;
                def.timeStep = dt;
                def.gravity = {};
                World world(def);
                const double spin = excess * def.maxRotation / dt, speed = excess * def.maxTranslation / dt;
                world.addBody(capsule({0.0, 0.0}, spin, {speed, 0.0}));
                const double angle0 = world.bodies()[0].angle;
                world.step();
                const RigidBody& b = world.bodies()[0];
                // In free flight the cut speeds are kept: exactly the limits (to round-off), and the
                // step turned and moved the body by exactly maxRotation and maxTranslation.
                CHECK(std::abs(b.angularVelocity) == Approx(def.maxRotation / dt).epsilon(1e-12));
                CHECK(b.velocity.length() == Approx(def.maxTranslation / dt).epsilon(1e-12));
                CHECK(std::abs(b.angle - angle0) == Approx(def.maxRotation).epsilon(1e-9));
                CHECK(b.position.x == Approx(def.maxTranslation).epsilon(1e-9));
                CHECK(world.stats().speedClamps >= 1);
            }
        }
    }
}

TEST_CASE("limits: speeds under the limits are left alone and never counted", "[limits][robustness]") {
    for (const double fraction : {0.0, 0.5, 0.99}) {
        WorldDef def;
        def.method = Method::solver;
        def.gravity = {};
        World world(def);
        world.addBody(capsule({0.0, 0.0}, fraction * def.maxRotation / def.timeStep,
                              {fraction * def.maxTranslation / def.timeStep, 0.0}));
        const double omega = world.bodies()[0].angularVelocity;
        for (int i = 0; i < 10; ++i) world.step();
        CHECK(world.bodies()[0].angularVelocity == omega);
        CHECK(world.stats().speedClamps == 0);
    }
}

TEST_CASE("limits: a body that goes non-finite is frozen where it was and never reaches the others",
          "[limits][robustness]") {
    // The case: an unstable capsule beside a ball resting on the floor, another ball 6 m away.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (const double bad : {nan, inf, -inf}) {
        for (const Method method : {Method::solver, Method::automatic}) {
            INFO(methodName(method) << ", injected " << bad);
            WorldDef def;
            def.method = method;
            World world(def);
            world.addSegment(test::line({-10.0, 0.0}, {10.0, 0.0}));
            const int cap = world.slot(world.addBody(capsule({0.0, 0.1}, 0.0)));
            const int near = world.slot(world.addCircle(test::ball({0.9, 0.5}, {}, 0.5)));
            const int far = world.slot(world.addCircle(test::ball({6.0, 0.5}, {}, 0.5)));
            for (int i = 0; i < 30; ++i) world.step();
            const Vec2 rest = world.bodies()[static_cast<std::size_t>(cap)].position;
            world.setAngularVelocity(world.bodyId(cap), bad);
            world.setVelocity(world.bodyId(cap), {bad, 1.0});
            for (int i = 0; i < 120; ++i) world.step();
            const RigidBody& frozen = world.bodies()[static_cast<std::size_t>(cap)];
            CHECK(frozen.position == rest);
            CHECK(frozen.velocity == Vec2{});
            CHECK(frozen.angularVelocity == 0.0);
            CHECK(frozen.motion == Motion::fixed);
            CHECK(world.stats().isolatedBodies == 1);
            CHECK(world.stats().firstIsolatedKind == Other::body);
            CHECK(world.stats().firstIsolatedBody == world.bodyId(cap));
            CHECK(world.stats().nonFinite);
            for (const int i : {near, far}) {
                const Circle& c = world.circles()[static_cast<std::size_t>(i)];
                CHECK(isFinite(c.position));
                CHECK(c.velocity.length() < 1.0); // resting, not flung (the ball reached 3.8e22 m/s)
            }
        }
    }
}

TEST_CASE("limits: the exact method's blocks and circles are never clamped", "[limits][robustness]") {
    // Only solver and auto cut speeds: the exact method resolves any speed by its time of impact.
    WorldDef def;
    def.method = Method::exact;
    def.gravity = {};
    World world(def);
    RigidBodyDef block;
    block.fixedRotation = true;
    block.velocity = {1e4, 0.0};
    world.addBody(block);
    world.addCircle(test::ball({0.0, 5.0}, {1e5, 0.0}, 0.5));
    world.step();
    CHECK(world.bodies()[0].velocity.x == 1e4);
    CHECK(world.circles()[0].velocity.x == 1e5);
    CHECK(world.stats().speedClamps == 0);
}
