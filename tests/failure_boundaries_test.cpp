// The boundaries theory predicts for "where methods fail" (issue 6), asserted on the very probes
// the bench's failure table is made from (bench/failures/), so the table and the tests cannot drift.
#include "failure_sweep.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <utility>

using bench::failures::Outcome;
using rube::Method;

namespace {

// The speed axis is speed x dt / r against a thin line (radius 0): a discrete step jumps the ball
// from wholly above the line to wholly below it only when it travels more than 2r (lecture 5).
constexpr double kThinLineThreshold = 2.0;

} // namespace

TEST_CASE("failures: discrete never tunnels through a thin static line below speed x dt = 2r", "[failures][tunnel]") {
    for (const double ratio : {0.1, 0.5, 1.0, 1.5, 1.9, 1.99, 1.999}) {
        INFO("speed x dt / r = " << ratio);
        // 1000 start phases spread over one step's travel: every way the crossing step can fall.
        const Outcome out = bench::failures::speedProbe(Method::discrete, ratio, 1000);
        CHECK_FALSE(out.tunnels);
        CHECK_FALSE(out.failed());
    }
}

TEST_CASE("failures: discrete tunnels through a thin static line above speed x dt = 2r", "[failures][tunnel]") {
    // The share of phases that tunnel is (v dt - 2r) / v dt: 0.5 % at 2.01 r, so 1000 phases find it.
    for (const double ratio : {2.01, 2.1, 3.0, 10.0, 100.0, 1e4}) {
        INFO("speed x dt / r = " << ratio);
        CHECK(bench::failures::speedProbe(Method::discrete, ratio, 1000).tunnels);
    }
}

TEST_CASE("failures: exact, solver and turn-based never tunnel at any speed tested", "[failures][tunnel]") {
    // Continuous detection (the time of impact, lecture 3; the solver's sweep for fast bodies) finds
    // the line wherever the step would end, up to speed x dt = 10,000 r (30 km/s for the 0.05 m ball).
    for (const Method method : {Method::exact, Method::solver, Method::turnBased}) {
        for (const double ratio : {0.5, 1.99, 2.01, 3.0, 10.0, 100.0, 1000.0, 1e4}) {
            INFO(rube::methodName(method) << ", speed x dt / r = " << ratio);
            CHECK_FALSE(bench::failures::speedProbe(method, ratio, 1000).tunnels);
        }
    }
}

TEST_CASE("failures: the table's first tunnelling speed for discrete is the first value tried past 2r",
          "[failures][table]") {
    const auto axes = bench::failures::failureAxes();
    const auto& speeds = axes.front().values;
    REQUIRE(axes.front().name == "speed x dt / r");
    const double firstPast = *std::find_if(speeds.begin(), speeds.end(),
                                           [](double v) { return v > kThinLineThreshold; });

    const bench::failures::Sweep sweep = bench::failures::runSweep(false);
    REQUIRE(sweep.methods.front() == Method::discrete);
    const auto first = sweep.cells[0][0].firstFailure();
    REQUIRE(first.has_value());
    CHECK(first->first == firstPast);
    CHECK(first->second.tunnels);
    // And the methods with continuous detection hold the whole speed axis.
    for (std::size_t m = 1; m < sweep.methods.size(); ++m) {
        INFO(rube::methodName(sweep.methods[m]));
        for (const auto& [value, outcome] : sweep.cells[m][0].tried) CHECK_FALSE(outcome.tunnels);
    }
}

TEST_CASE("failures: the exact method never gains energy with C <= 1 and keeps a tall stack apart",
          "[failures][exact]") {
    // Lecture 3: v' = u - C (v - u) with C <= 1 can only lose kinetic energy, and motion under gravity
    // is integrated exactly, so no drop of any bounciness may end with more energy than it began with.
    for (const double c : {0.0, 0.5, 0.9, 1.0}) {
        INFO("C = " << c);
        const Outcome out = bench::failures::bouncinessProbe(Method::exact, c);
        CHECK_FALSE(out.gainsEnergy);
        CHECK(out.energyGain < 1e-9);
    }
    // Resting contact is a projection: touching balls never overlap beyond round-off.
    const Outcome stack = bench::failures::stackProbe(Method::exact, 32);
    CHECK_FALSE(stack.failed());
    CHECK(stack.deepestOverlap < 1e-9);
}

TEST_CASE("failures: a probe reports what it sees: a discrete stack ends its steps overlapping",
          "[failures][discrete]") {
    // The discrete method moves every ball under gravity, then pushes each overlap apart once, in
    // index order: pushing a pair apart sends the lower ball back into the floor, and no second pass
    // looks again, so a stack of two or more ends each step overlapping (5 to 6 % of r at dt = 1/60).
    const Outcome out = bench::failures::stackProbe(Method::discrete, 8);
    CHECK(out.overlaps);
    CHECK(out.deepestOverlap > bench::failures::kOverlapTolerance);
    CHECK_FALSE(bench::failures::stackProbe(Method::discrete, 1).failed()); // one ball on a line holds
}

TEST_CASE("failures: a discrete stack sinks through a static floor from a height that grows with the step rate",
          "[failures][discrete][floor]") {
    // Lecture 5's first method pushes each overlap apart once: the pushes of the balls above add up
    // on the bottom ball, and from some height they drive it past the floor's line. Measured boundary
    // (r = 0.2 m, 5 s): 6 balls at 30 Hz, 8 at 60, 11 at 120, 17 at 240; one ball fewer always holds.
    const std::pair<double, int> boundaries[] = {{30.0, 6}, {60.0, 8}, {120.0, 11}, {240.0, 17}};
    for (const auto& [hz, height] : boundaries) {
        INFO(hz << " Hz, " << height << " balls");
        CHECK(bench::failures::floorStackProbe(Method::discrete, height, 1.0 / hz).sinks);
        CHECK_FALSE(bench::failures::floorStackProbe(Method::discrete, height - 1, 1.0 / hz).sinks);
    }
    // Far below the tunnelling speed: a column of 10 sinks while its bottom ball moves well under 2r / dt.
    CHECK(bench::failures::floorStackProbe(Method::discrete, 10).sinks);
    // Continuous detection and resting contact hold the same columns.
    for (const Method method : {Method::turnBased, Method::exact})
        CHECK_FALSE(bench::failures::floorStackProbe(method, 32).sinks);
}

TEST_CASE("failures: turn-based and exact slide on every incline and come to rest in every V", "[failures][incline]") {
    for (const Method method : {Method::turnBased, Method::exact}) {
        for (const double degrees : {0.01, 0.05, 0.12, 1.0, 30.0, 60.0}) {
            INFO(rube::methodName(method) << ", incline " << degrees);
            CHECK_FALSE(bench::failures::inclineProbe(method, degrees).failed());
        }
    }
    for (const double halfAngle : {5.0, 30.0, 60.0, 80.0}) {
        INFO("V half-angle " << halfAngle);
        CHECK_FALSE(bench::failures::vProbe(Method::exact, halfAngle).failed());
        CHECK_FALSE(bench::failures::vProbe(Method::turnBased, halfAngle).failed());
    }
    // The discrete method's push-outs leave a ball in a V short of rest.
    CHECK(bench::failures::vProbe(Method::discrete, 30.0).sinks);
}

TEST_CASE("failures: a bounce off a line cap leaves along the exact reflection under exact and turn-based",
          "[failures][impact]") {
    for (const double speed : {0.1, 1.0, 10.0, 100.0}) {
        INFO("impact speed " << speed << " m/s");
        for (const Method method : {Method::exact, Method::turnBased}) {
            const Outcome out = bench::failures::capBounceProbe(method, speed);
            CHECK(out.directionError < 1e-5);
        }
    }
    // Discrete reflects about the normal where the step ends, not where they met: off by degrees at 2 m/s.
    CHECK(bench::failures::capBounceProbe(Method::discrete, 2.0).directionError > 0.5);
}
