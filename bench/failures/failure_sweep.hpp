#pragma once
/// The failure sweep: every failure probe over its axis on each of rube's methods, and the first
/// value where each method fails, written as the Markdown table bench/results/failures.md.

#include "failure_probes.hpp"

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace bench::failures {

/// One axis of the sweep: what is varied, over which values (easiest first), and its probe.
struct Axis {
    std::string name;           ///< the column heading, e.g. "speed x dt / r"
    std::string scene;          ///< what the probe sets up, for the table's notes
    std::vector<double> values; ///< in the order tried: the first failing one is reported
    Outcome (*probe)(rube::Method, double value, bool quick);
};

/// One method on one axis: the outcome at every value tried.
struct Cell {
    std::vector<std::pair<double, Outcome>> tried;
    /// The first value tried that failed, if any.
    std::optional<std::pair<double, Outcome>> firstFailure() const;
};

/// The whole sweep: cells[method][axis], methods in rube's order (discrete, turn-based, exact, solver).
struct Sweep {
    std::vector<rube::Method> methods;
    std::vector<Axis> axes;
    std::vector<std::vector<Cell>> cells;
};

/// The axes (speed, stack height, step rate, mass ratio, bounciness, incline, V half-angle, impact
/// speed, stack on a floor); --quick tries fewer speed phases.
std::vector<Axis> failureAxes();

/// Runs every axis on every method; `quick` checks the sweep runs, with fewer phases per speed.
Sweep runSweep(bool quick);

/// The table: one row per method, one column per axis, each cell "first failing value: failures"
/// or "holds to the last value"; then every value tried, for the record.
void writeMarkdown(std::ostream& out, const Sweep& sweep, const std::string& command);

} // namespace bench::failures
