#pragma once
// Internal: where a kinematic segment whose path turns (a rotating paddle) stands at a given time.
// Not part of the public API.
//
// Within one step every method moves kinematic bodies in a straight line with their velocity; a
// turning segment is translated with its pivot's velocity during the step, contacts feel its surface
// at v + omega x r (Segment::velocityAt), and the turn itself is applied at the step's ends, where
// the world sets the segment onto its path again.

#include "rube/physics/body.hpp"
#include "rube/physics/collision.hpp"

#include <span>

namespace rube {

/// Sets s.a and s.b to their pose at time t: the pivot moved by the path's offset, both ends turned
/// about it by the path's angle.
void placeTurningSegment(Segment& s, const KinematicPath& path, double t);

/// The velocity a time-of-impact search gives segment s against a circle centred at `centre`: its own for
/// a segment that does not turn; for a turning one, its surface's velocity at the point nearest the circle,
/// as if the segment translated with it over the step (to first order in dt the chord that point follows).
inline Vec2 velocityTowards(const Segment& s, Vec2 centre) {
    return s.angularVelocity == 0.0 ? s.velocity : s.velocityAt(closestPointOnSegment(centre, s.a, s.b));
}

/// placeTurningSegment for every segment whose path turns (no others are touched).
void placeTurningSegments(std::span<Segment> segments, std::span<const KinematicPath> paths, double t);

} // namespace rube
