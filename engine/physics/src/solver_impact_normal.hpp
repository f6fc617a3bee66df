#pragma once
// Internal: speculative contacts aimed at their time of impact. Not part of the public API.
//
// A contact's normal is fixed for the step (solver_soft_step.hpp), taken where the pair starts. For a
// pair that is still apart and closing fast, that is not where it will touch: a ball striking a line
// cap or another ball at a glance meets it up to |v| dt further on, where the normal has turned (25
// degrees for a 20 m/s glance at a cap at 60 Hz). Such a contact takes the normal at its time of
// impact instead, and the gap along that normal, so the solver catches the pair exactly where it
// touches and restitution reflects the velocity about the true normal: v' = v - (1 + C)(v.n)n at the
// point of impact (lecture 3); between two balls, along the line of centres at that moment.

#include "solver_soft_step.hpp"

#include <span>

namespace rube {

/// For every contact that starts apart (gap > 0) and closes faster than `restingSpeed`, sweeps the
/// pair's relative motion over the step (start velocities, `gravity` against infinite mass, as the
/// substeps of `h` integrate it) and, when it touches within `dt`, replaces the contact's normal,
/// gap and kind by those at the time of impact. Contacts with turning segments keep theirs.
void aimAtTimeOfImpact(std::span<ContactConstraint> contacts, std::span<ContactRecord> records,
                       std::span<const Circle> circles, std::span<const Segment> segments,
                       std::span<const double> inverseMass, Vec2 gravity, double dt, double h, double restingSpeed);

} // namespace rube
