#pragma once
// Internal: collision resolve (lectures 3 and 5): the position reset and the velocity reflection,
// shared by every time-step method. Not part of the public API.

#include "rube/physics/body.hpp"
#include "rube/physics/collision.hpp"

#include <optional>
#include <span>

namespace rube {

struct StepContext;

/// A pair's bounciness C: the product of both materials' (a wall's default 1 leaves the ball's own).
double pairBounciness(const Material& first, const Material& second);

/// How fast body 1 approaches body 2 along the unit normal n (from body 2 to body 1):
/// -(v1 - v2) . n, positive when approaching.
double approachSpeed(Vec2 v1, Vec2 v2, Vec2 normal);

/// Newton's collision along the unit normal n (from body 2 to body 1): the normal parts become
/// v' = u - C (v - u), u the normal velocity of the centre of mass, and the tangential parts are kept
/// (lecture 3). An inverse mass of 0 is infinite mass (a wall): u is then the wall's normal velocity.
/// Changes nothing unless the bodies approach (lecture 3 tip); returns the approach speed before.
double resolveImpact(Vec2& v1, double inverseMass1, Vec2& v2, double inverseMass2, Vec2 normal, double bounciness);

/// Position reset: moves two overlapping bodies apart along n (from body 2 to body 1) by `depth`,
/// split by inverse mass so the centre of mass stays put; an infinite-mass body does not move.
void pushApart(Vec2& p1, double inverseMass1, Vec2& p2, double inverseMass2, Vec2 normal, double depth);

/// The unit normal of segment s's line on the side where `point` is (+normal when on the line).
Vec2 segmentSide(const Segment& s, Vec2 point);

/// An overlap with a segment, and whether it is with one of its line caps.
struct SegmentOverlap {
    Overlap overlap;
    bool lineCap = false;
};

/// Circle against segment s with the face's side fixed by `side` (a unit normal of the line): inside the
/// segment's span the circle overlaps while its signed distance along `side` is in (-R, R), R = r + radius,
/// so a circle that sank below the middle is still pushed back to where it came from; past the ends,
/// the line caps (lecture 5). A circle wholly on the other side does not overlap: it has tunnelled.
std::optional<SegmentOverlap> circleSegmentOverlapOnSide(Vec2 centre, double radius, const Segment& s, Vec2 side);

/// The discrete clean-up (lecture 5's first method), also the exact method's fallback: each dynamic circle in
/// index order, against every segment and then every other circle, is pushed out of what it overlaps and its
/// velocity reflected with Newton's formula if approaching. A segment's face side is the one the circle's
/// centre `sideCentres[i]` was on against the segment moved back by its velocity times `sideDelay`.
/// With `record`, appends each separated overlap as an Impact at world time `time`; returns how many there were.
int separateOverlaps(StepContext& context, std::span<const Vec2> sideCentres, double sideDelay, double time,
                     bool record);

} // namespace rube
