// The failure sweep and its Markdown table. Every axis is tried in full on every method, so the
// table shows not only the first failure but also whether a method recovers past it.

#include "failure_sweep.hpp"

#include "joint_probes.hpp"

#include <cstdio>
#include <ostream>

namespace bench::failures {
namespace {

// 1000 start offsets per speed find the discrete method's tunnels just past 2r, where the share
// that tunnels is (v dt - 2r) / v dt: 0.5 % at 2.01 r (see the README's tunnelling figures).
Outcome speed(rube::Method m, double v, bool quick) { return speedProbe(m, v, quick ? 100 : 1000); }
Outcome stack(rube::Method m, double v, bool) { return stackProbe(m, static_cast<int>(v)); }
// The time step as its rate, finest first, so the first failure is where the step grows too coarse.
constexpr int kStackForTimeStep = 16;
Outcome stepRate(rube::Method m, double hz, bool) { return stackProbe(m, kStackForTimeStep, 1.0 / hz); }
Outcome mass(rube::Method m, double v, bool) { return massRatioProbe(m, v); }
Outcome bounce(rube::Method m, double v, bool) { return bouncinessProbe(m, v); }
Outcome incline(rube::Method m, double v, bool) { return inclineProbe(m, v); }
Outcome vee(rube::Method m, double v, bool) { return vProbe(m, v); }
Outcome impact(rube::Method m, double v, bool) { return capBounceProbe(m, v); }
Outcome floorStack(rube::Method m, double v, bool) { return floorStackProbe(m, static_cast<int>(v)); }
Outcome chain(rube::Method m, double v, bool) { return chainProbe(m, v); }
Outcome motor(rube::Method m, double v, bool) { return motorProbe(m, v); }
Outcome spring(rube::Method m, double v, bool) { return springProbe(m, v); }

std::string number(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
}

std::string cellText(const Cell& cell) {
    if (const auto first = cell.firstFailure()) return "**" + number(first->first) + "**: " + first->second.describe();
    return "holds to " + number(cell.tried.back().first);
}

} // namespace

std::optional<std::pair<double, Outcome>> Cell::firstFailure() const {
    for (const auto& t : tried)
        if (t.second.failed()) return t;
    return std::nullopt;
}

std::vector<Axis> failureAxes() {
    return {
        {"speed x dt / r",
         "a 0.05 m ball at a thin static line, no gravity, C = 1, 1000 start phases",
         {0.5, 1, 1.5, 1.9, 1.99, 2.01, 2.1, 3, 10, 100, 1000, 10000},
         speed},
        {"stack height",
         "a column of touching balls (r = 0.1 m, C = 0) on a floor, 2 s",
         {1, 2, 4, 8, 16, 32, 64, 128, 256},
         stack},
        {"step rate, Hz",
         "a column of 16 touching balls (r = 0.1 m, C = 0) on a floor, 2 s, at dt = 1 / rate",
         {960, 480, 240, 120, 60, 30, 15},
         stepRate},
        {"mass ratio",
         "a heavy ball on a 1 kg ball on a floor (r = 0.1 m, C = 0), 2 s",
         {1, 3, 10, 30, 100, 1000, 1e4, 1e5, 1e6},
         mass},
        {"bounciness C",
         "4 balls (r = 0.1 m) dropped in a column with 0.1 m gaps onto a floor, 3 s",
         {0, 0.25, 0.5, 0.75, 0.9, 0.95, 1},
         bounce},
        {"incline, degrees",
         "a frictionless ball (r = 0.25 m) at rest on a tilted line, 10 s: *sinks* here means it froze or "
         "slid off x = g sin(theta) t^2 / 2 by more than 1 %",
         {0.01, 0.05, 0.12, 0.5, 1, 5, 15, 30, 45, 60},
         incline},
        {"V half-angle, degrees",
         "a ball (r = 0.25 m, C = 0.3) dropped 0.1 m into a V of two lines, 5 s: *sinks* here means it "
         "did not come to rest touching both (1e-9 m, 1e-9 m/s)",
         {5, 10, 15, 20, 30, 45, 60, 70, 75, 80},
         vee},
        {"impact speed, m/s",
         "a ball (r = 0.25 m, C = 1, no gravity) striking a line's cap at half its radius off centre: "
         "fails when it leaves more than 0.5 degrees off the exact reflection",
         {0.1, 0.5, 1, 2, 5, 10, 20, 50, 100},
         impact},
        {"stack on a floor",
         "a column of touching balls (r = 0.2 m, C = 0) on a floor, 5 s: only the bottom ball crossing "
         "the floor counts",
         {1, 2, 4, 6, 8, 10, 12, 16, 24, 32},
         floorStack},
        {"chain mass ratio",
         "a chain of 10 capsule links of 1 kg (0.5 m) on hinges from a pin, laid level, a box of ratio x 1 kg "
         "hinged to its end, 3 s: *stretches* when its hinges open by more than 1 % of its 5 m",
         {1, 3, 10, 30, 100, 300, 1000, 1e4},
         chain},
        {"motor torque / load",
         "a disc (r = 0.5 m, 1 kg) with a motor at 2 rad/s whose torque is this many times the load M g r of a "
         "1 kg rack it lifts through a gear: omega(t) = (tau - M g r) t / (I + M r^2) up to 2 rad/s, within 1 % "
         "at 0.25 and 0.5 s",
         {0.25, 0.5, 0.9, 1.1, 2, 5, 20, 100, 1000},
         motor},
        {"spring k, N/m",
         "a 1 kg ball on an undamped spring stretched 0.1 m, no gravity, 5 s at dt = 1/60 s (8 substeps of h = "
         "1/480 s; omega h = sqrt(k) / 480): its energy within 1 %",
         {10, 100, 1000, 3000, 1e4, 3e4, 1e5, 1e6, 1e7},
         spring},
    };
}

Sweep runSweep(bool quick) {
    Sweep sweep;
    sweep.methods = {rube::Method::discrete, rube::Method::turnBased, rube::Method::exact, rube::Method::solver,
                     rube::Method::automatic};
    sweep.axes = failureAxes();
    for (const rube::Method method : sweep.methods) {
        auto& row = sweep.cells.emplace_back();
        for (const Axis& axis : sweep.axes) {
            Cell& cell = row.emplace_back();
            for (const double value : axis.values) cell.tried.emplace_back(value, axis.probe(method, value, quick));
        }
    }
    return sweep;
}

void writeMarkdown(std::ostream& out, const Sweep& sweep, const std::string& command) {
    out << "# Where rube's methods fail\n\n"
        << "Generated by `" << command << "` (bench/failures/); do not edit by hand.\n\n"
        << "Each cell is the first value of the axis, tried from left to right in the order below, at which the\n"
        << "method fails, and how: it *tunnels* (ends past a line it came at), *sinks* (a resting ball passes\n"
        << "through the floor or the ball beneath it), overlaps by more than 5 % of a radius after a step, gains\n"
        << "more than 1 % energy (C <= 1 may only lose it), or hits the event cap (4096 impacts in a step); on\n"
        << "the joints' axes it *refuses joints* (only the solver carries them), *stretches* (a chain's hinges\n"
        << "open), *misses its formula* (a motor) or *loses energy* (an undamped spring).\n"
        << "Every method runs at dt = 1/60 s (but on the step-rate axis) with `WorldDef`'s defaults.\n\n";
    out << "| method |";
    for (const Axis& axis : sweep.axes) out << ' ' << axis.name << " |";
    out << "\n|---|";
    for (std::size_t a = 0; a < sweep.axes.size(); ++a) out << "---|";
    out << '\n';
    for (std::size_t m = 0; m < sweep.methods.size(); ++m) {
        out << "| " << rube::methodName(sweep.methods[m]) << " |";
        for (const Cell& cell : sweep.cells[m]) out << ' ' << cellText(cell) << " |";
        out << '\n';
    }
    out << "\n## The axes\n\n";
    for (const Axis& axis : sweep.axes) {
        out << "- **" << axis.name << "**: " << axis.scene << "; tried:";
        for (const double v : axis.values) out << ' ' << number(v);
        out << '\n';
    }
    out << "\n## Every value tried\n\n"
        << "`ok`, or the failures; in brackets the deepest overlap (fraction of r) and the largest energy gain\n"
        << "(relative) seen, up to the first failing step, where a run stops (over every start phase that held, for "
           "speed).\n";
    for (std::size_t a = 0; a < sweep.axes.size(); ++a) {
        out << "\n### " << sweep.axes[a].name << "\n\n| method |";
        for (const double v : sweep.axes[a].values) out << ' ' << number(v) << " |";
        out << "\n|---|";
        for (std::size_t v = 0; v < sweep.axes[a].values.size(); ++v) out << "---|";
        out << '\n';
        for (std::size_t m = 0; m < sweep.methods.size(); ++m) {
            out << "| " << rube::methodName(sweep.methods[m]) << " |";
            for (const auto& [value, outcome] : sweep.cells[m][a].tried) {
                char detail[64];
                if (outcome.refused) detail[0] = '\0';
                else if (outcome.jointError >= 0.0) std::snprintf(detail, sizeof detail, " (%.2g)", outcome.jointError);
                else if (outcome.directionError >= 0.0)
                    std::snprintf(detail, sizeof detail, " (%.2g deg)", outcome.directionError);
                else std::snprintf(detail, sizeof detail, " (%.2g, %.2g)", outcome.deepestOverlap, outcome.energyGain);
                out << ' ' << (outcome.failed() ? outcome.describe() : "ok") << detail << " |";
            }
            out << '\n';
        }
    }
}

} // namespace bench::failures
