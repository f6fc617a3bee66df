// Explosion force: one radial impulse per dynamic circle in the blast, J = strength * falloff(d / radius),
// applied as Delta v = J * inverseMass (lecture 3: an impulse is a change of momentum).
#include "rube/physics/explosion.hpp"

#include "rube/physics/world.hpp"

#include <algorithm>

namespace rube {

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
        const Vec2 offset = c.position - explosion.centre;
        const double distance = offset.length();
        if (!(distance < explosion.radius)) continue;
        // At the very centre there is no radial direction: push straight up (+y), documented in the header.
        const Vec2 direction = distance > 0.0 ? offset / distance : Vec2{0.0, 1.0};
        c.velocity += direction * (explosionImpulse(explosion, distance) * c.inverseMass); // Delta v = J / m
        affected.push_back(static_cast<int>(i));
    }
    return affected;
}

std::vector<CircleId> applyExplosion(World& world, const Explosion& explosion) {
    // The same impulses, through the world's setter so that a sleeping island it reaches wakes.
    std::vector<Circle> circles(world.circles().begin(), world.circles().end());
    std::vector<CircleId> affected;
    for (const int slot : applyExplosion(circles, explosion)) {
        affected.push_back(world.circleId(slot));
        world.setVelocity(affected.back(), circles[static_cast<std::size_t>(slot)].velocity);
    }
    return affected;
}

} // namespace rube
