// Joints that hold shapes together, each against its bound at 60 Hz under the solver (issue 21):
// revolute limits, a piston (prismatic) on its axis and at its limit, a welded hammer, and a chain
// of 20 links with a heavy weight.
#include "joint_test_world.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace rube;
using test::bar;
using test::jointAt;
using test::jointWorld;
using test::kPi;

TEST_CASE("joints: a pendulum stopped at +-30 degrees never passes a limit by more than 0.5 degrees",
          "[joints][revolute]") {
    const double limit = 30.0 * kPi / 180.0;
    const double spin = GENERATE(3.0, 8.0, -12.0); // rad/s at the start, hanging straight down
    const BodyShape shape = GENERATE(BodyShape::box, BodyShape::capsule);
    World world = jointWorld();
    // A 1 m bar hanging from the world at its top end.
    const JointEnd pendulum = bar(world, {0.0, -0.5}, {0.5, 0.05}, 1.0, shape, -kPi / 2);
    JointDef d = jointAt(world, JointKind::revolute, JointEnd{}, {0.0, 0.0}, pendulum, {0.0, 0.0});
    d.limits = {true, -limit, limit};
    const JointId j = world.addJoint(d);
    world.setAngularVelocity(pendulum.body, spin);
    world.setVelocity(pendulum.body, {0.5 * spin, 0.0}); // the centre, 0.5 m below the hinge, swings with it
    double worst = 0.0, widest = 0.0;
    for (int s = 0; s < 600; ++s) {
        world.step();
        const double theta = world.jointCoordinate(j);
        worst = std::max(worst, std::abs(theta) - limit);
        widest = std::max(widest, std::abs(theta));
    }
    INFO("spin " << spin << ": passed the limit by " << worst * 180.0 / kPi << " degrees, widest " << widest);
    CHECK(widest > limit - 0.01); // it reached a limit
    CHECK(worst * 180.0 / kPi < 0.5);
}

TEST_CASE("joints: a piston driven at 1 m/s keeps to its axis and stops at its limit", "[joints][prismatic]") {
    const double degrees = GENERATE(0.0, 30.0, 90.0, 135.0);
    const double travel = 2.0;
    World world = jointWorld();
    const Vec2 axis{std::cos(degrees * kPi / 180.0), std::sin(degrees * kPi / 180.0)};
    const JointEnd piston = bar(world, {1.0, 1.0}, {0.3, 0.15}, 2.0, BodyShape::box, degrees * kPi / 180.0);
    JointDef d = jointAt(world, JointKind::prismatic, JointEnd{}, {1.0, 1.0}, piston, {1.0, 1.0});
    d.localAxisA = axis;
    d.motor = {1.0, 200.0};
    d.limits = {true, 0.0, travel};
    const JointId j = world.addJoint(d);
    double offAxis = 0.0, beyond = 0.0;
    for (int s = 0; s < 240; ++s) {
        world.step();
        const Vec2 from = world.body(piston.body).position - Vec2{1.0, 1.0};
        offAxis = std::max(offAxis, std::abs(from.cross(axis)));
        beyond = std::max(beyond, world.jointCoordinate(j) - travel);
        if (s == 59) CHECK(world.body(piston.body).velocity.dot(axis) == Approx(1.0).epsilon(1e-3));
    }
    INFO(degrees << " degrees: off the axis by " << offAxis << " m, beyond the limit by " << beyond << " m");
    CHECK(offAxis < 1e-6);
    CHECK(beyond < 1e-3);
    CHECK(std::abs(world.jointCoordinate(j) - travel) < 1e-3);
    CHECK(std::abs(world.body(piston.body).angle - degrees * kPi / 180.0) < 1e-6);
}

TEST_CASE("joints: a welded hammer swung on a hinge keeps its head within 1 mm of the handle's end", "[joints][weld]") {
    const double headMass = GENERATE(0.5, 2.0, 5.0);
    World world = jointWorld();
    // A 1 m handle from the hinge at the origin, horizontal; the head across its far end.
    const JointEnd handle = bar(world, {0.5, 0.0}, {0.5, 0.03}, 0.3);
    const JointEnd head = bar(world, {1.05, 0.0}, {0.05, 0.15}, headMass);
    world.addJoint(jointAt(world, JointKind::revolute, JointEnd{}, {0.0, 0.0}, handle, {0.0, 0.0}));
    const JointDef weld = jointAt(world, JointKind::weld, handle, {1.0, 0.0}, head, {1.0, 0.0});
    world.addJoint(weld);
    double worst = 0.0, worstAngle = 0.0, lowest = 0.0;
    for (int s = 0; s < 300; ++s) {
        world.step();
        const Vec2 end = world.worldPoint(handle, weld.localAnchorA),
                   onHead = world.worldPoint(head, weld.localAnchorB);
        worst = std::max(worst, end.distance(onHead));
        worstAngle = std::max(worstAngle, std::abs(world.angleOf(head) - world.angleOf(handle)));
        lowest = std::min(lowest, world.body(head.body).position.y);
    }
    INFO("head " << headMass << " kg: " << worst * 1000 << " mm, " << worstAngle << " rad");
    CHECK(worst < 1e-3);
    CHECK(worstAngle < 1e-2);
    CHECK(lowest < -1.0); // it swung down
}

TEST_CASE("joints: a chain of 20 links stays within 1 % of its length, a 10 kg weight on 1 kg links too",
          "[joints][chain]") {
    const double weight = GENERATE(0.0, 10.0);
    const BodyShape shape = GENERATE(BodyShape::capsule, BodyShape::box);
    constexpr int kLinks = 20;
    constexpr double kLink = 0.5;
    World world = jointWorld();
    // Laid out horizontally from the hinge at the origin, to fall and swing.
    JointEnd previous{};
    std::vector<JointEnd> links;
    for (int i = 0; i < kLinks; ++i) {
        const JointEnd link = bar(world, {(i + 0.5) * kLink, 0.0}, {0.5 * kLink, 0.05}, 1.0, shape);
        world.addJoint(jointAt(world, JointKind::revolute, previous, {i * kLink, 0.0}, link, {i * kLink, 0.0}));
        links.push_back(link);
        previous = link;
    }
    if (weight > 0.0) {
        const JointEnd load = bar(world, {kLinks * kLink + 0.2, 0.0}, {0.2, 0.2}, weight);
        world.addJoint(
            jointAt(world, JointKind::revolute, previous, {kLinks * kLink, 0.0}, load, {kLinks * kLink, 0.0}));
    }
    // The chain's length along its hinges: from the origin to each link's ends in turn.
    double worst = 0.0;
    for (int s = 0; s < 600; ++s) {
        world.step();
        double stretch = 0.0;
        Vec2 hinge{};
        for (const JointEnd& link : links) {
            stretch += hinge.distance(world.worldPoint(link, {-0.5 * kLink, 0.0}));
            hinge = world.worldPoint(link, {0.5 * kLink, 0.0});
        }
        worst = std::max(worst, stretch / (kLinks * kLink));
        REQUIRE(std::isfinite(stretch));
    }
    INFO("weight " << weight << ": stretched by " << worst * 100 << " % of its length");
    CHECK(worst < 0.01);
    CHECK(world.stats().isolatedBodies == 0);
}
