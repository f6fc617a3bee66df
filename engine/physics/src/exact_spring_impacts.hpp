#pragma once
// Internal to the exact method (method_exact.cpp): times of impact where a trajectory is not a
// polynomial. A circle on a spring's closed form moves on cosines (exact_springs.hpp), so its gap to
// another body is no quartic to solve: its first root is found by conservative advancement with a
// second-order bound instead, which never steps past the first root and converges on it to round-off.
// Not part of the public API.

#include "exact_springs.hpp"

#include "rube/physics/time_of_impact.hpp"

#include <optional>

namespace rube {

/// A body's motion from now: on a spring's closed form, or p + v t + a t^2 / 2 (a = 0 for a
/// kinematic body, v = a = 0 for a fixed one), with bounds on its speed and acceleration over the
/// horizon it was made for.
struct Trajectory {
    Vec2 position, velocity, acceleration;
    const SpringPath* spring = nullptr;
    double speedBound = 0.0;
    double accelerationBound = 0.0;
    /// Position and velocity at time t from now.
    void at(double t, Vec2& p, Vec2& v) const;
};

/// p + v t + a t^2 / 2 over [0, horizon].
Trajectory parabolaTrajectory(Vec2 position, Vec2 velocity, Vec2 acceleration, double horizon);
/// On the spring's closed form: |v| <= V (springSpeedBound) and |a| <= omega^2 |y| + 2 zeta omega |v|
/// <= omega V (1 + 2 zeta), since |y| <= V / omega, for all later times.
Trajectory springTrajectory(const SpringPath& path, Vec2 position, Vec2 velocity);

/// The first time within the horizon at which a circle of `radius` on `circle` touches a circle of
/// `otherRadius` on `other` while approaching (attempt 3 of lecture 5: touching or overlapping at
/// t = 0 is an impact only when approaching). The normal points from the other towards the circle.
std::optional<Collision> trajectoryCircleCollision(const Trajectory& circle, double radius, const Trajectory& other,
                                                   double otherRadius, double horizon);

/// Likewise against the segment ab (with line caps of `segmentRadius`) moving at `segmentVelocity`;
/// lineCap is set when the closest point is an end.
std::optional<Collision> trajectorySegmentCollision(const Trajectory& circle, double radius, Vec2 a, Vec2 b,
                                                    Vec2 segmentVelocity, double segmentRadius, double horizon);

} // namespace rube
