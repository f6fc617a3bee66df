#pragma once
/// Continuous detection (lecture 5): when, within the rest of a step, a moving circle first touches
/// another circle, a point (a line cap) or a line segment, and where.
///
/// Times are seconds from now and velocities m/s; `horizon` (the step time left) replaces the
/// lecture's "t < 1". The other body is taken as standing still: pass the circle's motion relative
/// to it (velocity minus the other's velocity, acceleration minus the other's acceleration).

#include "rube/physics/vec2.hpp"

#include <cstdint>
#include <optional>

namespace rube {

/// What an overlap at the start means: the three pseudo codes of lecture 5.
enum class TimeOfImpactRule : std::uint8_t {
    attempt1, ///< t < 0 is ignored: when rounding leaves bodies slightly overlapping they pass through
    attempt2, ///< overlapping (c < 0) is an impact at t = 0 even when separating: balls stick together
    attempt3, ///< overlapping is an impact at t = 0 only when approaching (b < 0): the robust rule
};

/// A circle's motion relative to the body it may hit: centre(t) = centre + velocity t + acceleration t^2 / 2.
struct CircleMotion {
    Vec2 centre;         ///< at t = 0, m
    Vec2 velocity;       ///< m/s, relative to the other body
    double radius = 0.0; ///< m
    Vec2 acceleration{}; ///< m/s^2, relative: gravity against a wall, zero between two falling balls
    /// The centre at time t (seconds).
    Vec2 at(double t) const { return centre + velocity * t + acceleration * (0.5 * t * t); }
};

/// A predicted collision, in the frame where the other body stands still.
struct Collision {
    double timeOfImpact = 0.0; ///< seconds from now, in [0, horizon]
    Vec2 pointOfImpact;        ///< the circle's centre at the time of impact (lecture 5: POI)
    Vec2 normal;               ///< unit collision normal, from the other body towards the circle
    Vec2 contactPoint;         ///< where the surfaces touch, on the other body's surface
    bool lineCap = false;      ///< a segment's line cap was hit rather than its face
};

/// The lecture's abc formula for two circles: the earliest t in [0, horizon] with
/// |u + v t| = radiusSum, where a = |v|^2, b = 2 u . v, c = |u|^2 - radiusSum^2 and
/// t = (-b - sqrt(b^2 - 4ac)) / 2a, evaluated without cancellation. `rule` picks what c < 0 means.
std::optional<double> circleCircleTimeOfImpact(Vec2 relativePosition, Vec2 relativeVelocity, double radiusSum,
                                               double horizon, TimeOfImpactRule rule = TimeOfImpactRule::attempt3);

/// The lecture's time of impact on a one-sided line: a = distance before - radius, b = -(v . n).
/// b <= 0: none (moving away); a >= 0: t = a / b; -radius <= a < 0: t = 0 (attempt1: none, the
/// first pseudo code that lets a resting ball sink); a < -radius: none (the centre is already past).
std::optional<double> lineTimeOfImpact(double a, double b, double radius, double horizon,
                                       TimeOfImpactRule rule = TimeOfImpactRule::attempt3);

/// A moving circle against a circle of `otherRadius` standing at `otherCentre`. With acceleration
/// |d(t)|^2 = R^2 is a quartic, solved for its earliest root to round-off, and "approaching" at t = 0
/// uses the acceleration when the normal velocity is exactly 0; attempt3 also catches a body that
/// overlaps and separates but is turned back by the acceleration within the horizon.
std::optional<Collision> circleCircleCollision(const CircleMotion& circle, Vec2 otherCentre, double otherRadius,
                                               double horizon, TimeOfImpactRule rule = TimeOfImpactRule::attempt3);

/// A moving circle against a point: a line cap, a circle of radius 0 (lecture 5).
std::optional<Collision> circlePointCollision(const CircleMotion& circle, Vec2 point, double horizon,
                                              TimeOfImpactRule rule = TimeOfImpactRule::attempt3);

/// A moving circle against the two-sided segment ab with rounded line caps of `segmentRadius`:
/// both faces (the lecture's two lines with opposite normals), the point of impact checked to lie
/// along the segment, otherwise the caps. For the faces attempt2 and attempt3 are the same (the
/// line test rejects b <= 0 first); attempt1 ignores a < 0, the variant that lets a resting ball sink.
/// With acceleration the face's gap is quadratic in t; the caps are circleCircleCollision's quartic.
std::optional<Collision> circleSegmentCollision(const CircleMotion& circle, Vec2 a, Vec2 b, double segmentRadius,
                                                double horizon, TimeOfImpactRule rule = TimeOfImpactRule::attempt3);

} // namespace rube
