#pragma once
// Small builders for the joint tests: a world at 60 Hz on the solver, wheels and bars, and the
// joint definitions from world points.
#include "rube/physics/world.hpp"

#include <cmath>
#include <numbers>

namespace test {

inline rube::World jointWorld(rube::Vec2 gravity = {0.0, -9.81}, rube::Method method = rube::Method::solver) {
    rube::WorldDef def;
    def.gravity = gravity;
    def.timeStep = 1.0 / 60;
    def.method = method;
    return rube::World(def);
}

/// A wheel: a circle of `radius` and `mass` (a solid disc, I = m r^2 / 2).
inline rube::JointEnd wheel(rube::World& world, rube::Vec2 at, double radius, double mass) {
    rube::CircleDef d;
    d.position = at;
    d.radius = radius;
    d.mass = mass;
    d.material.bounciness = 0.0;
    return rube::JointEnd{world.addCircle(d), {}};
}

/// A box or capsule of half extents `half` and `mass`.
inline rube::JointEnd bar(rube::World& world, rube::Vec2 at, rube::Vec2 half, double mass,
                          rube::BodyShape shape = rube::BodyShape::box, double angle = 0.0) {
    rube::RigidBodyDef d;
    d.shape = shape;
    d.position = at;
    d.halfExtents = half;
    d.mass = mass;
    d.angle = angle;
    d.material.bounciness = 0.0;
    return rube::JointEnd{{}, world.addBody(d)};
}

/// A joint of `kind` between a and b, anchored at world points pa and pb as they stand now, with
/// the reference angle of their angles now.
inline rube::JointDef jointAt(const rube::World& world, rube::JointKind kind, rube::JointEnd a, rube::Vec2 pa,
                              rube::JointEnd b, rube::Vec2 pb) {
    rube::JointDef d;
    d.kind = kind;
    d.a = a;
    d.b = b;
    d.localAnchorA = world.localPoint(a, pa);
    d.localAnchorB = world.localPoint(b, pb);
    d.referenceAngle = world.angleOf(b) - world.angleOf(a);
    return d;
}

/// A revolute of `b` to the world at `at`.
inline rube::JointId hinge(rube::World& world, rube::JointEnd b, rube::Vec2 at, double motorSpeed = 0.0,
                           double maxTorque = 0.0) {
    rube::JointDef d = jointAt(world, rube::JointKind::revolute, rube::JointEnd{}, at, b, at);
    d.motor = {motorSpeed, maxTorque};
    return world.addJoint(d);
}

constexpr double kPi = std::numbers::pi;

} // namespace test
