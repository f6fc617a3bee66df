#pragma once
/// Measurements shared by the scenes' probes, all taken between steps (never inside the timed loop).

#include "sim.hpp"

#include <span>

namespace bench {

/// The largest overlap, in metres, between any two balls (all of `radius`) or a ball and a
/// static line; 0 when nothing overlaps. Sort-and-sweep on x, so the 1000-ball pile stays cheap.
double largestOverlap(const Sim& sim, double radius, std::span<const LineSpec> lines);

/// Kinetic plus potential energy per unit mass and gravity, in metres: E / (m g) = y + v^2 / 2g,
/// so an energy error reads as a height (the "1e-9 m").
double energyHeight(const BallState& ball, double gravity);

} // namespace bench
