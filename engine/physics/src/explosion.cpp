// Explosion force: one radial impulse per dynamic circle or rigid body in the blast, J = strength * falloff(d /
// radius), applied as Delta v = J * inverseMass (lecture 3: an impulse is a change of momentum).
#include "rube/physics/explosion.hpp"

#include "rube/physics/world.hpp"

#include <algorithm>
#include <optional>

namespace rube {

namespace {

/// The change of velocity the blast gives a body of `inverseMass` whose centre is at `position`:
/// Delta v = J / m along the radial direction (at the very centre, where there is none, straight up,
/// +y, documented in the header); none outside the blast radius.
std::optional<Vec2> blastKick(const Explosion& explosion, Vec2 position, double inverseMass) {
    const Vec2 offset = position - explosion.centre;
    const double distance = offset.length();
    if (!(distance < explosion.radius)) return std::nullopt;
    const Vec2 direction = distance > 0.0 ? offset / distance : Vec2{0.0, 1.0};
    return direction * (explosionImpulse(explosion, distance) * inverseMass);
}

} // namespace

double explosionFalloff(const Explosion& explosion, double distance) {
    // Strictly inside: a body exactly at the edge gets nothing, whatever the fall-off.
    if (!(explosion.radius > 0.0) || !(distance < explosion.radius)) return 0.0;
    const double x = std::max(0.0, distance) / explosion.radius; // relative distance in [0, 1)
    switch (explosion.falloff) {
    case Falloff::linear: return 1.0 - x;
    case Falloff::inverseSquareClamped: {
        // 1 / d^2 like the energy of a spherical blast front, clamped to 1 in the core so it stays finite.
        const double core = explosion.coreFraction;
        return x <= core ? 1.0 : (core / x) * (core / x);
    }
    case Falloff::constant: return 1.0;
    }
    return 0.0;
}

double explosionImpulse(const Explosion& explosion, double distance) {
    return explosion.strength * explosionFalloff(explosion, distance);
}

std::vector<int> applyExplosion(std::span<Circle> circles, const Explosion& explosion) {
    std::vector<int> affected;
    for (std::size_t i = 0; i < circles.size(); ++i) {
        Circle& c = circles[i];
        // Kinematic and fixed bodies have infinite mass (inverseMass 0): no impulse moves them.
        if (c.motion != Motion::dynamic) continue;
        const std::optional<Vec2> kick = blastKick(explosion, c.position, c.inverseMass);
        if (!kick) continue;
        c.velocity += *kick;
        affected.push_back(static_cast<int>(i));
    }
    return affected;
}

ExplosionPushed applyExplosion(World& world, const Explosion& explosion) {
    // The same impulses, through the world's setters so that a sleeping island it reaches wakes.
    ExplosionPushed pushed;
    std::vector<Circle> circles(world.circles().begin(), world.circles().end());
    for (const int slot : applyExplosion(circles, explosion)) {
        pushed.circles.push_back(world.circleId(slot));
        world.setVelocity(pushed.circles.back(), circles[static_cast<std::size_t>(slot)].velocity);
    }
    // Boxes and capsules: the same impulse through the centre of mass (a setter wakes, never moves a slot).
    const auto bodies = world.bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const RigidBody& b = bodies[i];
        if (b.motion != Motion::dynamic || b.inverseMass == 0.0) continue;
        const std::optional<Vec2> kick = blastKick(explosion, b.position, b.inverseMass);
        if (!kick) continue;
        pushed.bodies.push_back(world.bodyId(static_cast<int>(i)));
        world.setVelocity(pushed.bodies.back(), b.velocity + *kick);
    }
    return pushed;
}

} // namespace rube
