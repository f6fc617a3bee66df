// Ropes against their analytic answers, under every time-step method at the default 1/60 s step:
// a small-angle pendulum's period is 2 pi sqrt(L / g), a taut rope does no work (a wide swing keeps
// its energy), a ball hanging at rest stays at length L, a cut rope lets the ball fall freely, a
// slack rope never pushes, and a rope between two balls keeps their momentum and energy.
#include "rube/physics/rope.hpp"
#include "rube/physics/world.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace rube;

namespace {

constexpr Method kMethods[] = {Method::discrete, Method::turnBased, Method::exact, Method::solver};
constexpr double kG = 9.81;
const Vec2 kAnchor{0.0, 5.0};

// A world with nothing to collide with: only gravity and the rope act on the ball.
World openWorld(Method method, Vec2 gravity = {0.0, -kG}) {
    WorldDef def;
    def.method = method;
    def.gravity = gravity;
    return World(def);
}

// A pendulum of length L released from rest at `angle` radians from straight down; returns the rope.
RopeId addPendulum(World& world, double length, double angle, double mass = 1.0) {
    CircleDef ball;
    ball.position = kAnchor + Vec2{std::sin(angle), -std::cos(angle)} * length;
    ball.radius = 0.1;
    ball.mass = mass;
    const CircleId circle = world.addCircle(ball);
    return world.addRope(RopeDef{circle, {}, kAnchor, length});
}

// The mean period over `periods` swings, from the upward zero crossings of x - anchor.x, each
// placed between its two steps by linear interpolation (the crossing's error is O(dt^2 / T)).
double measurePeriod(World& world, int periods) {
    std::vector<double> crossings;
    double previousX = world.circles()[0].position.x - kAnchor.x;
    double previousT = world.time();
    while (static_cast<int>(crossings.size()) <= periods && world.time() < 200.0 * periods) {
        world.step();
        const double x = world.circles()[0].position.x - kAnchor.x;
        if (previousX < 0.0 && x >= 0.0)
            crossings.push_back(previousT + (world.time() - previousT) * (-previousX / (x - previousX)));
        previousX = x;
        previousT = world.time();
    }
    if (static_cast<int>(crossings.size()) <= periods) return 0.0;
    return (crossings.back() - crossings.front()) / periods;
}

double pendulumEnergy(const World& world, double mass) {
    const Circle& c = world.circles()[0];
    return mass * (0.5 * c.velocity.lengthSquared() + kG * (c.position.y - kAnchor.y));
}

} // namespace

TEST_CASE("rope: a small-angle pendulum's period is 2 pi sqrt(L / g) within 1 % under every method", "[rope]") {
    // 3 degrees: the finite-amplitude correction, T = T0 (1 + theta0^2 / 16 + ...), is 1.7e-4, well inside 1 %.
    const double amplitude = 0.05;
    for (const double length : {0.5, 1.0, 2.5}) {
        const double expected = 2.0 * std::numbers::pi * std::sqrt(length / kG);
        for (const Method method : kMethods) {
            CAPTURE(methodName(method), length);
            World world = openWorld(method);
            addPendulum(world, length, -amplitude);
            const double period = measurePeriod(world, 10);
            const double error = std::abs(period - expected) / expected;
            CAPTURE(period, expected);
            CHECK(error < 0.01);
            // Semi-implicit Euler in the angle is short by (omega dt)^2 / 24 (2.3e-4 at L = 0.5 m), the finite
            // amplitude long by 1.6e-4: measured 4e-5 to 1.1e-4, the same under every method.
            CHECK(error < 1e-3);
        }
    }
}

TEST_CASE("rope: a taut rope does no work: a 60-degree swing keeps its energy over 100 periods", "[rope]") {
    const double length = 1.0, mass = 2.0;
    for (const Method method : kMethods) {
        CAPTURE(methodName(method));
        World world = openWorld(method);
        addPendulum(world, length, std::numbers::pi / 3.0, mass);
        const double start = pendulumEnergy(world, mass);
        const double swing = mass * kG * length * 0.5; // m g L (1 - cos 60 deg): the energy that swings
        // The energy within a step wobbles by O(omega dt) (semi-implicit Euler's, bounded); what must
        // not happen is a drift. So compare the highest point of the first and the last 5 periods.
        const int stepsPerPeriod = 129; // 2.15 s at 60 Hz: 2 pi sqrt(L / g) (1 + theta0^2 / 16 + ...)
        double worst = 0.0, firstTop = -1e9, lastTop = -1e9;
        for (int i = 0; i < 100 * stepsPerPeriod; ++i) {
            world.step();
            worst = std::max(worst, std::abs(pendulumEnergy(world, mass) - start));
            const double y = world.circles()[0].position.y;
            if (i < 5 * stepsPerPeriod) firstTop = std::max(firstTop, y);
            if (i >= 95 * stepsPerPeriod) lastTop = std::max(lastTop, y);
        }
        const double topStart = kAnchor.y - length * 0.5;
        CAPTURE(worst / swing, firstTop - topStart, lastTop - topStart);
        CHECK(worst < 0.03 * swing); // bounded wobble, 2.5 % of the swing measured
        CHECK(std::abs(lastTop - firstTop) <
              5e-5 * length); // no drift (4 um measured): the swing still reaches its height
        CHECK(std::abs(firstTop - topStart) < 2e-3 * length);
        CHECK(world.stats().nonFinite == false);
    }
}

TEST_CASE("rope: a ball hanging at rest stays at length L for ten simulated minutes", "[rope]") {
    const double length = 2.0;
    for (const Method method : kMethods) {
        CAPTURE(methodName(method));
        World world = openWorld(method);
        addPendulum(world, length, 0.0);
        double drift = 0.0, speed = 0.0, sideways = 0.0;
        for (int i = 0; i < 60 * 600; ++i) {
            world.step();
            const Circle& c = world.circles()[0];
            drift = std::max(drift, std::abs(c.position.distance(kAnchor) - length));
            speed = std::max(speed, c.velocity.length());
            sideways = std::max(sideways, std::abs(c.position.x - kAnchor.x));
        }
        CAPTURE(drift, speed, sideways);
        CHECK(drift <= 1e-14);  // exactly L to rounding, every step: no creep
        CHECK(sideways == 0.0); // it hangs straight down
        CHECK(speed <= 1e-12);  // and never moves
    }
}

TEST_CASE("rope: a cut rope lets the ball fall freely", "[rope]") {
    const double length = 1.0;
    for (const Method method : kMethods) {
        CAPTURE(methodName(method));
        World world = openWorld(method);
        const RopeId rope = addPendulum(world, length, 0.0);
        for (int i = 0; i < 60; ++i) world.step();
        const Vec2 hung = world.circles()[0].position;
        REQUIRE(hung.distance(kAnchor) == Approx(length).epsilon(1e-12));
        world.cutRope(rope);
        CHECK(world.ropes()[0].cut);
        const double cutAt = world.time();
        for (int i = 0; i < 60; ++i) world.step();
        const double t = world.time() - cutAt;
        const Circle& c = world.circles()[0];
        // Free fall from rest: v = g t for every method; the drop is g t^2 / 2 (exact), and the
        // other methods' Euler sums add at most g t dt / 2 to it.
        CHECK(c.velocity.y == Approx(-kG * t).epsilon(1e-9));
        CHECK(c.velocity.x == 0.0);
        const double drop = hung.y - c.position.y;
        CHECK(drop >= 0.5 * kG * t * t - 1e-9);
        CHECK(drop <= 0.5 * kG * t * (t + world.def().timeStep) + 1e-9);
        CHECK(c.position.distance(kAnchor) > length + 4.0); // far past where the rope would have held it
    }
}

TEST_CASE("rope: a cut rope acts exactly as no rope at all", "[rope]") {
    for (const Method method : kMethods) {
        CAPTURE(methodName(method));
        World roped = openWorld(method), free = openWorld(method);
        roped.cutRope(addPendulum(roped, 1.0, 0.4));
        CircleDef ball;
        ball.position = roped.circles()[0].position;
        ball.radius = 0.1;
        free.addCircle(ball);
        for (int i = 0; i < 120; ++i) {
            roped.step();
            free.step();
        }
        CHECK(stateHash(roped) == stateHash(free));
    }
}

TEST_CASE("rope: a slack rope never pushes, it jerks taut and then holds the ball at L", "[rope]") {
    for (const Method method : kMethods) {
        CAPTURE(methodName(method));
        World world = openWorld(method), free = openWorld(method);
        CircleDef ball;
        ball.position = kAnchor + Vec2{0.0, -0.2};
        ball.radius = 0.1;
        world.addRope(RopeDef{world.addCircle(ball), {}, kAnchor, 1.0});
        free.addCircle(ball);
        // 0.8 m of slack takes sqrt(2 x 0.8 / g) = 0.40 s to fall: until then the rope does nothing.
        for (int i = 0; i < 20; ++i) {
            world.step();
            free.step();
        }
        CHECK(stateHash(world) == stateHash(free));
        for (int i = 0; i < 40; ++i) world.step();
        const Circle& c = world.circles()[0];
        CHECK(c.position.distance(kAnchor) == Approx(1.0).epsilon(1e-12));
        CHECK(c.velocity.length() < 1e-12); // the jerk is inelastic along the rope (C = 0): no rebound
    }
}

TEST_CASE("rope: two balls on a rope circle each other, keeping momentum, energy and their distance", "[rope]") {
    // No gravity: balls of 1 kg and 3 kg, 2 m apart, moving opposite ways with zero total momentum
    // plus a common drift. A taut rope only turns their relative velocity, so |v_rel| is constant.
    for (const Method method : kMethods) {
        CAPTURE(methodName(method));
        World world = openWorld(method, {0.0, 0.0});
        CircleDef a, b;
        a.position = {-1.5, 0.0};
        a.mass = 1.0;
        a.radius = 0.2;
        a.velocity = Vec2{0.0, 3.0} + Vec2{0.5, 0.0};
        b.position = {0.5, 0.0};
        b.mass = 3.0;
        b.radius = 0.2;
        b.velocity = Vec2{0.0, -1.0} + Vec2{0.5, 0.0};
        const CircleId ia = world.addCircle(a), ib = world.addCircle(b);
        world.addRope(RopeDef{ia, ib, {}, 2.0});
        const auto momentum = [&] { return world.circles()[0].velocity * 1.0 + world.circles()[1].velocity * 3.0; };
        const auto energy = [&] {
            return 0.5 * world.circles()[0].velocity.lengthSquared() +
                   1.5 * world.circles()[1].velocity.lengthSquared();
        };
        const Vec2 p0 = momentum();
        const double e0 = energy();
        for (int i = 0; i < 600; ++i) world.step();
        CHECK(approxEqual(momentum(), p0, 1e-12));
        CHECK(energy() == Approx(e0).epsilon(1e-12));
        CHECK(world.circles()[0].position.distance(world.circles()[1].position) == Approx(2.0).epsilon(1e-12));
        // Relative speed 4 m/s on a 2 m rope: omega = 2 rad/s clockwise, so after 10 s the rope points
        // at pi - 20 rad. Each step turns it by atan(v dt / L) rather than v dt / L, (omega dt)^2 / 3 =
        // 3.7e-4 slow: 7 mrad over 20 rad.
        const Vec2 d = world.circles()[0].position - world.circles()[1].position;
        const double angle = std::numbers::pi - 2.0 * world.time();
        CAPTURE(d.x, d.y, angle);
        CHECK(d.distance(Vec2{std::cos(angle), std::sin(angle)} * 2.0) < 0.02);
    }
}

TEST_CASE("rope: a rope to nothing or of no length is refused", "[rope]") {
    World world = openWorld(Method::exact);
    const CircleId ball = world.addCircle(CircleDef{});
    CHECK_THROWS_AS(world.addRope(RopeDef{CircleId{ball.index + 1, ball.generation}, {}, {}, 1.0}),
                    std::invalid_argument);
    CHECK_THROWS_AS(world.addRope(RopeDef{ball, ball, {}, 1.0}), std::invalid_argument);
    CHECK_THROWS_AS(world.addRope(RopeDef{ball, {}, {}, 0.0}), std::invalid_argument);
    CHECK_THROWS_AS(world.cutRope(RopeId{}), std::invalid_argument);
}

TEST_CASE("rope: a double pendulum's ropes never stretch, though either may go slack", "[rope]") {
    // The pendulum scene's double pendulum: the upper ball level with its anchor, the lower hanging
    // from it. Ropes pulled taut one after another would stretch each other by centimetres; the
    // extra passes over chained ropes hold both to their lengths.
    for (const Method method : kMethods) {
        CAPTURE(methodName(method));
        World world = openWorld(method);
        CircleDef upper, lower;
        upper.position = {8.0, 5.0};
        upper.radius = 0.2;
        lower.position = {8.0, 3.5};
        lower.radius = 0.2;
        const CircleId iu = world.addCircle(upper), il = world.addCircle(lower);
        world.addRope(RopeDef{iu, {}, {6.5, 5.0}, 1.5});
        world.addRope(RopeDef{il, iu, {}, 1.5});
        double stretch = 0.0;
        for (int i = 0; i < 60 * 12; ++i) {
            world.step();
            const Vec2 pu = world.circles()[0].position, pl = world.circles()[1].position;
            stretch = std::max({stretch, pu.distance({6.5, 5.0}) - 1.5, pl.distance(pu) - 1.5});
        }
        CAPTURE(stretch);
        CHECK(stretch < 1e-4);
        CHECK(world.stats().nonFinite == false);
    }
}
