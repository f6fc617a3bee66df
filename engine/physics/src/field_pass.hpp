#pragma once
// Internal: the pass that turns a world's fields (declared in rube/physics/fields.hpp) into velocity
// changes at the start of a step. Not part of the public API.

#include "rube/physics/body.hpp"
#include "rube/physics/fields.hpp"

#include <span>

namespace rube {

/// Changes the velocity of every dynamic circle by what the fields do to it over [time, time + dt].
/// `gravity` is needed because linear drag is integrated together with it (see field_pass.cpp).
/// `thrusterSlots` holds each thruster's circle's slot in `circles` (-1: none this step).
void applyFields(std::span<Circle> circles, const Fields& fields, std::span<const int> thrusterSlots,
                 const AirDrag& airDrag, Vec2 gravity, double time, double dt);

/// What the magnets do to circle `c`'s velocity over dt, F dt / m summed over them (zero unless it is
/// magnetic and dynamic). applyFields kicks with it; exact and the solver take that kick back and
/// move the circle under the pull as under gravity (StepContext::magnets).
Vec2 magnetKick(std::span<const Magnet> magnets, const Circle& c, double dt);

/// The second half of linear air drag's step, after the method's move: maps each dynamic circle's
/// velocity onto the exact v(dt) of dv/dt = g - k v, so that position and velocity are both exact.
void linearDragAfterMove(std::span<Circle> circles, const AirDrag& airDrag, Vec2 gravity, double dt);

/// A floating body's change of velocity over dt when its buoyancy, a spring of stiffness kappa per
/// unit mass along `up`, is stiffer than the step can follow (`stiffness` = dt^2 kappa > 1): implicit
/// Euler on the linearised spring, the rise after the step v1 = (v0 + kick) / (1 + dt^2 kappa) with
/// `kick` the explicit buoyant and gravitational change along up, then the drag exp(-k dt) on that
/// velocity; less `ownGravity` (the body's g dt), which the method adds after. Circles
/// (field_pass.cpp) and boxes and capsules (rigid_water.cpp) float by it.
Vec2 implicitFloatKick(Vec2 velocity, Vec2 up, double kick, double stiffness, double k, double dt, double ownGravity);

/// Which part of a thruster's impulse over a step: the kick before the method moves the bodies, or the rest after.
enum class BurnShare { beforeMove, afterMove };

/// Changes the velocity of each thruster's circle by its share of F tau / m over [time, time + dt]
/// (tau: how long it burns in the step), split so that the method's constant-velocity move between
/// the two shares gives the exact displacement of a constant force. applyFields does the first share.
void kickThrusters(std::span<Circle> circles, const std::vector<Thruster>& thrusters, std::span<const int> slots,
                   double time, double dt, BurnShare share);

} // namespace rube
