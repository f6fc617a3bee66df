// Sleeping with ropes (issue 26): a rope's circles share an island, a taut rope holds its circle
// towards its other end, and a circle's speed is judged as the rope pass will leave it. So a weight
// hanging still sleeps, a pendulum that drag brings to rest sleeps no sooner and no later than its
// decay allows, and a ball that strikes it, a moving rope end or a cut wakes exactly its island.
// Under the solver, and under auto where the island is the solver's (balls with friction on a floor);
// auto's exact islands (a lone pendulum touches nothing with friction) keep exact's behaviour and
// stay awake, which one case pins down.
#include "rube/physics/rope.hpp"
#include "rube/physics/world.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

using namespace rube;

namespace {

constexpr double kG = 10.0;

WorldDef ropeDef(Method method = Method::solver, double sleepSpeed = WorldDef{}.sleepSpeed, double drag = 0.0) {
    WorldDef def;
    def.method = method;
    def.gravity = {0.0, -kG};
    def.sleepSpeed = sleepSpeed;
    def.airDrag.linear = drag;
    return def;
}

/// A ball of `radius` and `mass` on a rope of `length` from `anchor`, released from rest at `angle`
/// radians from straight down.
CircleId addPendulum(World& world, Vec2 anchor, double length, double angle, double mass = 1.0, double radius = 0.1) {
    CircleDef ball;
    ball.position = anchor + Vec2{std::sin(angle), -std::cos(angle)} * length;
    ball.radius = radius;
    ball.mass = mass;
    const CircleId circle = world.addCircle(ball);
    world.addRope(RopeDef{circle, {}, anchor, length});
    return circle;
}

/// A 1 kg ball of radius 0.1 m thrown at `velocity` from `position`.
CircleDef thrown(Vec2 position, Vec2 velocity) {
    CircleDef ball;
    ball.position = position;
    ball.velocity = velocity;
    ball.radius = 0.1;
    return ball;
}

/// Steps until `id` is asleep: the step count, or -1 after `most` steps.
int stepsToSleep(World& world, CircleId id, int most) {
    for (int s = 1; s <= most; ++s) {
        world.step();
        if (world.circle(id).sleep.asleep) return s;
    }
    return -1;
}

} // namespace

TEST_CASE("rope sleep: a weight hanging still sleeps after timeToSleep, at the rope's length, and costs nothing",
          "[sleep][rope]") {
    const double length = GENERATE(0.5, 2.0, 7.0);
    const double mass = GENERATE(0.2, 5.0);
    World world(ropeDef());
    const Vec2 anchor{1.0, 10.0};
    const CircleId weight = addPendulum(world, anchor, length, 0.0, mass);
    const double dt = world.def().timeStep;
    const int steps = stepsToSleep(world, weight, static_cast<int>(std::ceil((world.def().timeToSleep + 0.2) / dt)));
    INFO("L " << length << " m, m " << mass << " kg: asleep after " << steps << " steps");
    REQUIRE(steps > 0);
    CHECK(steps >= static_cast<int>(std::floor(world.def().timeToSleep / dt))); // slow for timeToSleep first
    // Asleep where the rope holds it: straight below the anchor, L from it (the rope pass put it back).
    const Vec2 rest = world.circle(weight).position;
    CHECK(rest.distance(anchor) == Approx(length).epsilon(1e-12));
    CHECK(std::abs(rest.x - anchor.x) < 1e-12);
    for (int s = 0; s < 120; ++s) world.step();
    CHECK(world.circle(weight).sleep.asleep);
    CHECK(world.circle(weight).position == rest);
}

TEST_CASE("rope sleep: a pendulum damped by drag sleeps once its swing has decayed, not before", "[sleep][rope]") {
    // Linear drag: dv/dt = -k v, k = 2 r linear / m (AirDrag::linearRate), so the small swing obeys
    // theta'' + k theta' + (g / L) theta = 0 and its amplitude decays as e^(-k t / 2). It may sleep
    // only once it has been under sleepSpeed for timeToSleep: its speed amplitude
    // theta0 e^(-k t / 2) sqrt(g L) must be under sleepSpeed (a lower bound on the time). It must be
    // held too (gravity's pull across the rope, g sin theta, under 1e-5 m/s^2): at the latest once the
    // amplitude is under 1e-5 / g, then after timeToSleep more (an upper bound, plus a second's slack).
    const double length = GENERATE(0.5, 1.5);
    const double k = GENERATE(0.5, 1.0); // 1/s
    const double theta0 = 0.3;
    const double radius = 0.1, mass = 1.0;
    World world(ropeDef(Method::solver, WorldDef{}.sleepSpeed, k * mass / (2.0 * radius)));
    const Vec2 anchor{0.0, 5.0};
    const CircleId bob = addPendulum(world, anchor, length, theta0, mass, radius);
    const double speedAmplitude = theta0 * std::sqrt(kG * length);
    const double earliest = 2.0 / k * std::log(speedAmplitude / world.def().sleepSpeed);
    const double latest = 2.0 / k * std::log(theta0 / (1e-5 / kG)) + world.def().timeToSleep + 1.0;
    const double dt = world.def().timeStep;
    const int steps = stepsToSleep(world, bob, static_cast<int>(latest / dt));
    const double t = steps * dt;
    INFO("L " << length << " m, k " << k << "/s: asleep at " << t << " s (between " << earliest << " and " << latest
              << " s)");
    REQUIRE(steps > 0);
    CHECK(t >= earliest);
    // Held where it sleeps: within the hold rule's angle of straight down.
    const Vec2 d = world.circle(bob).position - anchor;
    CHECK(std::abs(d.x / d.length()) * kG <= 1e-5 * 1.0001);
}

TEST_CASE("rope sleep: a held-aside swing is not held, so without drag a pendulum never sleeps", "[sleep][rope]") {
    // No drag: the swing keeps its energy, and passes under sleepSpeed only briefly at each end.
    const double theta0 = GENERATE(0.01, 0.3);
    World world(ropeDef());
    const CircleId bob = addPendulum(world, {0.0, 5.0}, 1.0, theta0);
    bool everAsleep = false;
    for (int s = 0; s < 600; ++s) {
        world.step();
        everAsleep = everAsleep || world.circle(bob).sleep.asleep;
    }
    CHECK_FALSE(everAsleep);
}

TEST_CASE("rope sleep: a ball striking one sleeping pendulum wakes it and not the other", "[sleep][rope]") {
    World world(ropeDef());
    const CircleId struck = addPendulum(world, {0.0, 5.0}, 1.0, 0.0);
    const CircleId still = addPendulum(world, {3.0, 5.0}, 1.0, 0.0);
    // A double pendulum: a second ball hangs from the first of a third pair; one island of two.
    const CircleId upper = addPendulum(world, {6.0, 5.0}, 1.0, 0.0);
    CircleDef lowerDef;
    lowerDef.position = {6.0, 3.0};
    lowerDef.radius = 0.1;
    const CircleId lower = world.addCircle(lowerDef);
    world.addRope(RopeDef{lower, upper, {}, 1.0});
    for (int s = 0; s < 90; ++s) world.step();
    REQUIRE(world.circle(struck).sleep.asleep);
    REQUIRE(world.circle(still).sleep.asleep);
    REQUIRE(world.circle(upper).sleep.asleep);
    REQUIRE(world.circle(lower).sleep.asleep);
    CHECK(world.circle(upper).sleep.island == world.circle(lower).sleep.island);
    // A ball thrown sideways at the first bob, at its height; gravity drops it 5 cm on the way.
    world.addCircle(thrown({-1.0, 4.05}, {5.0, 0.0}));
    bool woke = false;
    for (int s = 0; s < 30; ++s) {
        world.step();
        woke = woke || !world.circle(struck).sleep.asleep;
    }
    CHECK(woke);
    CHECK(world.circle(struck).position.x > 0.05); // knocked aside, and swinging
    CHECK(world.circle(still).sleep.asleep);
    CHECK(world.circle(upper).sleep.asleep);
    // A setter on the lower ball of the pair wakes the whole pair.
    world.setVelocity(lower, {0.5, 0.0});
    CHECK_FALSE(world.circle(upper).sleep.asleep);
    CHECK_FALSE(world.circle(lower).sleep.asleep);
}

TEST_CASE("rope sleep: a rope's end moving on its path, or the rope cut, wakes what it holds", "[sleep][rope]") {
    const bool cut = GENERATE(false, true);
    World world(ropeDef());
    // The rope hangs from a kinematic circle that stands still for 3 s, then moves 1 m right in 1 s.
    KinematicPath path;
    path.keys = {{0.0, {0.0, 0.0}}, {3.0, {0.0, 0.0}}, {4.0, {1.0, 0.0}}};
    CircleDef holderDef;
    holderDef.position = {0.0, 5.0};
    holderDef.radius = 0.05;
    holderDef.motion = Motion::kinematic;
    holderDef.path = world.addPath(path);
    const CircleId holder = world.addCircle(holderDef);
    CircleDef weightDef;
    weightDef.position = {0.0, 4.0};
    weightDef.radius = 0.1;
    const CircleId weight = world.addCircle(weightDef);
    const RopeId rope = world.addRope(RopeDef{weight, holder, {}, 1.0});
    for (int s = 0; s < 120; ++s) world.step();
    REQUIRE(world.circle(weight).sleep.asleep);
    if (cut) {
        world.cutRope(rope);
        CHECK_FALSE(world.circle(weight).sleep.asleep);
        for (int s = 0; s < 30; ++s) world.step();
        // Free fall from rest: g t^2 / 2 over half a second, within semi-implicit Euler's excess g dt t / 2.
        const double dt = world.def().timeStep;
        CHECK(world.circle(weight).position.y == Approx(4.0 - 0.5 * kG * 0.25).margin(0.5 * kG * dt * 0.5 + 1e-3));
        return;
    }
    while (world.time() < 3.0 - 1e-9) world.step();
    CHECK(world.circle(weight).sleep.asleep);
    world.step();
    world.step();
    CHECK_FALSE(world.circle(weight).sleep.asleep);
    for (int s = 0; s < 30; ++s) world.step();
    CHECK(world.circle(weight).position.x > 0.05); // dragged after the holder
}

TEST_CASE("rope sleep: sleeping on or off, a damped pendulum rests in the same place", "[sleep][rope]") {
    // Both runs come to rest; sleeping stops the bob only after timeToSleep under sleepSpeed, so
    // they agree within sleepSpeed x timeToSleep (5 mm), the bound checked.
    const double theta0 = GENERATE(0.2, 0.6);
    const auto run = [&](double sleepSpeed) {
        World world(ropeDef(Method::solver, sleepSpeed, 5.0));
        addPendulum(world, {0.0, 5.0}, 1.0, theta0);
        for (int s = 0; s < 60 * 40; ++s) world.step();
        return world.circles()[0];
    };
    const Circle asleep = run(WorldDef{}.sleepSpeed), awake = run(0.0);
    CHECK(asleep.sleep.asleep);
    const double bound = WorldDef{}.sleepSpeed * WorldDef{}.timeToSleep;
    INFO("difference " << asleep.position.distance(awake.position) << " m (bound " << bound << " m)");
    CHECK(asleep.position.distance(awake.position) <= bound);
}

TEST_CASE("rope sleep: deterministic, the same state hash run twice", "[sleep][rope][determinism]") {
    const auto run = [] {
        World world(ropeDef(Method::solver, WorldDef{}.sleepSpeed, 2.0));
        addPendulum(world, {0.0, 5.0}, 1.0, 0.0);
        addPendulum(world, {2.0, 5.0}, 1.5, 0.4);
        std::vector<std::uint64_t> hashes;
        for (int s = 0; s < 600; ++s) {
            if (s == 200) world.addCircle(thrown({-1.0, 4.05}, {5.0, 0.0}));
            world.step();
            hashes.push_back(stateHash(world));
        }
        return hashes;
    };
    CHECK(run() == run());
}

TEST_CASE("rope sleep: under auto a lone pendulum is exact's and keeps exact's behaviour (awake)", "[sleep][rope]") {
    World world(ropeDef(Method::automatic));
    const CircleId weight = addPendulum(world, {0.0, 5.0}, 1.0, 0.0);
    for (int s = 0; s < 120; ++s) world.step();
    CHECK_FALSE(world.circle(weight).sleep.asleep);
    CHECK(world.stats().autoSolverSteps == 0);
}

TEST_CASE("rope sleep: under auto, roped balls on a floor with friction (the solver's island) sleep and wake",
          "[sleep][rope]") {
    // Friction between the balls and the floor makes the island the solver's (method_auto.cpp), which
    // sleeps with its ropes as under the solver; a rope between the two balls ties them into one island.
    const Method method = GENERATE(Method::solver, Method::automatic);
    INFO("method " << methodName(method));
    World world(ropeDef(method));
    SegmentDef floor;
    floor.a = {-10.0, 0.0};
    floor.b = {10.0, 0.0};
    floor.material = {0.0, 1.0};
    world.addSegment(floor);
    CircleDef ballDef;
    ballDef.radius = 0.2;
    ballDef.material = {0.0, 0.5};
    ballDef.position = {0.0, 0.2};
    const CircleId a = world.addCircle(ballDef);
    ballDef.position = {1.0, 0.2};
    const CircleId b = world.addCircle(ballDef);
    world.addRope(RopeDef{a, {}, {-1.0, 0.2}, 1.0}); // taut, along the floor
    world.addRope(RopeDef{b, a, {}, 1.0});
    for (int s = 0; s < 60; ++s) world.step();
    REQUIRE(world.circle(a).sleep.asleep);
    REQUIRE(world.circle(b).sleep.asleep);
    CHECK(world.circle(a).sleep.island == world.circle(b).sleep.island);
    // A ball rolled at b wakes both (one island through the rope) and pulls the rope taut.
    CircleDef rolled = ballDef;
    rolled.position = {3.0, 0.2};
    rolled.velocity = {-3.0, 0.0};
    world.addCircle(rolled);
    bool wokeA = false, wokeB = false;
    for (int s = 0; s < 60; ++s) {
        world.step();
        wokeA = wokeA || !world.circle(a).sleep.asleep;
        wokeB = wokeB || !world.circle(b).sleep.asleep;
    }
    CHECK(wokeA);
    CHECK(wokeB);
    if (method == Method::automatic) CHECK(world.stats().autoSolverSteps > 0);
}
