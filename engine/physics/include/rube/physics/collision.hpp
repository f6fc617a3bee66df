#pragma once
/// Collision detection: discrete overlap tests at the current positions, and continuous
/// times of impact over a step (lecture 5), including motion under constant acceleration.

#include "rube/physics/vec2.hpp"

#include <optional>

namespace rube {

// ---------------------------------------------------------------------------------------------
// Discrete detection: do the shapes overlap now?

/// How two overlapping shapes sit: the unit normal points from the other shape towards the
/// circle, `depth` is how far the circle must move along it to just touch, `point` is where the
/// other shape's surface is deepest inside the circle.
struct Overlap {
    Vec2 normal;
    double depth = 0.0;
    Vec2 point;
};

/// Circle against circle: distance(c1, c2) < r1 + r2 (lecture 5). The normal points from c2 to c1;
/// for coincident centres it is +y, so the push-back is still well defined.
std::optional<Overlap> circleCircleOverlap(Vec2 c1, double r1, Vec2 c2, double r2);

/// Circle against a point (a line cap of zero radius): distance(c, p) < r (lecture 5).
std::optional<Overlap> circlePointOverlap(Vec2 c, double r, Vec2 p);

/// The point of segment ab closest to p.
Vec2 closestPointOnSegment(Vec2 p, Vec2 a, Vec2 b);

/// Circle against a two-sided segment ab with rounded caps of `segmentRadius`: the circle's centre
/// is closer than r + segmentRadius to the segment. Inside the segment's span the normal is the
/// line's normal on the circle's side; past the ends it points from the cap (lecture 5, line caps).
std::optional<Overlap> circleSegmentOverlap(Vec2 c, double r, Vec2 a, Vec2 b, double segmentRadius = 0.0);

} // namespace rube
