// Bodies a joint joins do not collide with each other (Box2D's collideConnected = false), unless the
// joint says they do (issue 21): two overlapping bodies (circles, boxes, or one of each) on a weld, a
// revolute, a spring or a prismatic, with no gravity and the joint satisfied, feel no contact and
// hold still to the bit; with collideConnected their contact pushes them apart.
#include "joint_test_world.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace rube;
using test::bar;
using test::jointAt;
using test::jointWorld;
using test::wheel;

namespace {

struct Pushed {
    double moved = 0.0; ///< the largest change of the centres' distance, m
    double speed = 0.0; ///< the largest speed either reached, m/s
    int impacts = 0;
};

JointEnd body(World& world, bool circle, Vec2 at) {
    return circle ? wheel(world, at, 0.5, 1.0) : bar(world, at, {0.5, 0.5}, 1.0);
}

Vec2 centre(const World& world, JointEnd e) {
    return e.circle.isNull() ? world.body(e.body).position : world.circle(e.circle).position;
}

Vec2 velocity(const World& world, JointEnd e) {
    return e.circle.isNull() ? world.body(e.body).velocity : world.circle(e.circle).velocity;
}

// Two bodies of size 1 m, centres `gap` apart along x (overlapping by 1 - gap), joined at the
// midpoint by `kind`; 60 steps of the solver without gravity.
Pushed run(JointKind kind, bool circleA, bool circleB, bool collide, double gap) {
    World world = jointWorld({0.0, 0.0}, Method::solver);
    const JointEnd a = body(world, circleA, {0.0, 0.0}), b = body(world, circleB, {gap, 0.0});
    const Vec2 middle{gap / 2.0, 0.0};
    JointDef d = kind == JointKind::spring ? jointAt(world, kind, a, {0.0, 0.0}, b, {gap, 0.0})
                                           : jointAt(world, kind, a, middle, b, middle);
    d.restLength = gap; // the spring at rest
    d.stiffness = 50.0;
    d.collideConnected = collide;
    world.addJoint(d);
    Pushed out;
    for (int n = 0; n < 60; ++n) {
        world.step();
        out.moved = std::max(out.moved, std::abs(centre(world, b).distance(centre(world, a)) - gap));
        out.speed = std::max({out.speed, velocity(world, a).length(), velocity(world, b).length()});
        out.impacts += static_cast<int>(world.lastImpacts().size());
    }
    return out;
}

} // namespace

TEST_CASE("joints: bodies a joint joins do not collide, unless collideConnected", "[joints][collide]") {
    for (const JointKind kind : {JointKind::weld, JointKind::revolute, JointKind::spring, JointKind::prismatic})
        for (const auto& [circleA, circleB] : {std::pair{true, true}, std::pair{false, false}, std::pair{true, false}})
            for (const double gap : {0.3, 0.6, 0.95}) {
                const Pushed apart = run(kind, circleA, circleB, false, gap);
                const Pushed collide = run(kind, circleA, circleB, true, gap);
                INFO("kind " << static_cast<int>(kind) << " circles " << circleA << circleB << " gap " << gap
                             << ": without moved " << apart.moved << " speed " << apart.speed << "; with moved "
                             << collide.moved << " speed " << collide.speed);
                // Not colliding: nothing acts on them, the joint is satisfied, they hold still.
                CHECK(apart.moved == 0.0);
                CHECK(apart.speed == 0.0);
                CHECK(apart.impacts == 0);
                // Colliding: the contact pushes them apart (the soft step's push-out may leave no speed
                // at the step's end), the joint (but the prismatic's slide) holding them back.
                CHECK(std::max(collide.moved, collide.speed) > 1e-3);
                if (kind == JointKind::prismatic || kind == JointKind::spring) CHECK(collide.moved > 1e-3);
            }
}

TEST_CASE("joints: a spring's two balls pass through each other unless collideConnected", "[joints][collide]") {
    // Released 1.5 m apart on a spring of rest length 0: they meet in the middle. Not colliding, they
    // pass to the other side (the spring's 2-D closed form crosses at t = pi / (2 omega));
    // colliding, they bounce off at a distance of about their diameter.
    for (const bool collide : {false, true}) {
        World world = jointWorld({0.0, 0.0}, Method::solver);
        const JointEnd a = wheel(world, {0.0, 0.0}, 0.25, 1.0), b = wheel(world, {1.5, 0.0}, 0.25, 1.0);
        JointDef d = jointAt(world, JointKind::spring, a, {0.0, 0.0}, b, {1.5, 0.0});
        d.restLength = 0.0;
        d.stiffness = 20.0;
        d.collideConnected = collide;
        world.addJoint(d);
        double closest = 1.5;
        bool crossed = false;
        for (int n = 0; n < 120; ++n) {
            world.step();
            const Vec2 pa = world.circle(a.circle).position, pb = world.circle(b.circle).position;
            closest = std::min(closest, pa.distance(pb));
            crossed = crossed || pb.x < pa.x;
        }
        INFO("collide " << collide << ": closest " << closest);
        CHECK(crossed == !collide);
        if (collide) CHECK(closest > 0.45);
        else CHECK(closest < 0.1);
    }
}
