#pragma once
// Internal: the time of impact of two rounded polygons that move and turn over a step, by
// conservative advancement. The lecture's time of impact (lecture 5) solves |u + v t| = R for two
// circles; a box or capsule that turns has no closed form, so the gap is approached in safe steps:
// with d the gap and n the direction of the closest points at t, no point of A comes closer to B
// along n faster than w = n . (moveA - moveB) + |turnA| extentA + |turnB| extentB (per unit t), so
// nothing touches before t + d / w. Repeating from there converges on the first touch from outside.
// Not part of the public API.

#include "rigid_manifold.hpp"

namespace rube {

/// A rounded polygon moving over the step: its shape at t = 0 turned about `centre` by turn t and
/// carried by move t (t in [0, 1] of the step), as a rigid body's centre of mass or a paddle's pivot moves.
struct SweptShape {
    RoundedPolygon start; ///< the shape at t = 0
    Vec2 centre;          ///< what it turns about, at t = 0
    Vec2 move;            ///< displacement of the centre over the step, m
    double turn = 0.0;    ///< angle turned over the step, radians
    double extent = 0.0;  ///< the farthest core vertex from the centre, m
    /// The shape at t.
    RoundedPolygon at(double t) const;
};

/// The first t in [0, 1] at which the surfaces of A and B come within `target` (m) of each other, by
/// conservative advancement; 0 when they are that close (or overlap) already, -1 when they never are.
double sweptTimeOfImpact(const SweptShape& a, const SweptShape& b, double target);

} // namespace rube
