// Fields against their analytic answers: terminal speed under linear drag, the decay towards the
// wind's speed, a magnet's inverse-square pull, a thruster's impulse, and that a world without
// fields is untouched by them.
#include "rube/physics/fields.hpp"
#include "rube/physics/world.hpp"

#include "rigid_water.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

using namespace rube;

namespace {

// A world with nothing to collide with, so only gravity and the fields act.
World openWorld(Method method, Vec2 gravity = {0.0, -9.81}, AirDrag drag = {}) {
    WorldDef def;
    def.gravity = gravity;
    def.method = method;
    def.airDrag = drag;
    return World(def);
}

int addBall(World& world, double mass, double radius = 0.5, Vec2 velocity = {}, bool magnetic = false) {
    CircleDef ball;
    ball.mass = mass;
    ball.radius = radius;
    ball.velocity = velocity;
    ball.magnetic = magnetic;
    return world.slot(world.addCircle(ball));
}

constexpr Method kMethods[] = {Method::discrete, Method::turnBased, Method::exact, Method::solver, Method::automatic};

} // namespace

TEST_CASE("fields: a falling ball under linear drag reaches the terminal speed m g / k", "[fields][drag]") {
    // k = 2r linear = 1 * 0.8 = 0.8 N s/m; m = 2 kg: v_t = m g / k = 24.525 m/s; time constant m / k = 2.5 s.
    const double m = 2.0, g = 9.81, k = 0.8;
    for (const Method method : kMethods) {
        CAPTURE(methodName(method));
        World world = openWorld(method, {0.0, -g}, AirDrag{0.8, 0.0});
        addBall(world, m, 0.5);
        for (int i = 0; i < 60 * 30; ++i) world.step(); // 12 time constants
        const double terminal = m * g / k;
        CHECK(world.circles()[0].velocity.y == Approx(-terminal).epsilon(0.01));
        // The drag is integrated exactly with gravity, so at any step the speed is the analytic
        // v(t) = v_t (1 - e^{-k t / m}), not just its limit.
        World early = openWorld(method, {0.0, -g}, AirDrag{0.8, 0.0});
        addBall(early, m, 0.5);
        for (int i = 0; i < 60; ++i) early.step();
        const double t = early.time();
        CHECK(early.circles()[0].velocity.y == Approx(-terminal * -std::expm1(-k * t / m)).epsilon(1e-9));
    }
}

TEST_CASE("fields: under linear drag the exact methods move a ball along the exact x(t) and y(t)", "[fields][drag]") {
    // dv/dt = g - k v / m from v0: x(t) = x0 + v_t t + (v0 - v_t) tau (1 - e^{-t/tau}), tau = m / k, v_t = g tau.
    // The drag is split around the method's move, so exact and auto (exact here) follow it to round-off.
    const double m = 0.5, r = 0.25, linear = 2.0, g = 9.81;
    const double k = 2.0 * r * linear, tau = m / k;
    const Vec2 v0{6.0, 1.5};
    for (const Method method : {Method::exact, Method::automatic}) {
        CAPTURE(methodName(method));
        World world = openWorld(method, {0.0, -g}, AirDrag{linear, 0.0});
        addBall(world, m, r, v0);
        double worst = 0.0;
        for (int i = 0; i < 180; ++i) {
            world.step();
            const double t = world.time(), share = -std::expm1(-t / tau);
            const Vec2 expected{v0.x * tau * share, -g * tau * t + (v0.y + g * tau) * tau * share};
            worst = std::max(worst, (world.circles()[0].position - expected).length());
        }
        CHECK(worst < 1e-12);
    }
}

TEST_CASE("fields: quadratic drag slows a ball to sqrt(m g / k)", "[fields][drag]") {
    // F = 2r quadratic v^2 = m g at the terminal speed: v_t = sqrt(m g / (2r quadratic)).
    const double m = 1.0, g = 9.81, quadratic = 0.28, r = 0.25;
    World world = openWorld(Method::exact, {0.0, -g}, AirDrag{0.0, quadratic});
    addBall(world, m, r);
    for (int i = 0; i < 60 * 60; ++i) world.step();
    CHECK(-world.circles()[0].velocity.y == Approx(std::sqrt(m * g / (2.0 * r * quadratic))).epsilon(0.01));
}

TEST_CASE("fields: drag weighs a heavy ball less than a light one of the same size", "[fields][drag]") {
    World world = openWorld(Method::exact, {0.0, -9.81}, AirDrag{0.5, 0.2});
    const int light = addBall(world, 0.2, 0.3);
    const int heavy = addBall(world, 5.0, 0.3);
    world.setPosition(world.circleId(1), {5.0, world.circles()[1].position.y});
    for (int i = 0; i < 120; ++i) world.step();
    CHECK(world.circles()[heavy].velocity.y < world.circles()[light].velocity.y);
}

TEST_CASE("fields: a ball in a fan's wind approaches the air's speed as u + (v0 - u) e^{-k t / m}", "[fields][wind]") {
    World world = openWorld(Method::exact, {0.0, 0.0});
    const int ball = addBall(world, 1.0, 0.5, {0.0, 0.0});
    world.fields().winds.push_back(Wind{{-100, 0}, {1, 0}, 200, 200, 3.0, 0.5});
    for (int i = 0; i < 90; ++i) world.step();
    const double k = 2.0 * 0.5 * 0.5; // 2r drag / m
    CHECK(world.circles()[ball].velocity.x == Approx(3.0 * -std::expm1(-k * world.time())).epsilon(1e-9));
    CHECK(world.circles()[ball].velocity.y == 0.0);

    SECTION("outside the region, or with the fan off, nothing happens") {
        World still = openWorld(Method::exact, {0.0, 0.0});
        addBall(still, 1.0);
        still.fields().winds.push_back(
            Wind{{1, 0}, {1, 0}, 5, 4, 3.0, 0.5}); // blows away from the ball: behind the fan
        still.fields().winds.push_back(
            Wind{{-1, 2}, {1, 0}, 5, 3.9, 3.0, 0.5}); // the ball is 2 m off the axis, outside a 3.9 m column
        still.fields().winds.push_back(Wind{{-9, 0}, {1, 0}, 20, 9, 3.0, 0.5, false}); // switched off
        for (int i = 0; i < 30; ++i) still.step();
        CHECK(still.circles()[0].velocity == Vec2{});
    }
}

TEST_CASE("fields: a magnet pulls steel with strength / d^2 and leaves other balls alone", "[fields][magnet]") {
    Magnet magnet;
    magnet.position = {0.0, 0.0};
    magnet.strength = 2.0;
    magnet.radius = 0.2;
    for (const double d : {0.5, 1.0, 3.0}) {
        const Vec2 f = magnetForce(magnet, {d, 0.0});
        CHECK(f.x == Approx(-2.0 / (d * d)).epsilon(1e-12));
        CHECK(f.y == 0.0);
    }
    // Held at the radius inside it, zero at and past the reach, finite at the very centre.
    CHECK(magnetForce(magnet, {0.1, 0.0}).x == Approx(-2.0 / 0.04));
    CHECK(magnetForce(magnet, {0.0, 0.0}) == Vec2{});
    magnet.reach = 2.0;
    CHECK(magnetForce(magnet, {2.0, 0.0}) == Vec2{});

    for (const Method method : kMethods) {
        CAPTURE(methodName(method));
        World world = openWorld(method, {0.0, 0.0});
        const int steel = addBall(world, 4.0, 0.2, {}, true);
        const int rubber = addBall(world, 4.0, 0.2, {}, false);
        world.setPosition(world.circleId(steel), {2.0, 0.0});
        world.setPosition(world.circleId(rubber), {0.0, 2.0});
        world.fields().magnets.push_back(Magnet{{0.0, 0.0}, 2.0, 0.2});
        world.step();
        const double dt = 1.0 / 60.0, a0 = -0.5 / 4.0; // F / m = (2 / 2^2) / 4 at x = 2
        const Circle& c = world.circles()[steel];
        if (method == Method::exact || method == Method::automatic || method == Method::solver) {
            // Velocity Verlet: x1 = x0 + a0 dt^2 / 2, v1 = (a0 + a1) dt / 2 with a1 the pull at x1.
            const double x1 = 2.0 + 0.5 * a0 * dt * dt, a1 = -2.0 / (x1 * x1) / 4.0;
            CHECK(c.position.x == Approx(x1).epsilon(1e-14));
            CHECK(c.velocity.x == Approx(0.5 * (a0 + a1) * dt).epsilon(1e-12));
        } else {
            // The others: one step's kick, Delta v = F dt / m, then the move at that speed.
            CHECK(c.velocity.x == Approx(a0 * dt).epsilon(1e-12));
            CHECK(c.position.x == Approx(2.0 + a0 * dt * dt).epsilon(1e-14));
        }
        CHECK(world.circles()[rubber].velocity == Vec2{});
    }
}

TEST_CASE("fields: a steel ball swinging through a magnet's pull keeps its energy to second order under exact",
          "[fields][magnet]") {
    // No gravity, no contact: the ball passes the magnet (off centre, so it swings round it) and the
    // energy E = m v^2 / 2 - s / d (the pull s / d^2 is -dU/dd of U = -s / d, outside the magnet's
    // radius) is conserved. Exact moves it by velocity Verlet, whose error halves twice as the step
    // halves (second order); the kick (symplectic Euler) halved it once.
    const double s = 2.0, m = 4.0;
    for (const double miss : {1.0, 1.5, 2.0})
        for (const double speed : {1.0, 1.5}) {
            CAPTURE(miss, speed);
            double drift[2] = {};
            for (int k = 0; k < 2; ++k) {
                WorldDef def;
                def.gravity = {};
                def.method = Method::exact;
                def.timeStep = k == 0 ? 1.0 / 60.0 : 1.0 / 120.0;
                World world(def);
                const int steel = addBall(world, m, 0.1, {speed, 0.0}, true);
                world.setPosition(world.circleId(steel), {-3.0, miss});
                world.fields().magnets.push_back(Magnet{{0.0, 0.0}, s, 0.3, 100.0});
                const auto energy = [&] {
                    const Circle& c = world.circles()[static_cast<std::size_t>(steel)];
                    return 0.5 * m * c.velocity.lengthSquared() - s / c.position.length();
                };
                const double e0 = energy();
                while (world.time() < 6.0) {
                    world.step();
                    REQUIRE(world.circles()[static_cast<std::size_t>(steel)].position.length() > 0.4);
                    drift[k] = std::max(drift[k], std::abs(energy() - e0));
                }
            }
            // Second order: 4 x less at half the step (3 allows for the orbit's own change of shape).
            CHECK(drift[0] > 3.0 * drift[1]);
        }
}

TEST_CASE("fields: a thruster gives F t / m over the time it burns, even mid-step", "[fields][thruster]") {
    World world = openWorld(Method::exact, {0.0, 0.0});
    const int rocket = addBall(world, 2.0);
    // Lights a third of the way into step 6 and burns 1.5 s: Delta v = 10 N * 1.5 s / 2 kg = 7.5 m/s.
    world.fields().thrusters.push_back(Thruster{world.circleId(rocket), {10.0, 0.0}, 6.33 / 60.0, 6.33 / 60.0 + 1.5});
    for (int i = 0; i < 180; ++i) world.step();
    CHECK(world.circles()[rocket].velocity.x == Approx(7.5).epsilon(1e-12));
}

TEST_CASE("fields: a thruster moves a body x = F t^2 / (2m) exactly, and coasts once burnt out", "[fields][thruster]") {
    // F = 10 N on m = 2 kg, no gravity: a = 5 m/s^2. It lights at t = 0 and burns T = 1.2345 s, so
    // it goes out a part of the way through step 74 (T / dt = 74.07); after that it coasts at a T.
    const double force = 10.0, m = 2.0, a = force / m, burn = 1.2345;
    World world = openWorld(Method::exact, {0.0, 0.0});
    const int rocket = addBall(world, m);
    world.fields().thrusters.push_back(Thruster{world.circleId(rocket), {force, 0.0}, 0.0, burn});
    double worstBurning = 0.0, worstCoasting = 0.0;
    for (int i = 0; i < 240; ++i) {
        world.step();
        const double t = world.time(), x = world.circles()[rocket].position.x;
        if (t <= burn) {
            // x = F t^2 / (2m), v = F t / m while it burns.
            worstBurning = std::max(worstBurning, std::abs(x - 0.5 * a * t * t) / (0.5 * a * t * t));
            CHECK(world.circles()[rocket].velocity.x == Approx(a * t).epsilon(1e-9));
        } else {
            // Burnt out: x = a T^2 / 2 + a T (t - T), v = a T.
            const double expected = 0.5 * a * burn * burn + a * burn * (t - burn);
            worstCoasting = std::max(worstCoasting, std::abs(x - expected) / expected);
            CHECK(world.circles()[rocket].velocity.x == Approx(a * burn).epsilon(1e-12));
        }
        CHECK(world.circles()[rocket].position.y == 0.0);
    }
    INFO("worst relative error while burning " << worstBurning << ", coasting " << worstCoasting);
    CHECK(worstBurning < 1e-9);
    CHECK(worstCoasting < 1e-9);
    // At t = 4 s: 20.88 m; a burn that never ended would have carried it a t^2 / 2 = 40 m.
    CHECK(world.circles()[rocket].position.x == Approx(0.5 * a * burn * burn + a * burn * (4.0 - burn)).epsilon(1e-9));
}

TEST_CASE("fields: a world without fields moves exactly as before", "[fields]") {
    // The pass is skipped, not run with zeros: states are bit-identical to a plain fall.
    World plain = openWorld(Method::exact);
    World empty = openWorld(Method::exact);
    addBall(plain, 1.0, 0.5, {1.0, 2.0});
    addBall(empty, 1.0, 0.5, {1.0, 2.0});
    empty.fields().winds.push_back(Wind{{50, 50}, {1, 0}, 5, 1, 3.0, 0.5}); // far away: the pass runs, adds 0
    for (int i = 0; i < 100; ++i) {
        plain.step();
        empty.step();
    }
    CHECK(stateHash(plain) == stateHash(empty));
    const double t = plain.time();
    CHECK(plain.circles()[0].position.y == Approx(2.0 * t - 0.5 * 9.81 * t * t).margin(1e-9));
}

TEST_CASE("fields: the submerged area of a circle is the circular segment below the surface", "[fields][water]") {
    const double r = 0.5, pi = 3.141592653589793;
    CHECK(submergedArea(r, r) == 0.0);
    CHECK(submergedArea(r, 2.0) == 0.0);
    CHECK(submergedArea(r, -r) == Approx(pi * r * r));
    CHECK(submergedArea(r, 0.0) == Approx(pi * r * r / 2.0).epsilon(1e-15));
    for (const double h : {-0.45, -0.2, 0.1, 0.3, 0.49}) {
        CAPTURE(h);
        // Against a midpoint-rule integral of the chord width 2 sqrt(r^2 - y^2) over the part of the
        // disc below the surface, which lies at y = -h from the centre: y in [-r, -h].
        const int n = 200'000;
        double below = 0.0;
        for (int i = 0; i < n; ++i) {
            const double y = -r + (-h + r) * (i + 0.5) / n;
            below += 2.0 * std::sqrt(r * r - y * y) * (-h + r) / n;
        }
        CHECK(submergedArea(r, h) == Approx(below).epsilon(1e-6));
        CHECK(submergedArea(r, h) + submergedArea(r, -h) == Approx(pi * r * r).epsilon(1e-14));
    }
}

TEST_CASE("fields: a ball of half the water's density floats with its centre at the surface", "[fields][water]") {
    // rho A g = m g at equilibrium: A = m / rho = pi r^2 / 2, so half the ball is under water.
    const double r = 0.5, rho = 1000.0, pi = 3.141592653589793;
    for (const Method method : kMethods) {
        CAPTURE(methodName(method));
        World world = openWorld(method);
        world.fields().waters.push_back(Water{{-10.0, -10.0}, {10.0, 0.0}, rho});
        const int ball = addBall(world, 0.5 * rho * pi * r * r, r);
        world.setPosition(world.circleId(ball), {0.0, 1.5});
        for (int i = 0; i < 60 * 29; ++i) world.step();
        const double before = world.circles()[ball].position.y;
        for (int i = 0; i < 60; ++i) world.step();
        const Circle& c = world.circles()[ball];
        CHECK(std::abs(c.position.y) < 0.02 * r);
        // At rest: it moves less than a millimetre over the last second. (Its velocity after a step
        // is not 0 but up to g dt: buoyancy acts at the step's start, gravity within the method.)
        CHECK(std::abs(c.position.y - before) < 0.001);
    }
    SECTION("a quarter as dense floats higher, where a quarter of its area is under") {
        World world = openWorld(Method::exact);
        world.fields().waters.push_back(Water{{-10.0, -10.0}, {10.0, 0.0}, rho});
        const int ball = addBall(world, 0.25 * rho * pi * r * r, r);
        for (int i = 0; i < 60 * 30; ++i) world.step();
        // Solve A(h) = pi r^2 / 4 for the height h of the centre above the surface by bisection.
        double lo = -r, hi = r;
        for (int i = 0; i < 100; ++i) {
            const double mid = 0.5 * (lo + hi);
            (submergedArea(r, mid) > pi * r * r / 4.0 ? lo : hi) = mid;
        }
        CHECK(world.circles()[ball].position.y == Approx(lo).margin(0.02 * r));
        CHECK(lo > 0.1 * r); // it really floats higher than the half-density ball
    }
}

TEST_CASE("fields: a ball far lighter than its water floats at Archimedes' depth and never gains height",
          "[fields][water]") {
    // Buoyancy is a spring of stiffness |g| rho w / m per unit mass (w the chord at the surface); for a
    // light ball on dense water its period is shorter than the step, and kicked at the step's start it
    // gained energy every step (a 10 g ball of radius 0.1 m on 1000 kg/m^2 rose 6.7 km in 20 s). Set on
    // the surface, from a 0.1 g bead to a 20 kg ball, with and without drag, at 30 to 240 Hz, under
    // every method: it must never rise more than a centimetre above where a ball floats, and with drag
    // it must settle where rho A g = m g.
    const double pi = 3.141592653589793;
    for (const double rho : {1000.0, 8000.0}) {
        for (const double drag : {0.0, 1000.0}) {
            for (const auto& [mass, r] :
                 {std::pair{0.0001, 0.05}, std::pair{0.01, 0.1}, std::pair{0.05, 0.1}, std::pair{20.0, 0.3}}) {
                for (const double rate : {30.0, 60.0, 240.0}) {
                    for (const Method method : {Method::exact, Method::solver}) {
                        WorldDef def;
                        def.gravity = {0.0, -9.81};
                        def.method = method;
                        def.timeStep = 1.0 / rate;
                        World world(def);
                        world.fields().waters.push_back(Water{{-10.0, -10.0}, {10.0, 0.0}, rho, drag});
                        const int ball = addBall(world, mass, r);
                        world.setPosition(world.circleId(ball), {0.0, r}); // resting on the surface
                        // Where it floats: the centre's height h with A(h) = m / rho (bisection).
                        double lo = -r, hi = r;
                        for (int i = 0; i < 100; ++i) {
                            const double mid = 0.5 * (lo + hi);
                            (submergedArea(r, mid) > mass / rho ? lo : hi) = mid;
                        }
                        double highest = -1e9, lastSecond = 0.0;
                        const int steps = static_cast<int>(8.0 * rate);
                        for (int i = 0; i < steps; ++i) {
                            world.step();
                            highest = std::max(highest, world.circles()[ball].position.y);
                            if (i >= steps - static_cast<int>(rate)) lastSecond += world.circles()[ball].position.y;
                        }
                        // The mean over the last second: a lightly damped ball still bobs about its
                        // float height, and the lightest ride on a sliver of water thinner than a
                        // step's fall, g dt^2, so they hop by up to that.
                        const double y = lastSecond / rate;
                        INFO(methodName(method)
                             << ", rho " << rho << ", drag " << drag << ", " << mass << " kg, r " << r << ", " << rate
                             << " Hz: highest " << highest << ", end " << y << ", floats at " << lo
                             << " (density ratio " << mass / (pi * r * r * rho) << ")");
                        CHECK(std::isfinite(y));
                        CHECK(highest < std::max(lo, r) + 0.01);
                        if (drag > 0.0) CHECK(y == Approx(lo).margin(0.01 * r + 9.81 * def.timeStep * def.timeStep));
                    }
                }
            }
        }
    }
}

namespace {

/// A solver world with one pool of `rho` (and `drag`) under y = 0, and one dynamic body.
World poolWorld(double rho, double drag, double rate = 60.0) {
    WorldDef def;
    def.gravity = {0.0, -9.81};
    def.method = Method::solver;
    def.timeStep = 1.0 / rate;
    World world(def);
    world.fields().waters.push_back(Water{{-20.0, -20.0}, {20.0, 0.0}, rho, drag});
    return world;
}

RigidBodyDef floater(BodyShape shape, Vec2 half, double mass, double angle = 0.0) {
    RigidBodyDef d;
    d.shape = shape;
    d.halfExtents = half;
    d.mass = mass;
    d.angle = angle;
    d.position = {0.0, 0.0};
    return d;
}

} // namespace

TEST_CASE("fields: a box floats upright with its density ratio's share of its height under water", "[fields][water]") {
    // rho_water A_under g = m g: a flat box (wide, so upright is stable) of density ratio s floats with
    // s of its height h under the surface, its centre at h (1/2 - s) above it. Boxes once fell through.
    for (const double ratio : {0.2, 0.5, 0.8}) {
        for (const auto& [w, h] : {std::pair{1.0, 0.4}, std::pair{2.0, 0.5}, std::pair{0.6, 0.3}}) {
            World world = poolWorld(8.0, 5.0);
            const double mass = ratio * 8.0 * w * h;
            const BodyId id = world.addBody(floater(BodyShape::box, {0.5 * w, 0.5 * h}, mass));
            world.setPosition(id, {0.0, 0.5 * h + 0.2}); // dropped from 0.2 m above the water
            double highest = -1e9;
            for (int i = 0; i < 60 * 20; ++i) {
                world.step();
                if (i > 60 * 2) highest = std::max(highest, world.bodies()[0].position.y);
            }
            const RigidBody& b = world.bodies()[0];
            INFO("ratio " << ratio << ", box " << w << " x " << h << ": centre " << b.position.y << ", angle "
                          << b.angle << " (expected " << h * (0.5 - ratio) << ")");
            CHECK(b.position.y == Approx(h * (0.5 - ratio)).margin(0.01 * h));
            CHECK(std::abs(b.angle) < 1e-6);
            CHECK(std::abs(b.position.x) < 1e-9);
            CHECK(highest < 0.5 * h + 0.2); // never thrown higher than it fell from
        }
    }
}

TEST_CASE("fields: a tall box floating upright rolls onto its side, and a box denser than the water sinks "
          "at g (1 - rho_w / rho_b)",
          "[fields][water]") {
    // A box of half the water's density, four times as tall as wide: its centre of buoyancy moves the
    // wrong way when it tilts, so a slight tilt grows until it lies flat (its long side along the surface).
    {
        World world = poolWorld(8.0, 5.0);
        const double w = 0.25, h = 1.0;
        world.addBody(floater(BodyShape::box, {0.5 * w, 0.5 * h}, 0.5 * 8.0 * w * h, 0.02));
        for (int i = 0; i < 60 * 20; ++i) world.step();
        const RigidBody& b = world.bodies()[0];
        const double fromFlat = std::abs(std::remainder(b.angle, std::numbers::pi)) - 0.5 * std::numbers::pi;
        INFO("angle " << b.angle << ", centre " << b.position.y);
        CHECK(std::abs(fromFlat) < 0.02);
        CHECK(b.position.y == Approx(0.0).margin(0.01)); // lying flat, half under
    }
    // Twice the water's density, no drag: it falls at g (1 - 1/2) once wholly under.
    {
        World world = poolWorld(8.0, 0.0);
        const double w = 0.5, h = 0.5;
        const BodyId id = world.addBody(floater(BodyShape::box, {0.5 * w, 0.5 * h}, 2.0 * 8.0 * w * h));
        world.setPosition(id, {0.0, -1.0});
        for (int i = 0; i < 30; ++i) world.step();
        const double v0 = world.bodies()[0].velocity.y;
        for (int i = 0; i < 60; ++i) world.step();
        const double a = (world.bodies()[0].velocity.y - v0) / 1.0;
        CHECK(a == Approx(-9.81 * 0.5).epsilon(1e-9));
    }
}

TEST_CASE("fields: a capsule floats with its density ratio's share of its area under water, and a light "
          "box on dense water stays put",
          "[fields][water]") {
    for (const double ratio : {0.25, 0.5, 0.75}) {
        World world = poolWorld(8.0, 5.0);
        const Vec2 half{0.5, 0.2}; // core 1 m, radius 0.2 m: lying flat
        const double area = 4.0 * half.x * half.y + std::numbers::pi * half.y * half.y;
        world.addBody(floater(BodyShape::capsule, half, ratio * 8.0 * area));
        for (int i = 0; i < 60 * 20; ++i) world.step();
        const RigidBody& b = world.bodies()[0];
        const Submerged under = submergedPart(b, world.fields().waters[0]);
        INFO("ratio " << ratio << ": under " << under.area / area << " of the capsule, angle " << b.angle);
        // The caps are polygons: their area is within 0.7 % of the true one.
        CHECK(under.area / area == Approx(ratio).margin(0.01));
        CHECK(std::abs(b.angle) < 1e-6);
    }
    // 10 g, 0.3 m square, on 1000 kg/m^2 water: far stiffer than the step; it must neither fly nor sink.
    for (const double rate : {30.0, 60.0, 240.0}) {
        World world = poolWorld(1000.0, 1000.0, rate);
        const BodyId id = world.addBody(floater(BodyShape::box, {0.15, 0.15}, 0.01));
        world.setPosition(id, {0.0, 0.15});
        double highest = -1e9, lowest = 1e9;
        for (int i = 0; i < static_cast<int>(8 * rate); ++i) {
            world.step();
            highest = std::max(highest, world.bodies()[0].position.y);
            lowest = std::min(lowest, world.bodies()[0].position.y);
        }
        INFO(rate << " Hz: between " << lowest << " and " << highest);
        CHECK(highest < 0.15 + 0.01);
        CHECK(lowest > 0.15 - 0.01);
    }
}

namespace {

// A fixed round magnet of radius R at `at` (the part: a fixed circle with a field of the same radius)
// and a steel ball of radius r and mass m, `gap` from its surface in direction `towards` (magnet to ball).
struct MagnetHold {
    World world;
    int ball = -1;
    Vec2 at;
    double reach = 0.0; // centre distance at contact
};

MagnetHold magnetHold(Method method, double dt, double strength, Vec2 gravity, Vec2 towards, double gap,
                      double bounciness) {
    WorldDef def;
    def.method = method;
    def.timeStep = dt;
    def.gravity = gravity;
    MagnetHold hold{World(def), -1, {}, 0.0};
    const double R = 0.25, r = 0.2;
    hold.at = {0.0, 4.0};
    CircleDef magnet;
    magnet.position = hold.at;
    magnet.radius = R;
    magnet.motion = Motion::fixed;
    magnet.material.bounciness = bounciness;
    hold.world.addCircle(magnet);
    CircleDef steel;
    steel.radius = r;
    steel.mass = 4.0;
    steel.magnetic = true;
    steel.material.bounciness = bounciness;
    hold.reach = R + r;
    steel.position = hold.at + towards.normalized() * (hold.reach + gap);
    hold.ball = hold.world.slot(hold.world.addCircle(steel));
    hold.world.fields().magnets.push_back(Magnet{hold.at, strength, R, 3.0});
    return hold;
}

} // namespace

TEST_CASE("fields: a ball a magnet holds rests on it, at rest and touching, under exact and auto", "[fields][magnet]") {
    // The magnet's kick, given whole at a step's start, brought a held ball back onto the magnet at the
    // kick's speed every step: a real impact, a bounce, and a ball standing still that reported a
    // constant speed away from the magnet (-0.23 m/s for the part's magnet and steel ball at 100 Hz).
    // Moved by the pull as by gravity, a constant acceleration over the step, it rests on the magnet.
    // The ball starts 5 cm from the magnet on the side gravity pulls it to (frictionless, that is
    // where it can hang), for gravity down, tilted, sideways and none; pulls from just enough to hold
    // it against gravity at contact to 20 times that; several steps and bouncinesses.
    const double m = 4.0, contact = 0.45;
    const double weight = 9.81;
    const double holds = m * weight * contact * contact; // strength whose pull at contact is the ball's weight
    const Vec2 gravities[] = {{0.0, -weight}, {0.5 * weight, -0.866 * weight}, {weight, 0.0}, {0.0, 0.0}};
    for (const Method method : {Method::exact, Method::automatic, Method::solver})
        for (const Vec2 gravity : gravities)
            for (const double times : {1.5, 4.0, 20.0})
                for (const double dt : {1.0 / 60.0, 1.0 / 100.0, 1.0 / 240.0})
                    for (const double bounciness : {0.3, 0.8}) {
                        CAPTURE(methodName(method), gravity.x, gravity.y, times, dt, bounciness);
                        const Vec2 towards = gravity == Vec2{} ? Vec2{1.0, 1.0} : gravity;
                        MagnetHold hold = magnetHold(method, dt, times * holds, gravity, towards, 0.05, bounciness);
                        World& world = hold.world;
                        const int steps = static_cast<int>(std::lround(3.0 / dt));
                        double fastest = 0.0, sliding = 0.0, farthest = 0.0, hardest = 0.0;
                        for (int i = 0; i < steps; ++i) {
                            world.step();
                            if (world.time() < 2.0) continue; // the last second: it has long come to rest
                            const Circle& c = world.circles()[static_cast<std::size_t>(hold.ball)];
                            const Vec2 out = (c.position - hold.at).normalized();
                            fastest = std::max(fastest, std::abs(c.velocity.dot(out)));
                            sliding = std::max(sliding, std::abs(c.velocity.cross(out)));
                            farthest = std::max(farthest, std::abs((c.position - hold.at).length() - contact));
                            for (const Impact& impact : world.lastImpacts())
                                hardest = std::max(hardest, impact.approachSpeed);
                        }
                        // The solver's contacts are soft: the ball rests a little into the magnet,
                        // the load over the contact's spring (micrometres).
                        const bool soft = method == Method::solver;
                        CHECK(fastest < (soft ? 1e-6 : 1e-9));
                        // Along the magnet, frictionless, nothing stops what round-off leaves of a
                        // bounce when no gravity pulls the ball back below the magnet: micrometres a second.
                        CHECK(sliding < (gravity == Vec2{} ? 1e-5 : 1e-9));
                        CHECK(farthest < (soft ? 1e-4 : 1e-9));
                        // Resting contact, not impacts: nothing meets the magnet faster than the pull
                        // less gravity gives it over a step.
                        CHECK(hardest <= times * weight * dt * 1.0000001);
                    }
}

TEST_CASE("fields: too weak a magnet above a ball lets it fall, as F = strength / d^2 says", "[fields][magnet]") {
    // Below its weight at contact, m g d^2, the pull cannot hold the ball under the magnet: it falls
    // away under g - F / m, which only grows as it goes.
    const double contact = 0.45, holds = 4.0 * 9.81 * contact * contact;
    for (const Method method : {Method::exact, Method::automatic})
        for (const double times : {0.5, 0.9}) {
            CAPTURE(methodName(method), times);
            MagnetHold hold = magnetHold(method, 1.0 / 60.0, times * holds, {0.0, -9.81}, {0.0, -1.0}, 0.0, 0.3);
            for (int i = 0; i < 30; ++i) hold.world.step();
            const Circle& c = hold.world.circles()[static_cast<std::size_t>(hold.ball)];
            // Half a second at no more than g (1 - times) down: at least that far, at most g t^2 / 2.
            const double fell = hold.at.y - contact - c.position.y, t = hold.world.time();
            CHECK(fell >= 0.5 * 9.81 * (1.0 - times) * t * t * 0.999);
            CHECK(fell <= 0.5 * 9.81 * t * t);
        }
}

TEST_CASE("fields: a magnet under the floor holds a steel ball on it, still", "[fields][magnet]") {
    // A face holds the ball with what it leaves of g + F / m (here nothing: both press into the floor),
    // so the ball stands still on it instead of being kicked into it and bounced every step.
    for (const Method method : {Method::exact, Method::automatic, Method::solver})
        for (const double strength : {5.0, 50.0, 500.0})
            for (const double bounciness : {0.3, 0.9}) {
                CAPTURE(methodName(method), strength, bounciness);
                WorldDef def;
                def.method = method;
                World world(def);
                SegmentDef floor;
                floor.a = {-5.0, 0.0};
                floor.b = {5.0, 0.0};
                floor.material.bounciness = bounciness;
                world.addSegment(floor);
                CircleDef steel;
                steel.radius = 0.2;
                steel.mass = 4.0;
                steel.magnetic = true;
                steel.material.bounciness = bounciness;
                steel.position = {0.0, 0.5};
                const int ball = world.slot(world.addCircle(steel));
                world.fields().magnets.push_back(Magnet{{0.0, -0.3}, strength, 0.25, 3.0});
                double fastest = 0.0, lowest = 1.0, highest = 0.0;
                for (int i = 0; i < 240; ++i) {
                    world.step();
                    if (i < 120) continue;
                    const Circle& c = world.circles()[static_cast<std::size_t>(ball)];
                    fastest = std::max(fastest, c.velocity.length());
                    lowest = std::min(lowest, c.position.y);
                    highest = std::max(highest, c.position.y);
                }
                // The solver's contact is soft: the ball rests the load over its spring into the floor,
                // 0.11 mm when the strongest magnet presses it at 51 g; still, it stays where it rests.
                const double give = method == Method::solver ? 2e-4 : 1e-9;
                CHECK(highest - lowest < 1e-9);
                CHECK(fastest < (method == Method::solver ? 1e-6 : 1e-9));
                CHECK(lowest == Approx(0.2).margin(give));
                CHECK(highest == Approx(0.2).margin(give));
            }
}
