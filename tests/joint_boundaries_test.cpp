// The joints' failure axes (issue 21), asserted on the very probes the bench's failure table is made
// from (bench/failures/joint_probes.cpp): where each holds follows from how the solver carries it.
#include "joint_probes.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace bench::failures;
using rube::Method;

TEST_CASE("joint probes: discrete, turn-based and exact refuse joints, and the solver and auto carry them",
          "[failures][joints]") {
    for (const Method m : {Method::discrete, Method::turnBased, Method::exact}) {
        CHECK(chainProbe(m, 1.0).refused);
        CHECK(motorProbe(m, 2.0).refused);
        CHECK(springProbe(m, 100.0).refused == (m != Method::exact));
    }
    // Exact follows the spring probe's ball on its closed form: its energy to round-off at any
    // stiffness, where the solver's velocity Verlet gives way past omega h = 0.5.
    for (const double k : {100.0, 1e4, 1e5, 1e7}) {
        const Outcome exact = springProbe(Method::exact, k);
        INFO("k " << k << ": energy off by " << exact.jointError);
        CHECK_FALSE(exact.failed());
        CHECK(exact.jointError < 1e-9);
    }
    for (const Method m : {Method::solver, Method::automatic}) {
        CHECK_FALSE(chainProbe(m, 10.0).failed());
        CHECK_FALSE(springProbe(m, 100.0).failed());
    }
}

TEST_CASE("joint probes: a motor's clamp follows alpha = (tau - M g r) / I_eff on both sides of its load",
          "[failures][joints]") {
    // Below its load the motor is dragged back, above it lifts; the clamp at tau h a substep makes
    // both exact, however strong the motor.
    for (const double ratio : {0.25, 0.9, 1.1, 5.0, 1000.0}) {
        const Outcome out = motorProbe(Method::solver, ratio);
        INFO("tau / load " << ratio << ": off by " << out.jointError);
        CHECK_FALSE(out.failed());
    }
}

TEST_CASE("joint probes: a spring keeps its energy while omega h is small, and loses it past velocity Verlet's bound",
          "[failures][joints]") {
    // Velocity Verlet's energy error is about (omega h)^2 / 4, h = 1/480 s: 1 % at omega h = 0.2,
    // k = (0.2 x 480)^2 = 9216 N/m for 1 kg; past omega h = 0.5 (k = 57,600) the implicit spring loses it.
    CHECK_FALSE(springProbe(Method::solver, 3000.0).failed());
    const Outcome verlet = springProbe(Method::solver, 1e4);
    CHECK(verlet.losesEnergy);
    CHECK(verlet.jointError < 0.02);
    const Outcome implicit = springProbe(Method::solver, 1e5);
    CHECK(implicit.losesEnergy);
    CHECK(implicit.jointError > 0.5);
    CHECK_FALSE(implicit.nonFinite);
}
