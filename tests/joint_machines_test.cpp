// Joints that make machines go, each against its formula at 60 Hz under the solver (issue 21):
// gears (angle1 + ratio angle2 constant), belts (same sense, ratio of radii), pulleys (the Atwood
// machine's a = g (m2 - m1) / (m1 + m2), the rope's length, a slack rope) and motors (target speed,
// alpha <= tau_max / I). Which methods carry joints: the solver, auto (which gives their islands to
// it); the others refuse.
#include "joint_test_world.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

using namespace rube;
using test::hinge;
using test::jointWorld;
using test::wheel;

namespace {

struct GearRun {
    double worstError = 0.0; // |angle2 - expected(angle1)| over the run, rad
    double turned = 0.0;     // |angle1| at the end, rad
};

// Wheel 1 (a circle) driven by a motor, wheel 2 (a box, or a circle) coupled to it by a gear of
// `ratio`: angle1 + ratio angle2 stays 0, so angle2 = -angle1 / ratio.
GearRun runGear(double ratio, bool boxWheel, Method method, double seconds) {
    World world = jointWorld({0.0, -9.81}, method);
    const JointEnd w1 = wheel(world, {0.0, 0.0}, 0.5, 1.0);
    const JointEnd w2 = boxWheel ? test::bar(world, {3.0, 0.0}, {0.4, 0.4}, 2.0)
                                 : wheel(world, {3.0, 0.0}, 0.5 * std::abs(ratio), 1.0);
    const JointId j1 = hinge(world, w1, {0.0, 0.0}, 3.0, 50.0);
    const JointId j2 = hinge(world, w2, {3.0, 0.0});
    JointDef gear;
    gear.kind = JointKind::gear;
    gear.jointA = j1;
    gear.jointB = j2;
    gear.ratio = ratio;
    world.addJoint(gear);
    GearRun run;
    const int steps = static_cast<int>(std::lround(seconds * 60));
    for (int s = 0; s < steps; ++s) {
        world.step();
        const double a1 = world.jointCoordinate(j1), a2 = world.jointCoordinate(j2);
        run.worstError = std::max(run.worstError, std::abs(a2 + a1 / ratio));
        run.turned = std::abs(a1);
    }
    return run;
}

} // namespace

TEST_CASE("joints: a gear keeps angle2 = -angle1 / ratio within 1e-6 rad over 10 s", "[joints][gear]") {
    const double ratio = GENERATE(1.0 / 3.0, 1.0, 2.5, -0.75);
    const bool boxWheel = GENERATE(false, true);
    const GearRun run = runGear(ratio, boxWheel, Method::solver, 10.0);
    INFO("ratio " << ratio << (boxWheel ? " box" : " circle") << ": worst " << run.worstError << " rad");
    CHECK(run.turned > 20.0); // the motor turned it (3 rad/s for most of 10 s)
    CHECK(run.worstError < 1e-6);
}

TEST_CASE("joints: a belt turns both wheels the same way at the ratio of their radii", "[joints][gear]") {
    // A belt is a gear of ratio -r2 / r1: the rims move together, r1 angle1 = r2 angle2.
    const double r2 = GENERATE(0.25, 0.5, 1.5);
    const double r1 = 0.5;
    World world = jointWorld();
    const JointEnd w1 = wheel(world, {0.0, 0.0}, r1, 1.0), w2 = wheel(world, {4.0, 1.0}, r2, 2.0);
    const JointId j1 = hinge(world, w1, {0.0, 0.0}, -2.0, 40.0), j2 = hinge(world, w2, {4.0, 1.0});
    JointDef belt;
    belt.kind = JointKind::gear;
    belt.jointA = j1;
    belt.jointB = j2;
    belt.ratio = -r2 / r1;
    world.addJoint(belt);
    double worst = 0.0;
    for (int s = 0; s < 600; ++s) {
        world.step();
        const double a1 = world.jointCoordinate(j1), a2 = world.jointCoordinate(j2);
        worst = std::max(worst, std::abs(a2 - a1 * r1 / r2));
    }
    INFO("r2 " << r2 << ": worst " << worst);
    CHECK(worst < 1e-6);
    CHECK(world.jointCoordinate(j1) < -15.0);
    CHECK(world.jointCoordinate(j2) * world.jointCoordinate(j1) > 0.0); // the same sense
}

TEST_CASE("joints: rack and pinion turns a wheel's angle into a slide", "[joints][gear]") {
    World world = jointWorld({0.0, 0.0});
    const JointEnd pinion = wheel(world, {0.0, 0.0}, 0.5, 1.0);
    const JointEnd rack = test::bar(world, {0.0, -0.7}, {1.0, 0.1}, 1.0);
    const JointId turn = hinge(world, pinion, {0.0, 0.0}, 2.0, 20.0);
    JointDef slide = test::jointAt(world, JointKind::prismatic, JointEnd{}, {0.0, -0.7}, rack, {0.0, -0.7});
    const JointId slider = world.addJoint(slide);
    JointDef gear;
    gear.kind = JointKind::gear;
    gear.jointA = turn;
    gear.jointB = slider;
    gear.ratio = 1.0 / 0.5; // angle + slide / r = 0: the rack moves at the rim's speed
    world.addJoint(gear);
    double worst = 0.0;
    for (int s = 0; s < 300; ++s) {
        world.step();
        worst = std::max(worst, std::abs(world.jointCoordinate(turn) * 0.5 + world.jointCoordinate(slider)));
    }
    CHECK(worst < 1e-6);
    CHECK(world.jointCoordinate(slider) < -4.0); // 1 m/s for 5 s, less the spin-up
}

namespace {

struct Atwood {
    World world = jointWorld();
    JointEnd light, heavy;
    JointId rope;
};

// Boxes of m1 and m2 hanging 500 m below their ground points, the rope taut (or `slack` m longer):
// in 10 s the light one rises at most g t^2 / 2 = 490 m.
void buildAtwood(Atwood& at, double m1, double m2, double slack) {
    at.light = test::bar(at.world, {-1.0, 0.0}, {0.2, 0.2}, m1);
    at.heavy = test::bar(at.world, {1.0, 0.0}, {0.2, 0.2}, m2);
    JointDef d;
    d.kind = JointKind::pulley;
    d.a = at.light;
    d.b = at.heavy;
    d.groundA = {-1.0, 500.0};
    d.groundB = {1.0, 500.0};
    d.length = 1000.0 + slack;
    at.rope = at.world.addJoint(d);
}

} // namespace

TEST_CASE("joints: an Atwood machine accelerates at g (m2 - m1) / (m1 + m2), its rope's length kept",
          "[joints][pulley]") {
    const double m1 = 1.0, m2 = GENERATE(3.0, 1.5, 10.0);
    Atwood at;
    buildAtwood(at, m1, m2, 0.0);
    const double expected = 9.81 * (m2 - m1) / (m1 + m2);
    double worstLength = 0.0, worstAcceleration = 0.0;
    for (int s = 1; s <= 600; ++s) {
        at.world.step();
        worstLength = std::max(worstLength, std::abs(at.world.jointCoordinate(at.rope) - 1000.0));
        if (s % 60 == 0) {
            // v = a t from rest: the light box rises, the heavy one falls.
            const double t = s / 60.0;
            const double up = at.world.body(at.light.body).velocity.y, down = -at.world.body(at.heavy.body).velocity.y;
            worstAcceleration = std::max(
                {worstAcceleration, std::abs(up / t - expected) / expected, std::abs(down / t - expected) / expected});
        }
    }
    INFO("m2 " << m2 << ": length error " << worstLength << " m, acceleration error " << worstAcceleration);
    CHECK(worstAcceleration < 0.005);
    CHECK(worstLength < 1e-6);
}

TEST_CASE("joints: a slack pulley rope does not pull, and it catches when taut", "[joints][pulley]") {
    Atwood at;
    buildAtwood(at, 1.0, 3.0, 1.0);               // 1 m of slack: both fall freely until the rope is taut
    for (int s = 0; s < 12; ++s) at.world.step(); // 0.2 s: each falls 0.196 m, the rope shortens by 0.39 m
    const double t = 0.2;
    CHECK(at.world.body(at.light.body).velocity.y == Approx(-9.81 * t).epsilon(1e-9));
    CHECK(at.world.body(at.heavy.body).velocity.y == Approx(-9.81 * t).epsilon(1e-9));
    double longest = 0.0;
    for (int s = 0; s < 240; ++s) {
        at.world.step();
        longest = std::max(longest, at.world.jointCoordinate(at.rope));
    }
    CHECK(longest < 1001.0 + 1e-3);                       // it caught them
    CHECK(at.world.body(at.light.body).velocity.y > 0.0); // and the heavy side now lifts the light one
}

TEST_CASE("joints: a motor reaches its speed no faster than tau_max / I allows", "[joints][motor]") {
    const double target = GENERATE(10.0, -4.0);
    const double maxTorque = GENERATE(2.0, 0.5);
    // A disc of 1 kg and radius 1 m: I = m r^2 / 2 = 0.5 kg m^2.
    World world = jointWorld();
    const JointEnd w = wheel(world, {0.0, 0.0}, 1.0, 1.0);
    hinge(world, w, {0.0, 0.0}, target, maxTorque);
    const double alpha = maxTorque / 0.5, dt = 1.0 / 60;
    double previous = 0.0, worstAlpha = 0.0;
    const int steps = static_cast<int>(std::ceil(std::abs(target) / alpha * 60)) + 60;
    for (int s = 0; s < steps; ++s) {
        world.step();
        const double omega = world.circle(w.circle).angularVelocity;
        worstAlpha = std::max(worstAlpha, std::abs(omega - previous) / dt);
        previous = omega;
        if (s + 1 == 60) CHECK(std::abs(omega) == Approx(std::min(alpha, std::abs(target))).epsilon(0.01));
    }
    INFO("target " << target << " tau " << maxTorque << ": worst alpha " << worstAlpha << " of " << alpha);
    CHECK(worstAlpha <= alpha * 1.01);
    CHECK(previous == Approx(target).epsilon(0.01));
}

TEST_CASE("joints: the solver and auto carry joints, and discrete, turn-based and exact refuse them", "[joints]") {
    for (const Method method : {Method::discrete, Method::turnBased, Method::exact}) {
        World world = jointWorld({0.0, -9.81}, method);
        hinge(world, wheel(world, {0.0, 0.0}, 0.5, 1.0), {0.0, 0.0}, 1.0, 1.0);
        CHECK_THROWS_AS(world.step(), std::logic_error);
    }
    // auto gives a wholly jointed world to the solver: the same steps, bit for bit.
    const GearRun solver = runGear(2.5, true, Method::solver, 2.0),
                  automatic = runGear(2.5, true, Method::automatic, 2.0);
    CHECK(solver.turned == automatic.turned);
    CHECK(solver.worstError == automatic.worstError);
}

TEST_CASE("joints: auto hands a jointed island to the solver and runs a far ball exactly", "[joints]") {
    // A ball bouncing on its own floor far from a motor-driven gear pair: under auto the ball is the
    // exact method's, step for step bit-identical to the ball alone under exact; the gears the solver's.
    const auto addBall = [](World& world) {
        SegmentDef floor;
        floor.a = {40.0, 0.0};
        floor.b = {60.0, 0.0};
        world.addSegment(floor);
        CircleDef ball;
        ball.position = {50.0, 3.0};
        ball.velocity = {1.0, 0.0};
        ball.radius = 0.25;
        return world.addCircle(ball);
    };
    World alone = jointWorld({0.0, -9.81}, Method::exact);
    const CircleId lone = addBall(alone);
    World machine = jointWorld({0.0, -9.81}, Method::automatic);
    const CircleId ball = addBall(machine);
    const JointEnd w1 = wheel(machine, {0.0, 0.0}, 0.5, 1.0), w2 = wheel(machine, {2.0, 0.0}, 1.5, 1.0);
    const JointId j1 = hinge(machine, w1, {0.0, 0.0}, 3.0, 50.0), j2 = hinge(machine, w2, {2.0, 0.0});
    JointDef gear;
    gear.kind = JointKind::gear;
    gear.jointA = j1;
    gear.jointB = j2;
    gear.ratio = 3.0;
    machine.addJoint(gear);
    int bounces = 0;
    double worstGear = 0.0;
    for (int s = 0; s < 300; ++s) {
        alone.step();
        machine.step();
        bounces += static_cast<int>(alone.lastImpacts().size());
        REQUIRE(machine.circle(ball).position.x == alone.circle(lone).position.x);
        REQUIRE(machine.circle(ball).position.y == alone.circle(lone).position.y);
        REQUIRE(machine.circle(ball).velocity.y == alone.circle(lone).velocity.y);
        worstGear = std::max(worstGear, std::abs(machine.jointCoordinate(j2) + machine.jointCoordinate(j1) / 3.0));
    }
    CHECK(bounces >= 2);
    CHECK(worstGear < 1e-6);
    CHECK(machine.jointCoordinate(j1) > 10.0);
    CHECK(machine.stats().exactBodySteps > 0);
    CHECK(machine.stats().solverBodySteps > 0);
}

TEST_CASE("joints: handles: removing a body removes its joints and the gears on them", "[joints]") {
    World world = jointWorld();
    const JointEnd w1 = wheel(world, {0.0, 0.0}, 0.5, 1.0), w2 = wheel(world, {2.0, 0.0}, 0.5, 1.0);
    const JointId j1 = hinge(world, w1, {0.0, 0.0}), j2 = hinge(world, w2, {2.0, 0.0});
    JointDef gear;
    gear.kind = JointKind::gear;
    gear.jointA = j1;
    gear.jointB = j2;
    const JointId g = world.addJoint(gear);
    CHECK(world.joints().size() == 3);
    world.setEnabled(w2.circle, false); // its hinge waits, and the gear with it
    CHECK(world.joints().size() == 1);
    CHECK(world.slot(g) == -1);
    world.setEnabled(w2.circle, true);
    CHECK(world.joints().size() == 3);
    CHECK(world.slot(g) == 2);
    world.remove(w1.circle);
    CHECK_FALSE(world.isValid(j1));
    CHECK_FALSE(world.isValid(g));
    CHECK(world.isValid(j2));
    CHECK(world.joints().size() == 1);
    CHECK_THROWS_AS(world.joint(g), std::invalid_argument);
    JointDef same = test::jointAt(world, JointKind::revolute, w2, {2.0, 0.0}, w2, {2.0, 0.0});
    CHECK_THROWS_AS(world.addJoint(same), std::invalid_argument);
}
