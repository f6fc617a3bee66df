#pragma once
/// Bodies: dynamic and kinematic circles, static and kinematic line segments with rounded caps.

#include "rube/physics/vec2.hpp"

#include <cstdint>
#include <vector>

namespace rube {

/// How a body moves: `fixed` never, `kinematic` along a scripted path with infinite mass,
/// `dynamic` under gravity and impacts with finite mass.
enum class Motion : std::uint8_t { fixed, kinematic, dynamic };

/// Surface response of a body. A pair's bounciness and friction are the products of both (walls
/// default to bounciness 1, so a ball's own applies on a plain wall, and to friction 0: a plain wall
/// is frictionless, and so is every pair until a scene asks for friction on both sides).
struct Material {
    double bounciness = 1.0; ///< C in v' = u - C (v - u) (lecture 3): 0 sticks, 1 is perfectly elastic
    double friction = 0.0;   ///< Coulomb coefficient mu: the tangential impulse is at most mu times the normal one
};

/// One key of a scripted path: the body's offset from where it was placed, at a time in seconds,
/// and (segments only) the angle it has turned about its pivot by then.
struct PathKey {
    double time = 0.0;
    Vec2 offset;
    double angle = 0.0; ///< radians, counter-clockwise about the segment's pivot (circles ignore it)
};

/// A scripted path: offsets at key times, straight lines in between; after the last key it
/// holds still, or with `loop` starts again from the first key.
struct KinematicPath {
    std::vector<PathKey> keys;
    bool loop = false;
    /// The offset at time t (seconds since the world started).
    Vec2 offsetAt(double t) const;
    /// The angle turned at time t, radians: straight lines between the keys, as the offset.
    double angleAt(double t) const;
    /// True when some key turns (a rotating paddle); a path that never turns only translates.
    bool turns() const;
};

/// How long a dynamic circle has been slow, and whether the solver has put it to sleep (Box2D's
/// islands: everything touching it was slow as long). An asleep circle has zero velocity and spin;
/// any change to them from outside (an explosion, a field, the game) wakes its island.
struct SleepState {
    bool asleep = false;
    int island = -1;      ///< asleep: the island it fell asleep with (the index of one of its circles)
    double slowFor = 0.0; ///< seconds its speed and its surface's spin speed have stayed below the threshold
};

/// A circle. Dynamic circles move under gravity and impacts; kinematic ones follow a path.
struct Circle {
    Vec2 position;
    Vec2 velocity;
    double radius = 0.5;
    double inverseMass = 1.0; ///< 0 for kinematic circles: infinite mass (lecture 3, walls)
    Material material;
    Motion motion = Motion::dynamic;
    int path = -1;                ///< index of its KinematicPath, or -1
    Vec2 origin;                  ///< where it was placed: the path's offsets are added to this
    bool magnetic = false;        ///< magnets pull it (steel)
    double angle = 0.0;           ///< radians turned since it was placed (counter-clockwise)
    double angularVelocity = 0.0; ///< omega, rad/s
    double inverseInertia = 0.0;  ///< 1 / I about the centre; 0 for kinematic and fixed circles
    SleepState sleep;             ///< the solver's rest: asleep circles hold still until something reaches them
    double gravityScale = 1.0;    ///< how much of the world's gravity acts on it: -1 rises at g (a balloon)
};

/// A two-sided line segment from a to b with rounded line caps of `radius` at both ends.
/// radius 0 is the lecture's line: the caps are zero-radius circles. A positive radius makes it a
/// capsule of thickness 2 radius. Static unless it follows a path (kinematic, infinite mass).
struct Segment {
    Vec2 a;
    Vec2 b;
    Vec2 velocity; ///< of both endpoints, during the current step (kinematic only)
    double radius = 0.0;
    Material material;
    int path = -1;
    Vec2 originA, originB;
    double surfaceSpeed = 0.0; ///< a conveyor: its surface moves along a->b at this speed, m/s (felt through friction)
    double pivotAlong = 0.5;   ///< where along a->b it turns when its path turns: 0 at a, 1 at b
    double angularVelocity = 0.0; ///< omega about the pivot during the current step, rad/s (turning paths only)
    Motion motion() const { return path >= 0 ? Motion::kinematic : Motion::fixed; }
    /// A conveyor's belt velocity: surfaceSpeed along a->b (what friction carries a body towards).
    Vec2 beltVelocity() const { return (b - a).normalized() * surfaceSpeed; }
    /// The velocity of its surface at `point`: v + omega x r, r from the pivot (lecture 3's point velocity).
    Vec2 velocityAt(Vec2 point) const {
        // Exactly `velocity` when it does not turn, so translating paths give bit-identical results.
        return angularVelocity == 0.0 ? velocity
                                      : velocity + (point - lerp(a, b, pivotAlong)).perpendicular() * angularVelocity;
    }
};

/// What a caller fills in to add a circle; the defaults give a 1 kg dynamic ball of radius 0.5 m.
struct CircleDef {
    Vec2 position;
    Vec2 velocity;
    double radius = 0.5;
    double mass = 1.0; ///< ignored for kinematic circles
    Material material;
    Motion motion = Motion::dynamic;
    int path = -1;
    bool magnetic = false;        ///< magnets pull it (steel)
    double angularVelocity = 0.0; ///< omega at the start, rad/s (a spinning throw)
    double inertiaFactor = 0.5;   ///< I = inertiaFactor m r^2: 1/2 a solid disc, 1 a thin ring
    double gravityScale = 1.0;    ///< how much of the world's gravity acts on it (dynamic only)
    std::uint64_t userValue = 0;  ///< the caller's own value (World::userValue)
};

/// What a caller fills in to add a segment; the default is a static line of zero thickness.
struct SegmentDef {
    Vec2 a;
    Vec2 b{1.0, 0.0};
    double radius = 0.0;
    Material material;
    int path = -1;
    double surfaceSpeed = 0.0; ///< a conveyor's belt speed along a->b, m/s
    double pivotAlong = 0.5;   ///< where along a->b a turning path turns it: 0 at a, 1 at b (a paddle's hinge)
};

} // namespace rube
