#pragma once
/// Rigid bodies that are not circles: boxes (lecture 3's blocks, and rotating planks, seesaws and
/// dominoes) and capsules. A box with `fixedRotation` is the lecture's axis-aligned block: it never
/// turns, so its collisions follow lecture 3 (per-axis time and point of impact).

#include "rube/physics/body.hpp"

#include <cstdint>

namespace rube {

/// The shape of a rigid body, in its own frame (centre at the origin, angle 0).
enum class BodyShape : std::uint8_t {
    box,     ///< a rectangle of halfExtents.x by halfExtents.y either side of the centre
    capsule, ///< a segment from (-halfExtents.x, 0) to (halfExtents.x, 0) with rounded caps of radius halfExtents.y
};

/// A rigid body: position of its centre of mass, angle, and their rates.
struct RigidBody {
    BodyShape shape = BodyShape::box;
    Vec2 position;                ///< centre of mass, m
    double angle = 0.0;           ///< radians, counter-clockwise from the body's own frame
    Vec2 velocity;                ///< m/s
    double angularVelocity = 0.0; ///< omega, rad/s
    Vec2 halfExtents{0.5, 0.5};   ///< box: half width and half height; capsule: half length and radius (m)
    double inverseMass = 1.0;     ///< 0 for fixed and kinematic bodies
    double inverseInertia = 1.0;  ///< 1 / I about the centre of mass; 0 when fixedRotation or not dynamic
    Material material;
    Motion motion = Motion::dynamic;
    bool fixedRotation = false; ///< lecture 3's block: stays axis-aligned
    double gravityScale = 1.0;  ///< how much of the world's gravity acts on it
    /// Asleep (the solver only, WorldDef::sleepSpeed): its island is a circle's index when the island
    /// holds a circle (as the circles' own), else -1 - the slot of one of its rigid bodies.
    SleepState sleep;
};

/// What a caller fills in to add a rigid body; the default is a 1 kg dynamic 1 m x 1 m box.
struct RigidBodyDef {
    BodyShape shape = BodyShape::box;
    Vec2 position;
    double angle = 0.0;
    Vec2 velocity;
    double angularVelocity = 0.0;
    Vec2 halfExtents{0.5, 0.5};
    double mass = 1.0; ///< ignored unless dynamic
    Material material;
    Motion motion = Motion::dynamic;
    bool fixedRotation = false;  ///< lecture 3's block: never turns
    double gravityScale = 1.0;   ///< how much of the world's gravity acts on it (dynamic only)
    std::uint64_t userValue = 0; ///< the caller's own value (World::userValue)
};

/// The farthest any point of the body lies from its centre, m: the radius of the circle about the
/// centre that holds it at every angle.
inline double boundingRadius(const RigidBody& b) {
    return b.shape == BodyShape::box ? b.halfExtents.length() : b.halfExtents.x + b.halfExtents.y;
}

/// True for lecture 3's block, a box that never turns (every method moves it); any other body turns,
/// which only the solver models.
inline bool isBlock(const RigidBody& b) { return b.shape == BodyShape::box && b.fixedRotation; }
inline bool isBlock(const RigidBodyDef& d) { return d.shape == BodyShape::box && d.fixedRotation; }

/// The moment of inertia of a uniform body of `mass` about its centre:
/// box m (w^2 + h^2) / 12; capsule: its rectangle plus two half discs (parallel-axis theorem).
double momentOfInertia(BodyShape shape, Vec2 halfExtents, double mass);

} // namespace rube
