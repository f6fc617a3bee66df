#pragma once
/// Aiming and shooting (week 2, and the rubric's "advanced aiming"): aiming in the current direction
/// and at a target, a gravity-influenced projectile on both arcs of the ballistic equation, leading a
/// moving target with and without gravity, timing a fixed-angle shot to hit a moving target, and the
/// predicted arc for drawing.
///
/// Pure functions: positions in m, velocities in m/s, gravity in m/s^2 in any direction. A projectile
/// is a point on p(t) = muzzle + v t + g t^2 / 2, the path Method::exact moves a free ball along; a
/// target moves at constant velocity, q(t) = target + targetVelocity t.

#include "rube/physics/vec2.hpp"
#include "rube/physics/world.hpp" // Aabb

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace rube {

/// A launch: the direction the projectile is aimed in and the velocity it leaves the muzzle with.
struct Shot {
    Vec2 direction;     ///< unit vector of the launch
    double angle = 0.0; ///< the launch angle, radians from the +x axis counter-clockwise (direction.angle())
    Vec2 velocity;      ///< direction * muzzle speed, m/s
};

/// Aiming in the current direction: the unit vector at `angle` radians and the launch velocity.
Shot aimInDirection(double angle, double muzzleSpeed);

/// Aiming at a target without gravity: the direction from the muzzle to the point (nothing when they coincide).
std::optional<Shot> aimAtTarget(Vec2 muzzle, Vec2 target, double muzzleSpeed);

/// One solution of the ballistic equation: the shot and the time it takes to reach the target.
struct Arc {
    Shot shot;
    double timeOfFlight = 0.0; ///< seconds from launch until the projectile is at the target
};

/// A gravity-influenced shot at a fixed target: the low and the high arc, or why there is none.
struct GravityShot {
    std::optional<Arc>
        lowArc; ///< the flatter, earlier arc; the only one at exactly the minimum speed or without gravity
    std::optional<Arc> highArc; ///< the lobbed, later arc
    double minimumSpeed = 0.0;  ///< the least muzzle speed that reaches the target, m/s (always filled in)
    std::string reason;         ///< empty when reachable, otherwise why not ("target out of reach: ...")
    /// True when at least one arc reaches the target.
    bool reachable() const { return lowArc.has_value(); }
};

/// Aiming a gravity-influenced projectile at `target` with a fixed muzzle speed, for any gravity vector:
/// tan(theta) = (s^2 +- sqrt(s^4 - g (g x^2 + 2 y s^2))) / (g x) in the frame where gravity is -y.
GravityShot aimGravityShot(Vec2 muzzle, Vec2 target, double muzzleSpeed, Vec2 gravity);

/// A projectile and a target meeting: the shot, when, and where.
struct Intercept {
    Shot shot;
    double time = 0.0;  ///< seconds from launch until the projectile meets the target
    Vec2 pointOfImpact; ///< where they meet: the target's position at `time`
};

/// Leading a moving target: the earliest intercept within (0, maxTime] of a shot fired now at the target
/// moving at constant velocity, from |d + v t - g t^2 / 2| = s t (a quadratic without gravity, a quartic
/// with it). Nothing when no shot at this muzzle speed catches the target.
std::optional<Intercept> leadMovingTarget(Vec2 muzzle, Vec2 target, Vec2 targetVelocity, double muzzleSpeed,
                                          Vec2 gravity = {}, double maxTime = std::numeric_limits<double>::infinity());

/// When to fire a shot whose direction is fixed, so it hits a target moving at constant velocity.
struct ShotTiming {
    bool possible = false;
    double delay = 0.0;      ///< seconds from now until the shot must be fired (>= 0)
    double flightTime = 0.0; ///< seconds from firing until the projectile meets the target
    Vec2 pointOfImpact;      ///< where they meet
    std::string reason;      ///< empty when possible, otherwise why not
};

/// Timing a fixed-angle shot to hit a moving target: the smallest delay >= 0 after which a shot fired
/// along `direction` at `muzzleSpeed` meets the target (with gravity, or with gravity = {} without);
/// a target standing on the path gives delay 0, one beside it or out of reach gives a reason.
ShotTiming timeFixedAngleShot(Vec2 muzzle, Vec2 direction, double muzzleSpeed, Vec2 target, Vec2 targetVelocity,
                              Vec2 gravity = {});

/// The predicted arc for drawing: `pointCount` points of p + v t + g t^2 / 2 evenly spaced over
/// [0, duration]; with a box it ends at the point where the arc leaves it (empty if it starts outside).
std::vector<Vec2> predictedArc(Vec2 position, Vec2 velocity, Vec2 gravity, double duration, int pointCount,
                               std::optional<Aabb> box = std::nullopt);

} // namespace rube
