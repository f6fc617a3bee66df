// The rigid contacts' two stiffnesses (issue 26). A body resting on one point of a fixed floor is a
// spring of stiffness m omega^2 loaded by m g: it rests overlapped by g / omega^2, whatever its mass
// (makeSoftness' soft constraint at rest: overlap = load / (m omega^2)). Against infinite mass the
// spring is twice the contact's hertz: stacking contacts (two shapes, neither held by a pivot or
// joint: RigidContact::stacking) are 70 Hz, so 140 Hz on the floor; a ball's and a held body's
// (a mechanism's) are 60, so 120.
#include "rube/physics/world.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace rube;

namespace {

/// The overlap a body resting on one point settles to under gravity g with a spring of `hertz`.
double restingOverlap(double g, double hertz) {
    const double omega = 2.0 * std::numbers::pi * hertz;
    return g / (omega * omega);
}

/// A fixed box whose top face is y = 0.
World floorWorld(double g) {
    WorldDef def;
    def.method = Method::solver;
    def.gravity = {0.0, -g};
    def.sleepSpeed = 0.0; // measured awake: asleep, nothing would be solved at all
    World world(def);
    RigidBodyDef floor;
    floor.position = {0.0, -1.0};
    floor.halfExtents = {20.0, 1.0};
    floor.motion = Motion::fixed;
    world.addBody(floor);
    return world;
}

/// Where the box laid on the hump (boxOnHump) starts: its centre's height, resting on one point.
constexpr double kBoxStart = 1.7;

/// A fixed capsule standing upright, its top cap (radius 0.3 m, top at y = 1.6) a hump, and a box
/// 0.2 m thick laid on it, its centre over the hump: one point, its arm along the normal. A box that
/// thick rocks back on a hump of radius above 0.1 m.
BodyId boxOnHump(World& world, double halfWidth, double mass) {
    RigidBodyDef post;
    post.shape = BodyShape::capsule;
    post.halfExtents = {0.5, 0.3};
    post.angle = 0.5 * std::numbers::pi;
    post.position = {0.0, 0.8};
    post.motion = Motion::fixed;
    world.addBody(post);
    RigidBodyDef d;
    d.halfExtents = {halfWidth, 0.1};
    d.position = {0.0, kBoxStart};
    d.mass = mass;
    d.material = {0.0, 0.5};
    return world.addBody(d);
}

} // namespace

TEST_CASE("a box resting on a fixed capsule's cap rests g / omega^2 into it, at the stacking contacts' 140 Hz",
          "[rigid][softness]") {
    for (const double g : {4.0, 9.81, 25.0})
        for (const double mass : {0.05, 1.0, 40.0})
            for (const double halfWidth : {0.2, 0.6}) {
                World world = floorWorld(g);
                const BodyId box = boxOnHump(world, halfWidth, mass);
                for (int step = 0; step < 240; ++step) world.step();
                const double overlap = kBoxStart - world.body(box).position.y;
                INFO("g " << g << " mass " << mass << " half width " << halfWidth << ": overlap " << overlap
                          << ", angle " << world.body(box).angle);
                CHECK(overlap == Approx(restingOverlap(g, 140.0)).epsilon(1e-3));
            }
}

TEST_CASE("a box a joint holds rests on a fixed capsule's cap at a mechanism's 120 Hz", "[rigid][softness]") {
    // The same box and hump, the box on a vertical slide from the world (a prismatic joint: free to
    // fall, held upright and in place), so the contact still carries the whole weight.
    for (const double g : {4.0, 9.81, 25.0})
        for (const double mass : {0.05, 1.0, 40.0}) {
            World world = floorWorld(g);
            const BodyId box = boxOnHump(world, 0.4, mass);
            JointDef slide;
            slide.kind = JointKind::prismatic;
            slide.b.body = box;
            slide.localAnchorA = {0.0, kBoxStart};
            slide.localAxisA = {0.0, 1.0};
            world.addJoint(slide);
            for (int step = 0; step < 240; ++step) world.step();
            const double overlap = kBoxStart - world.body(box).position.y;
            INFO("g " << g << " mass " << mass << ": overlap " << overlap);
            CHECK(overlap == Approx(restingOverlap(g, 120.0)).epsilon(1e-3));
        }
}

TEST_CASE("a ball resting on a fixed box rests g / omega^2 into it, at a ball's 120 Hz", "[rigid][softness]") {
    for (const double g : {4.0, 9.81, 25.0})
        for (const double mass : {0.05, 1.0, 40.0})
            for (const double radius : {0.05, 0.2}) {
                World world = floorWorld(g);
                CircleDef c;
                c.position = {0.0, radius};
                c.radius = radius;
                c.mass = mass;
                c.material = {0.0, 0.5};
                const CircleId ball = world.addCircle(c);
                for (int step = 0; step < 240; ++step) world.step();
                const double overlap = radius - world.circle(ball).position.y;
                INFO("g " << g << " mass " << mass << " radius " << radius << ": overlap " << overlap);
                CHECK(overlap == Approx(restingOverlap(g, 120.0)).epsilon(1e-3));
            }
}
