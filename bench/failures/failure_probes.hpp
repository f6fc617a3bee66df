#pragma once
/// Failure probes: one small rube scene per axis of "where methods fail" (issue 6), run on one of
/// rube's methods at one value of the axis, reporting which of the failures happened. The bench's
/// failure table sweeps them; the tests in tests/failure_boundaries_test.cpp assert their boundaries.

#include "rube/physics/world.hpp"

#include <string>

namespace bench::failures {

/// What went wrong in a probe run; several may happen in the same step.
struct Outcome {
    bool tunnels = false;         ///< a ball ended on the far side of the line it came at
    bool sinks = false;           ///< a resting ball went through the floor or through the ball beneath it
    bool overlaps = false;        ///< two shapes overlapped by more than 5 % of a radius after a step
    bool gainsEnergy = false;     ///< the total energy rose above its start by more than 1 %
    bool eventCap = false;        ///< a step hit the exact method's impact cap (maxEventsPerStep)
    bool nonFinite = false;       ///< a NaN or infinity appeared
    double deepestOverlap = 0.0;  ///< the largest overlap seen, as a fraction of the radius
    double energyGain = 0.0;      ///< the largest rise of the energy over its start, relative
    bool misdirected = false;     ///< a bounce left more than 0.5 degrees off the exact reflection
    double directionError = -1.0; ///< that bounce's direction error, degrees (capBounceProbe; -1: not measured)
    bool refused = false;         ///< the method does not model the probe's joints (World::step refuses them)
    bool stretches = false;       ///< a chain's hinges opened by more than 1 % of its length
    bool missesFormula = false;   ///< a motor's speed left its formula by more than 1 %
    bool losesEnergy = false;     ///< an undamped spring's energy fell by more than 1 %
    double jointError = -1.0;     ///< the joint probe's own measure, relative (-1: not measured)

    /// True when anything above went wrong.
    bool failed() const {
        return tunnels || sinks || overlaps || gainsEnergy || eventCap || nonFinite || misdirected || refused ||
               stretches || missesFormula || losesEnergy;
    }
    /// The failures, worst first, joined by ", " ("" when none).
    std::string describe() const;
};

/// The share of a radius two shapes may overlap before it counts as a failure (the 5 %).
inline constexpr double kOverlapTolerance = 0.05;
/// The relative rise of the energy that counts as a gain: C <= 1 may only lose energy (lecture 3).
inline constexpr double kEnergyTolerance = 0.01;
/// Every probe's time step, s.
inline constexpr double kTimeStep = 1.0 / 60;

/// A ball of radius 0.05 m coming straight at a thin static line with speed x dt = `travelPerRadius`
/// x r, no gravity, C = 1, from `phases` start offsets spread over one step's travel (every phase of
/// the crossing step). Stops at the first phase that fails.
Outcome speedProbe(rube::Method method, double travelPerRadius, int phases = 1000);

/// A column of `height` balls (r = 0.1 m, 1 kg, C = 0) standing on a floor, each touching the one
/// beneath, under gravity for 2 s, at `timeStep` s a step.
Outcome stackProbe(rube::Method method, int height, double timeStep = kTimeStep);

/// A ball `ratio` times heavier resting on a 1 kg ball on a floor (r = 0.1 m, C = 0), under gravity for 2 s.
Outcome massRatioProbe(rube::Method method, double ratio);

/// A column of 4 balls (r = 0.1 m) dropped with 0.1 m gaps onto a floor, all of bounciness C, under
/// gravity for 3 s: the energy may only fall.
Outcome bouncinessProbe(rube::Method method, double bounciness);

/// A column of `height` balls (r = 0.2 m, 1 kg, C = 0) standing on a static floor for 5 s at
/// `timeStep`: only whether the bottom ball ends a step below the floor (sinks) counts.
Outcome floorStackProbe(rube::Method method, int height, double timeStep = kTimeStep);

/// A frictionless ball (r = 0.25 m) at rest on a static line tilted `degrees`, 10 s: it fails
/// (sinks, as "freezes") unless it slides x = g sin(theta) t^2 / 2 within 1 % at the end, or when
/// its energy rises.
Outcome inclineProbe(rube::Method method, double degrees);

/// A ball (r = 0.25 m, C = 0.3) dropped 0.1 m above its resting height, a tenth of the way off the
/// axis, into a V of two static lines each `halfAngleDegrees` from the V's axis, 5 s: it fails
/// (sinks, as "cycles") unless it ends touching both lines within 1e-9 m, slower than 1e-9 m/s.
Outcome vProbe(rube::Method method, double halfAngleDegrees);

/// A ball (r = 0.25 m, C = 1, no gravity) striking a line's rounded cap (radius 0) at `speed` m/s with
/// an impact parameter of half its radius: the error of its outgoing direction against the exact
/// reflection about the normal at the time of impact, degrees, in Outcome::directionError; fails above 0.5.
Outcome capBounceProbe(rube::Method method, double speed);

} // namespace bench::failures
