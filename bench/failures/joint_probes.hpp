#pragma once
/// Failure probes for joints (issue 21): a chain's mass ratio, a motor's torque against its load,
/// a spring's stiffness against the time step. Methods that refuse joints (discrete, turn-based,
/// exact) fail every value as "refuses joints".

#include "failure_probes.hpp"

namespace bench::failures {

/// A chain of 10 capsule links (1 kg, 0.5 m) hinged to the world, laid level, with a box of `ratio`
/// kg hinged to its end, 3 s: fails (stretches) when the links' hinges open by more than 1 % of the
/// chain's 5 m in all; jointError is the largest opening, relative to the length.
Outcome chainProbe(rube::Method method, double ratio);

/// A disc (r = 0.5 m, 1 kg) whose motor (2 rad/s) has `torqueOverLoad` times the torque M g r of a
/// 1 kg rack hanging on its rim (a gear to a vertical prismatic): omega(t) must follow
/// (tau - M g r) t / (I + M r^2), held at 2 rad/s, within 1 % at 0.25 and 0.5 s (misses the formula).
Outcome motorProbe(rube::Method method, double torqueOverLoad);

/// A 1 kg ball on an undamped spring of `stiffness` to a fixed point, stretched 0.1 m, no gravity,
/// 5 s at 1/60 s: fails when its energy strays more than 1 % from the start (gains or loses energy).
Outcome springProbe(rube::Method method, double stiffness);

} // namespace bench::failures
