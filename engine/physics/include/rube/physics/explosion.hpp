#pragma once
/// Explosion force (the rubric's extra physics): a radial impulse, falling off with distance, given
/// to every dynamic circle, box and capsule whose centre lies within the blast radius.
///
/// An impulse changes momentum at once: Delta v = J / m = J * inverseMass (lecture 3, Newton's second
/// law over an instant), so heavier bodies get a smaller kick and every body the same momentum for the
/// same distance. Kinematic and fixed bodies (infinite mass) are untouched.

#include "rube/physics/body.hpp"
#include "rube/physics/handles.hpp"
#include "rube/physics/vec2.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace rube {

class World;

/// How the impulse falls off with the distance d from the centre, as a fraction of the full strength.
enum class Falloff : std::uint8_t {
    linear,               ///< 1 - d / radius: full at the centre, fading to zero at the edge (the default)
    inverseSquareClamped, ///< min(1, (coreFraction radius / d)^2): full in the core, then 1 / d^2, cut at the radius
    constant,             ///< 1 everywhere within the radius
};

/// An explosion: where, how far it reaches and how hard it pushes.
struct Explosion {
    Vec2 centre;                       ///< m
    double radius = 1.0;               ///< m: a body whose centre is this far or farther is unaffected
    double strength = 1.0;             ///< N s: the impulse J a body at the centre receives
    Falloff falloff = Falloff::linear; ///< how J shrinks towards the edge
    double coreFraction = 0.1; ///< inverseSquareClamped only: the full-strength core, as a fraction of the radius
};

/// The fraction of the strength at distance `distance` from the centre: 1 at the centre (0 at or past the radius).
double explosionFalloff(const Explosion& explosion, double distance);

/// The impulse magnitude J = strength * falloff(d / radius) at `distance` from the centre, N s.
double explosionImpulse(const Explosion& explosion, double distance);

/// Applies the explosion to every dynamic circle whose centre is closer than the radius:
/// v += J inverseMass (p - centre) / |p - centre|, along +y for a body exactly at the centre
/// (a radial direction does not exist there; +y is "up", away from the usual floor).
/// Returns the indices of the circles it pushed, in increasing order.
std::vector<int> applyExplosion(std::span<Circle> circles, const Explosion& explosion);

/// What an explosion pushed in a world, each list in slot order.
struct ExplosionPushed {
    std::vector<CircleId> circles;
    std::vector<BodyId> bodies; ///< dynamic boxes and capsules
    std::size_t size() const { return circles.size() + bodies.size(); }
};

/// The same on a world's circles, and on its dynamic boxes and capsules, each pushed through its
/// centre of mass (v += J inverseMass along the direction from the centre to it; a push through the
/// centre turns nothing), their islands woken. Segments are fixed or kinematic and never move.
ExplosionPushed applyExplosion(World& world, const Explosion& explosion);

} // namespace rube
