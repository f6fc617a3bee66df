// The joints' failure probes (joint_probes.hpp): each builds its machine through rube's public API
// and stops at the first failing step.

#include "joint_probes.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace bench::failures {
namespace {

using rube::JointDef;
using rube::JointEnd;
using rube::JointKind;
using rube::Method;
using rube::Vec2;
using rube::World;

World makeWorld(Method method, Vec2 gravity) {
    rube::WorldDef def;
    def.method = method;
    def.timeStep = kTimeStep;
    def.gravity = gravity;
    return World(def);
}

JointEnd box(World& world, Vec2 at, Vec2 half, double mass, rube::BodyShape shape = rube::BodyShape::box) {
    rube::RigidBodyDef d;
    d.shape = shape;
    d.position = at;
    d.halfExtents = half;
    d.mass = mass;
    d.material.bounciness = 0.0;
    return JointEnd{{}, world.addBody(d)};
}

rube::JointId hinge(World& world, JointEnd a, JointEnd b, Vec2 at) {
    JointDef d;
    d.a = a;
    d.b = b;
    d.localAnchorA = world.localPoint(a, at);
    d.localAnchorB = world.localPoint(b, at);
    d.referenceAngle = world.angleOf(b) - world.angleOf(a);
    return world.addJoint(d);
}

// Only the solver carries joints; the others refuse them (World::step throws).
bool refuses(Method method, Outcome& out) {
    out.refused = !rube::movesTurningBodies(method);
    return out.refused;
}

bool finiteState(const World& world) {
    for (const rube::RigidBody& b : world.bodies())
        if (!rube::isFinite(b.position) || !rube::isFinite(b.velocity)) return false;
    for (const rube::Circle& c : world.circles())
        if (!rube::isFinite(c.position) || !rube::isFinite(c.velocity)) return false;
    return true;
}

// One step; false (and the outcome marked) when a body's state went non-finite.
bool stepFinite(World& world, Outcome& out) {
    world.step();
    out.nonFinite = !finiteState(world);
    return !out.nonFinite;
}

} // namespace

Outcome chainProbe(Method method, double ratio) {
    Outcome out;
    if (refuses(method, out)) return out;
    constexpr int kLinks = 10;
    constexpr double kLink = 0.5;
    World world = makeWorld(method, {0.0, -9.81});
    std::vector<JointEnd> links;
    JointEnd previous{};
    for (int i = 0; i < kLinks; ++i) {
        const JointEnd link = box(world, {(i + 0.5) * kLink, 0.0}, {0.5 * kLink, 0.05}, 1.0, rube::BodyShape::capsule);
        hinge(world, previous, link, {i * kLink, 0.0});
        links.push_back(link);
        previous = link;
    }
    hinge(world, previous, box(world, {kLinks * kLink + 0.2, 0.0}, {0.2, 0.2}, ratio), {kLinks * kLink, 0.0});
    out.jointError = 0.0;
    for (int step = 0; step < 180 && !out.failed(); ++step) {
        if (!stepFinite(world, out)) break;
        double open = 0.0;
        Vec2 end{};
        for (const JointEnd& link : links) {
            open += end.distance(world.worldPoint(link, {-0.5 * kLink, 0.0}));
            end = world.worldPoint(link, {0.5 * kLink, 0.0});
        }
        out.jointError = std::max(out.jointError, open / (kLinks * kLink));
        out.stretches = out.jointError > 0.01;
    }
    return out;
}

Outcome motorProbe(Method method, double torqueOverLoad) {
    Outcome out;
    if (refuses(method, out)) return out;
    constexpr double r = 0.5, m = 1.0, load = 1.0, g = 9.81, target = 2.0;
    World world = makeWorld(method, {0.0, -g});
    rube::CircleDef disc;
    disc.radius = r;
    disc.mass = m;
    const JointEnd wheel{world.addCircle(disc), {}};
    const double tau = torqueOverLoad * load * g * r;
    JointDef axle;
    axle.b = wheel;
    axle.motor = {target, tau};
    const rube::JointId turn = world.addJoint(axle);
    // The rack hangs at the rim's right, sliding up as the wheel turns counter-clockwise: s = r angle.
    const JointEnd rack = box(world, {r + 0.1, 0.0}, {0.05, 0.5}, load);
    JointDef rail;
    rail.kind = JointKind::prismatic;
    rail.b = rack;
    rail.localAnchorA = {r + 0.1, 0.0};
    rail.localAxisA = {0.0, 1.0};
    const rube::JointId slide = world.addJoint(rail);
    JointDef gear;
    gear.kind = JointKind::gear;
    gear.jointA = turn;
    gear.jointB = slide;
    gear.ratio = -1.0 / r;
    world.addJoint(gear);
    // alpha = (tau - M g r) / (I + M r^2), until the motor's speed is reached.
    const double inertia = 0.5 * m * r * r + load * r * r;
    const double alpha = (tau - load * g * r) / inertia;
    out.jointError = 0.0;
    for (int step = 1; step <= 30 && !out.failed(); ++step) {
        if (!stepFinite(world, out)) break;
        if (step % 15 != 0) continue;
        const double t = step * kTimeStep;
        const double expected = std::min(alpha * t, target);
        const double omega = world.circle(wheel.circle).angularVelocity;
        const double miss = std::abs(omega - expected) / std::max(std::abs(expected), 1e-3);
        out.jointError = std::max(out.jointError, miss);
        out.missesFormula = miss > 0.01;
    }
    return out;
}

Outcome springProbe(Method method, double stiffness) {
    Outcome out;
    // Exact follows this spring (a ball on its line, no gravity) on its closed form.
    if (method != Method::exact && refuses(method, out)) return out;
    World world = makeWorld(method, {0.0, 0.0});
    rube::CircleDef ball;
    ball.position = {1.1, 0.0};
    ball.radius = 0.05;
    const rube::CircleId id = world.addCircle(ball);
    JointDef spring;
    spring.kind = JointKind::spring;
    spring.b = JointEnd{id, {}};
    spring.restLength = 1.0;
    spring.stiffness = stiffness;
    world.addJoint(spring);
    const double e0 = 0.5 * stiffness * 0.01;
    out.jointError = 0.0;
    for (int step = 0; step < 300 && !out.failed(); ++step) {
        if (!stepFinite(world, out)) break;
        const rube::Circle& c = world.circle(id);
        const double stretch = c.position.length() - 1.0;
        const double e = 0.5 * stiffness * stretch * stretch + 0.5 * c.velocity.lengthSquared();
        out.energyGain = std::max(out.energyGain, (e - e0) / e0);
        out.jointError = std::max(out.jointError, std::abs(e - e0) / e0);
        out.gainsEnergy = (e - e0) / e0 > kEnergyTolerance;
        out.losesEnergy = (e0 - e) / e0 > kEnergyTolerance;
    }
    return out;
}

} // namespace bench::failures
