#pragma once
/// Lecture 3's blocks: axis-aligned boxes that never turn. Discrete overlap tests at the current
/// positions, and continuous times of impact of a moving block against a block, a circle and a line
/// segment with rounded line caps, with the point of impact and the collision normal.
///
/// As in time_of_impact.hpp, times are seconds from now, `horizon` is the step time left, and the
/// other body stands still: pass the block's motion relative to it. Normals point from the other body
/// towards the block. An overlap at the start is an impact at t = 0 only when approaching (attempt 3).

#include "rube/physics/collision.hpp"
#include "rube/physics/time_of_impact.hpp"
#include "rube/physics/vec2.hpp"

#include <optional>

namespace rube {

/// A block's motion relative to the body it may hit: centre(t) = centre + velocity t + acceleration t^2 / 2.
struct BlockMotion {
    Vec2 centre;         ///< at t = 0, m
    Vec2 velocity;       ///< m/s, relative to the other body
    Vec2 halfExtents;    ///< half width and half height, m
    Vec2 acceleration{}; ///< m/s^2, relative (gravity against a wall, zero between two falling blocks)
    /// The centre at time t (seconds).
    Vec2 at(double t) const { return centre + velocity * t + acceleration * (0.5 * t * t); }
};

/// Block against block (lecture 3, AABB): they overlap when P.right > Q.left, P.left < Q.right and the
/// same on y. The normal is the axis of least penetration, from block 2 towards block 1.
std::optional<Overlap> blockBlockOverlap(Vec2 centre1, Vec2 half1, Vec2 centre2, Vec2 half2);

/// Block against circle: the circle's centre lies within the block grown by r (the rounded rectangle).
/// The normal points from the circle towards the block: along an axis against a face, radial at a corner.
std::optional<Overlap> blockCircleOverlap(Vec2 centre, Vec2 half, Vec2 circleCentre, double radius);

/// Block against the two-sided segment ab with rounded caps of `segmentRadius`, the face side fixed by
/// `side` (a unit normal of the line): across the face the block overlaps while its signed distance
/// along `side` is within its reach, so a block that sank below the line's middle is still pushed back
/// where it came from; past the ends, the line caps (block against circle). The normal points from the
/// segment towards the block.
std::optional<Overlap> blockSegmentOverlapOnSide(Vec2 centre, Vec2 half, Vec2 a, Vec2 b, double segmentRadius,
                                                 Vec2 side);

/// The lecture's Assignment 3.3: a moving block against a block standing still. Per axis, the distance
/// between the facing sides before and after the move gives t = a / b; the impact is the earliest time
/// one axis closes while the other overlaps. Normal axis-aligned; pointOfImpact is the block's centre
/// then; contactPoint the middle of the two faces' shared span. lineCap is never set.
std::optional<Collision> blockBlockCollision(const BlockMotion& block, Vec2 otherCentre, Vec2 otherHalfExtents,
                                             double horizon);

/// A moving block against a circle standing still: the circle's centre against the block grown by r,
/// its faces offset by r (axis-aligned normals) and its corners circles of radius r (radial normals,
/// lineCap set: a corner was hit).
std::optional<Collision> blockCircleCollision(const BlockMotion& block, Vec2 circleCentre, double radius,
                                              double horizon);

/// A moving block against the two-sided segment ab with rounded caps of `segmentRadius` (a floor, a
/// ramp): the segment's faces offset by the block's reach along their normal plus the radius (the
/// block's nearest corner or side touching the line), and past the ends the caps as circles
/// (lineCap set).
std::optional<Collision> blockSegmentCollision(const BlockMotion& block, Vec2 a, Vec2 b, double segmentRadius,
                                               double horizon);

/// How far a block reaches from its centre along the unit direction n: hx |nx| + hy |ny|.
double blockReach(Vec2 half, Vec2 n);

} // namespace rube
