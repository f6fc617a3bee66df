#pragma once
// Internal: a lone bounce resolved at its time of impact under gravity. Not part of the public API.
//
// Restitution runs once at the end of the step (solver_soft_step.hpp): from the time of impact t0 to
// the end of the step the contact holds the circle, so gravity's share of the normal velocity after
// the touch, g.n (dt - t0), is lost and the circle ends the step on the surface rather than on its
// way up. At 60 Hz that put a 1 m/s bounce on a 17-degree line 5 degrees and 16 % off. A circle whose
// only contact this step is one bounce off infinite mass (a line, a cap, a fixed ball) is bounced at
// t0 and flown along its parabola for the rest of the step instead. A circle with other contacts
// keeps the end-of-step restitution: carrying it on would drive it into its neighbours.

#include "solver_soft_step.hpp"

#include <cstdint>
#include <span>

namespace rube {

/// For each contact aimed at its time of impact t0 (ContactRecord::impactTime, within `dt`) that
/// bounces (C > 0, approach above `threshold`) a dynamic circle off a body of infinite mass, the
/// circle touching nothing else this step: sets the circle's normal velocity and gap to those of the
/// reflection at t0 followed by free flight to the end of the step, and marks the record `carried`.
/// Bullets (`isBullet`) are left to the continuous pass. `circles` still hold their velocities at the start of the
/// step; `gravity` in m/s^2; substeps of `h` seconds. A bounce due within the first substep of the next step (t0 in
/// (dt, dt + h]), which the last substep's speculative constraint caught early, is undone: the circle is left in free
/// flight, its contact's impulse zeroed, so the next step bounces it at t0. Returns how many bounces it carried or
/// deferred.
int carryPastImpact(std::span<ContactConstraint> contacts, std::span<ContactRecord> records,
                    std::span<SolverBody> bodies, std::span<const Circle> circles, std::span<const double> inverseMass,
                    std::span<const std::uint8_t> isBullet, int circleCount, double threshold, Vec2 gravity, double dt,
                    double h);

} // namespace rube
