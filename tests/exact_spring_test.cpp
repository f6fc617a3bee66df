// The exact method's springs (issue 21): a circle on a spring to a fixed point moves on the damped
// oscillator's closed form, so over 100 periods at 60 Hz its period, energy and damped envelope stay
// to 1e-9 of the formulas, and an impact on it comes at the analytic root of x_eq + A cos(omega t) =
// the floor. Where there is no closed form the exact method refuses and names why, and auto gives
// the island to the solver. The references below are written independently of the method's: the
// amplitude-phase form from t = 0, not the method's step-by-step composition.
#include "joint_test_world.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace rube;
using test::jointWorld;
using test::kPi;

namespace {

struct SpringCase {
    double mass = 1.0;
    double k = 100.0;
    double c = 0.0;
    double restLength = 0.0;
    Vec2 anchor{0.0, 0.0};
    Vec2 position{1.0, 0.0};
    Vec2 velocity{};
    Vec2 gravity{};
    Method method = Method::exact;
};

struct SpringWorld {
    World world;
    CircleId ball;
    JointId spring;
};

SpringWorld makeSpring(const SpringCase& s) {
    SpringWorld w{jointWorld(s.gravity, s.method), {}, {}};
    CircleDef ball;
    ball.position = s.position;
    ball.velocity = s.velocity;
    ball.radius = 0.1;
    ball.mass = s.mass;
    ball.material.bounciness = 1.0;
    w.ball = w.world.addCircle(ball);
    JointDef d;
    d.kind = JointKind::spring;
    d.localAnchorA = s.anchor; // a is the world: the fixed point
    d.b = JointEnd{w.ball, {}};
    d.restLength = s.restLength;
    d.stiffness = s.k;
    d.damping = s.c;
    w.spring = w.world.addJoint(d);
    return w;
}

// Spring, kinetic and gravity's energy: E = m |v|^2 / 2 + k (|d| - L0)^2 / 2 - m g . p.
double energy(const SpringWorld& w, const SpringCase& s) {
    const Circle& c = w.world.circle(w.ball);
    const double stretch = (c.position - s.anchor).length() - s.restLength;
    return 0.5 * s.mass * c.velocity.lengthSquared() + 0.5 * s.k * stretch * stretch -
           s.mass * s.gravity.dot(c.position);
}

// The equilibrium: anchor + L0 n + m g / k (n along the spring for a rest length).
Vec2 equilibrium(const SpringCase& s) {
    const Vec2 n = (s.position - s.anchor).normalized();
    return s.anchor + n * s.restLength + s.gravity * (s.mass / s.k);
}

} // namespace

TEST_CASE("exact spring: an undamped oscillator keeps its period and energy to 1e-9 over 100 periods",
          "[exact][joints][spring]") {
    // 2-D isotropic (rest length 0: an ellipse about x_eq = m g / k) over masses, stiffnesses,
    // amplitudes and gravities; and along the line for a rest length (a hanging spring).
    int cases = 0;
    double worstPeriod = 0.0, worstEnergyAll = 0.0, worstPosition = 0.0;
    for (const double mass : {0.5, 1.0, 3.0})
        for (const double k : {10.0, 100.0, 2000.0})
            for (const double amplitude : {0.05, 1.0})
                for (const Vec2 gravity : {Vec2{0.0, 0.0}, Vec2{0.0, -9.81}, Vec2{3.0, -25.0}})
                    for (const bool line : {false, true}) {
                        if (line && gravity.x != 0.0) continue; // a line spring hangs along gravity
                        SpringCase s;
                        s.mass = mass;
                        s.k = k;
                        s.gravity = gravity;
                        const double omega = std::sqrt(k / mass);
                        if (line) {
                            // Hanging 2 m below the anchor plus the sag, stretched by the amplitude.
                            s.restLength = 2.0;
                            s.position = {0.0, -(2.0 + mass * 9.81 / k * (gravity.y != 0.0) + amplitude)};
                        } else {
                            s.position = equilibrium(s) + Vec2{amplitude, 0.0};
                            s.velocity = {0.0, 0.5 * amplitude * omega}; // an ellipse of half the width
                        }
                        const Vec2 eq = equilibrium(s);
                        const Vec2 y0 = s.position - eq, u0 = s.velocity;
                        SpringWorld w = makeSpring(s);
                        const double e0 = energy(w, s);
                        const double oscillation = 0.5 * mass * u0.lengthSquared() + 0.5 * k * y0.lengthSquared();
                        const double period = 2.0 * kPi * std::sqrt(mass / k);
                        const double dt = w.world.def().timeStep;
                        const int steps = static_cast<int>(std::ceil(100.0 * period / dt));
                        // The phase of the component along y0, unwrapped step by step: its mean rate is
                        // 2 pi per period of the world's motion, whatever its frequency.
                        const Vec2 e = y0.normalized();
                        double phase = 0.0, previous = 0.0, worstEnergy = 0.0;
                        for (int n = 1; n <= steps; ++n) {
                            w.world.step();
                            const Circle& c = w.world.circle(w.ball);
                            const double now = std::atan2(-c.velocity.dot(e) / omega, (c.position - eq).dot(e));
                            double turn = now - previous;
                            if (turn < -kPi) turn += 2.0 * kPi;
                            phase += turn;
                            previous = now;
                            worstEnergy = std::max(worstEnergy, std::abs(energy(w, s) - e0) / oscillation);
                        }
                        const double t = steps * dt;
                        const double measured = 2.0 * kPi * t / phase;
                        // x(t) = x_eq + y0 cos(omega t) + u0 / omega sin(omega t), from t = 0.
                        const Vec2 expected = eq + y0 * std::cos(omega * t) + u0 * (std::sin(omega * t) / omega);
                        const Circle& c = w.world.circle(w.ball);
                        INFO("m " << mass << " k " << k << " A " << amplitude << " g " << gravity.y << " line "
                                  << line);
                        CHECK(std::abs(measured / period - 1.0) < 1e-9);
                        CHECK(worstEnergy < 1e-9);
                        CHECK((c.position - expected).length() < 1e-9 * (1.0 + y0.length()));
                        CHECK(w.world.lastImpacts().empty());
                        worstPeriod = std::max(worstPeriod, std::abs(measured / period - 1.0));
                        worstEnergyAll = std::max(worstEnergyAll, worstEnergy);
                        worstPosition = std::max(worstPosition, (c.position - expected).length() / (1.0 + y0.length()));
                        ++cases;
                    }
    CHECK(cases == 90);
    // The figures over all cases (printed with -s).
    INFO("worst period " << worstPeriod << ", energy " << worstEnergyAll << ", position " << worstPosition);
    CHECK(worstPeriod < 1e-9);
    CHECK(worstEnergyAll < 1e-9);
    CHECK(worstPosition < 1e-9);
}

TEST_CASE("exact spring: a damped spring follows its envelope e^(-zeta omega t) to 1e-9, under-, critically and "
          "over-damped",
          "[exact][joints][spring]") {
    double worstAll = 0.0;
    for (const double zeta : {0.1, 0.5, 1.0, 2.5})
        for (const double restLength : {0.0, 1.5})
            for (const double k : {40.0, 400.0}) {
                SpringCase s;
                s.k = k;
                s.mass = 2.0;
                s.restLength = restLength;
                s.c = 2.0 * zeta * std::sqrt(k * s.mass); // zeta = c / (2 sqrt(k m))
                s.gravity = {0.0, -9.81};
                const double omega = std::sqrt(k / s.mass), a = zeta * omega;
                s.position = {0.0, -(restLength + s.mass * 9.81 / k + 0.4)};
                s.velocity = {0.0, 0.3};
                const Vec2 eq = equilibrium(s);
                const double y0 = (s.position - eq).y, u0 = s.velocity.y;
                SpringWorld w = makeSpring(s);
                double worst = 0.0;
                const double dt = w.world.def().timeStep;
                const int steps = static_cast<int>(std::ceil(100.0 * 2.0 * kPi / omega / dt));
                for (int n = 1; n <= steps; ++n) {
                    w.world.step();
                    const double t = n * dt;
                    // The reference from t = 0: for zeta < 1 the envelope R0 e^(-a t) times a cosine
                    // of the damped frequency; at and past 1 the sum of two decaying exponentials.
                    double y = 0.0;
                    if (zeta < 1.0) {
                        const double wd = omega * std::sqrt(1.0 - zeta * zeta);
                        const double r0 = std::hypot(y0, (u0 + a * y0) / wd), phi = std::atan2((u0 + a * y0) / wd, y0);
                        y = r0 * std::exp(-a * t) * std::cos(wd * t - phi);
                        // The envelope itself: sqrt(y^2 + ((u + a y) / wd)^2) = R0 e^(-a t).
                        const Circle& c = w.world.circle(w.ball);
                        const double yn = (c.position - eq).y, un = c.velocity.y;
                        const double envelope = std::hypot(yn, (un + a * yn) / wd);
                        worst = std::max(worst, std::abs(envelope - r0 * std::exp(-a * t)) / r0);
                    } else if (zeta == 1.0) {
                        y = (y0 + (u0 + omega * y0) * t) * std::exp(-omega * t);
                    } else {
                        const double root = omega * std::sqrt(zeta * zeta - 1.0);
                        const double r1 = -a + root, r2 = -a - root;
                        y = ((u0 - r2 * y0) * std::exp(r1 * t) + (r1 * y0 - u0) * std::exp(r2 * t)) / (r1 - r2);
                    }
                    const Circle& c = w.world.circle(w.ball);
                    worst = std::max(worst, std::abs((c.position - eq).y - y) / std::abs(y0));
                    REQUIRE(c.position.x == 0.0);
                }
                INFO("zeta " << zeta << " L0 " << restLength << " k " << k << ": worst " << worst);
                CHECK(worst < 1e-9);
                worstAll = std::max(worstAll, worst);
            }
    INFO("worst envelope and path " << worstAll);
    CHECK(worstAll < 1e-9); // the figure over all cases (printed with -s)
}

TEST_CASE("exact spring: an impact on a spring-held ball comes at the root of x_eq + A cos(omega t) = the floor",
          "[exact][joints][spring]") {
    double worstTime = 0.0;
    for (const double k : {25.0, 100.0, 900.0})
        for (const double amplitude : {0.3, 1.2})
            for (const double restLength : {0.0, 2.0})
                for (const bool circleBelow : {false, true}) {
                    // Released at rest A above x_eq; the floor (a segment, or a fixed circle's top) 0.8 A
                    // below x_eq, touched when x_eq - A cos(omega t) ... reaches it: elastic, it comes back.
                    SpringCase s;
                    s.k = k;
                    s.restLength = restLength;
                    s.gravity = {0.0, -9.81};
                    s.anchor = {0.3, 5.0};
                    const double sag = 9.81 / k;
                    s.position = {0.3, 5.0 - restLength - sag + amplitude};
                    if (restLength > 0.0 && amplitude >= restLength + sag) continue;
                    SpringWorld w = makeSpring(s);
                    const Vec2 eq = equilibrium(s);
                    const double radius = 0.1, floor = eq.y - 0.8 * amplitude - radius;
                    if (circleBelow) {
                        CircleDef post;
                        post.position = {0.3, floor - 0.5};
                        post.radius = 0.5;
                        post.motion = Motion::fixed;
                        post.material.bounciness = 1.0;
                        w.world.addCircle(post);
                    } else {
                        SegmentDef ground;
                        ground.a = {-5.0, floor};
                        ground.b = {5.0, floor};
                        ground.material.bounciness = 1.0;
                        w.world.addSegment(ground);
                    }
                    // The ball's bounciness 1 too (a pair's is the product): energy is kept through it.
                    const double e0 = energy(w, s);
                    const double omega = std::sqrt(k);
                    // y(t) = A cos(omega t) = floor + r - x_eq: t = acos(-0.8) / omega.
                    const double expected = std::acos((floor + radius - eq.y) / amplitude) / omega;
                    double first = -1.0;
                    for (int n = 0; n < 600 && first < 0.0; ++n) {
                        w.world.step();
                        if (!w.world.lastImpacts().empty()) first = w.world.lastImpacts().front().time;
                    }
                    INFO("k " << k << " A " << amplitude << " L0 " << restLength << " circle " << circleBelow);
                    REQUIRE(first >= 0.0);
                    CHECK(std::abs(first - expected) < 1e-9);
                    worstTime = std::max(worstTime, std::abs(first - expected));
                    // The resolve reflected the normal speed of an elastic pair: a bounce, not a rest.
                    const Circle& c = w.world.circle(w.ball);
                    CHECK(c.position.y > floor + radius - 1e-9);
                    CHECK(c.velocity.y > 0.0);
                    CHECK(std::abs(energy(w, s) - e0) < 1e-9 * 0.5 * k * amplitude * amplitude);
                }
    INFO("worst time of impact off by " << worstTime << " s");
    CHECK(worstTime < 1e-9); // the figure over all cases (printed with -s)
}

TEST_CASE("exact spring: where there is no closed form the exact method refuses and names why",
          "[exact][joints][spring]") {
    struct Refusal {
        const char* why;
        SpringCase spring;
        bool oneSided = false;
        bool offCentre = false;
    };
    SpringCase offLine;
    offLine.restLength = 1.0;
    offLine.position = {2.0, 0.0};
    offLine.velocity = {0.0, 1.0}; // moving across its line: a pendulum on a spring
    SpringCase dampedOff;
    dampedOff.c = 1.0;
    dampedOff.position = {1.0, 0.0};
    dampedOff.gravity = {0.0, -9.81}; // damped, rest length 0, gravity across the line
    SpringCase through;
    through.restLength = 1.0;
    through.position = {1.5, 0.0};
    through.velocity = {-20.0, 0.0}; // fast enough to pass the fixed point
    for (const Refusal& r :
         {Refusal{"moves (or gravity pulls) off it", offLine}, Refusal{"moves (or gravity pulls) off it", dampedOff},
          Refusal{"pass through its fixed point", through}, Refusal{"one-sided", SpringCase{}, true},
          Refusal{"off its circle's centre", SpringCase{}, false, true}}) {
        const auto make = [&](Method method) {
            SpringCase s = r.spring;
            s.method = method;
            SpringWorld w = makeSpring(s);
            JointDef d = w.world.joint(w.spring).def;
            if (r.oneSided) d.springSide = SpringSide::pullOnly;
            if (r.offCentre) d.localAnchorB = {0.05, 0.0};
            w.world.remove(w.spring);
            w.spring = w.world.addJoint(d);
            return w;
        };
        SpringWorld w = make(Method::exact);
        const Vec2 before = w.world.circle(w.ball).position;
        std::string message;
        try {
            w.world.step();
        } catch (const std::logic_error& e) {
            message = e.what();
        }
        INFO(message);
        CHECK(message.find(r.why) != std::string::npos);
        CHECK(message.find("use method 'auto' or 'solver'") != std::string::npos);
        CHECK(w.world.circle(w.ball).position == before);
        // auto carries the same world on the solver.
        SpringWorld a = make(Method::automatic);
        a.world.step();
        CHECK(a.world.stats().solverBodySteps == 1);
    }
    // Two bodies on one spring: coupled.
    World two = jointWorld({0.0, 0.0}, Method::exact);
    JointDef d;
    d.kind = JointKind::spring;
    d.a = test::wheel(two, {0.0, 0.0}, 0.1, 1.0);
    d.b = test::wheel(two, {1.0, 0.0}, 0.1, 1.0);
    d.stiffness = 100.0;
    two.addJoint(d);
    CHECK_THROWS_WITH(two.step(), Catch::Contains("between two bodies"));
}

TEST_CASE("exact spring: an impact that knocks the ball off its spring's line puts the step back and refuses, and auto "
          "hands it to the solver",
          "[exact][joints][spring]") {
    // A ball hanging on a spring with a rest length falls onto a slope: the bounce throws it sideways,
    // where the spring has no closed form.
    for (const Method method : {Method::exact, Method::automatic}) {
        SpringCase s;
        s.restLength = 1.0;
        s.gravity = {0.0, -9.81};
        s.anchor = {0.0, 3.0};
        s.position = {0.0, 3.0 - 1.0 - 9.81 / 100.0 + 0.5};
        s.method = method;
        SpringWorld w = makeSpring(s);
        SegmentDef slope;
        slope.a = {-2.0, 1.0};
        slope.b = {2.0, 2.0};
        w.world.addSegment(slope);
        bool refused = false;
        for (int n = 0; n < 120 && !refused; ++n) {
            const Circle before = w.world.circle(w.ball);
            try {
                w.world.step();
            } catch (const std::logic_error& e) {
                refused = true;
                INFO(e.what());
                CHECK(std::string(e.what()).find("after an impact") != std::string::npos);
                // Nothing of the step is kept: the ball is where the step began.
                CHECK(w.world.circle(w.ball).position == before.position);
                CHECK(w.world.circle(w.ball).velocity == before.velocity);
            }
        }
        CHECK(refused == (method == Method::exact));
        if (method == Method::automatic) {
            CHECK(w.world.stats().exactBodySteps > 0);  // before the slope
            CHECK(w.world.stats().solverBodySteps > 0); // after it
            CHECK(w.world.circle(w.ball).position.x != 0.0);
        }
    }
}

TEST_CASE("exact spring: auto puts a spring-to-fixed-point island on exact, bit for bit, and a two-body spring on "
          "the solver",
          "[exact][joints][spring][auto]") {
    SpringCase s;
    s.gravity = {0.0, -9.81};
    s.position = {0.4, -0.2};
    s.velocity = {0.0, 1.0};
    SpringWorld exact = makeSpring(s);
    s.method = Method::automatic;
    SpringWorld automatic = makeSpring(s);
    // Beside them, under auto, two balls on one spring: coupled, the solver's.
    JointDef d;
    d.kind = JointKind::spring;
    d.a = test::wheel(automatic.world, {20.0, 0.0}, 0.1, 1.0);
    d.b = test::wheel(automatic.world, {21.0, 0.0}, 0.1, 1.0);
    d.stiffness = 50.0;
    d.restLength = 0.5;
    automatic.world.addJoint(d);
    for (int n = 0; n < 300; ++n) {
        exact.world.step();
        automatic.world.step();
        REQUIRE(automatic.world.circle(automatic.ball).position == exact.world.circle(exact.ball).position);
        REQUIRE(automatic.world.circle(automatic.ball).velocity == exact.world.circle(exact.ball).velocity);
    }
    CHECK(automatic.world.stats().exactBodySteps == 300);
    CHECK(automatic.world.stats().solverBodySteps == 600);
}

TEST_CASE("exact spring: a ball its spring pulls into the floor comes to rest on it, never through it",
          "[exact][joints][spring]") {
    // x_eq lies below the floor: the ball lands, bounces less each time (bounciness 0.5) and rests,
    // its resting contacts settled at each step's end as any resting ball's are.
    for (const double k : {30.0, 300.0})
        for (const double restLength : {0.0, 2.0}) {
            // The fixed point below the floor: the spring pulls the ball down onto it.
            SpringCase s;
            s.k = k;
            s.restLength = restLength;
            s.gravity = {0.0, -9.81};
            s.anchor = {0.0, -0.2 - restLength};
            s.position = {0.0, 0.3};
            SpringWorld w = makeSpring(s);
            SegmentDef ground;
            ground.a = {-3.0, 0.0};
            ground.b = {3.0, 0.0};
            ground.material.bounciness = 0.5;
            w.world.addSegment(ground);
            REQUIRE(equilibrium(s).y < 0.0);
            double lowest = s.position.y;
            for (int n = 0; n < 600; ++n) {
                w.world.step();
                lowest = std::min(lowest, w.world.circle(w.ball).position.y);
            }
            const Circle& c = w.world.circle(w.ball);
            INFO("k " << k << " L0 " << restLength << ": lowest " << lowest << ", speed " << c.velocity.length());
            CHECK(lowest > 0.1 - 1e-3); // the radius, less the resting slop of a step
            CHECK(c.position.x == 0.0);
            CHECK(c.velocity.length() < 0.05);
        }
}
