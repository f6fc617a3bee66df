// The World's handles: remove and disable without a trace, stale handles detected, user values,
// setters that wake, and gravity scaled per body (exact free flight where the method is exact).
#include "random_scene.hpp"
#include "scene_builders.hpp"

#include "rube/physics/world.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <stdexcept>

using namespace rube;
using test::ball;
using test::line;
using test::makeRandomScene;
using test::RandomScene;

namespace {

constexpr Method kMethods[] = {Method::discrete, Method::turnBased, Method::exact, Method::solver, Method::automatic};

// Far from everything else: a fixed ball on a short floor of its own, left of the scene. Fixed, and
// the size of the pile's balls, because the methods' global choices see every body: a dynamic ball
// resting there adds events to exact's cap per step and bodies to auto's budget, and another size
// changes the solver's grid cells, so the two worlds would part before the removal (measured: 30 of
// 150 runs with a 0.25 m dynamic ball); the check just after the removal makes sure they did not.
struct FarBodies {
    CircleId ball;
    SegmentId floor;
};

FarBodies addFarBodies(World& world, Vec2 at, Motion motion) {
    FarBodies far;
    far.floor = world.addSegment(line(at + Vec2{-1.0, 0.0}, at + Vec2{1.0, 0.0}));
    CircleDef def = ball(at + Vec2{0.0, 0.3}, {}, 0.3);
    def.material = {0.3, 0.4};
    def.motion = motion;
    far.ball = world.addCircle(def);
    return far;
}

// A pile of `n` x `n` balls with friction in a box, sleeping allowed (solver and auto put it to sleep).
void addPile(World& world, int n) {
    world.addSegment(line({-2.0, 0.0}, {2.0, 0.0}));
    world.addSegment(line({-2.0, 0.0}, {-2.0, 6.0}));
    world.addSegment(line({2.0, 0.0}, {2.0, 6.0}));
    for (int row = 0; row < n; ++row)
        for (int col = 0; col < n; ++col) {
            CircleDef def = ball({-1.5 + 0.61 * col + 0.05 * (row % 2), 0.3 + 0.62 * row}, {}, 0.3);
            def.material = {0.2, 0.5};
            world.addCircle(def);
        }
}

} // namespace

TEST_CASE("handles: a far body removed at step k leaves a world bit-identical to one it never was in", "[handles]") {
    const int k = 40, steps = 160;
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        for (const Method method : kMethods) {
            CAPTURE(seed, methodName(method));
            FarBodies far;
            RandomScene with = makeRandomScene(seed, [&](World& world, Vec2 size) {
                far = addFarBodies(world, {-0.8 * size.x, -0.5 * size.y}, Motion::fixed);
            });
            RandomScene without = makeRandomScene(seed);
            if (with.turning && !movesTurningBodies(method)) continue;
            with.world.setMethod(method);
            without.world.setMethod(method);
            for (int step = 0; step < steps; ++step) {
                if (step == k) {
                    with.world.remove(far.ball);
                    with.world.remove(far.floor);
                    INFO("just after the removal");
                    REQUIRE(stateHash(with.world) == stateHash(without.world));
                }
                with.world.step();
                without.world.step();
                if (step >= k) REQUIRE(stateHash(with.world) == stateHash(without.world));
            }
        }
    }
    // A pile that falls asleep under solver and auto, its far neighbour removed while it sleeps or settles.
    for (const Method method : kMethods) {
        for (const int at : {30, 280}) {
            CAPTURE(methodName(method), at);
            WorldDef def;
            def.method = method;
            World with(def), without(def);
            const FarBodies far = addFarBodies(with, {-20.0, 0.0}, Motion::fixed);
            addPile(with, 5);
            addPile(without, 5);
            for (int step = 0; step < 320; ++step) {
                if (step == at) {
                    if (method == Method::solver && at > 100)
                        CHECK(with.circles()[1].sleep.asleep); // removed while the pile sleeps
                    with.remove(far.ball);
                }
                if (step == at + 1) {
                    with.remove(far.floor);
                    CHECK(stateHash(with) == stateHash(without));
                }
                with.step();
                without.step();
            }
            CHECK(stateHash(with) == stateHash(without));
            if (method == Method::solver) CHECK(with.circles()[0].sleep.asleep); // it did fall asleep
        }
    }
}

TEST_CASE("handles: a far rigid body removed from a stack's world leaves no trace under solver and auto",
          "[handles][rigid]") {
    for (const Method method : {Method::solver, Method::automatic}) {
        CAPTURE(methodName(method));
        WorldDef def;
        def.method = method;
        World with(def), without(def);
        RigidBodyDef box;
        box.halfExtents = {0.5, 0.25};
        box.material = {0.1, 0.6};
        box.position = {-30.0, 0.25};
        const BodyId farBox = with.addBody(box);
        for (World* world : {&with, &without}) {
            world->addSegment(line({-40.0, 0.0}, {5.0, 0.0}));
            for (int i = 0; i < 4; ++i) {
                box.position = {0.05 * i, 0.25 + 0.5 * i};
                box.angle = 0.02 * i;
                world->addBody(box);
            }
        }
        for (int step = 0; step < 240; ++step) {
            if (step == 60) with.remove(farBox);
            with.step();
            without.step();
        }
        CHECK(stateHash(with) == stateHash(without));
    }
}

TEST_CASE("handles: removing what a ball rests on lets it fall, also from sleep", "[handles]") {
    for (const Method method : kMethods) {
        CAPTURE(methodName(method));
        WorldDef def;
        def.method = method;
        World world(def);
        world.addSegment(line({-5.0, 0.0}, {5.0, 0.0}));
        const SegmentId shelf = world.addSegment(line({-1.0, 2.0}, {1.0, 2.0}));
        const CircleId lower = world.addCircle(ball({3.0, 0.3}, {}, 0.3));
        const CircleId upper = world.addCircle(ball({3.0, 0.9}, {}, 0.3));
        const CircleId onShelf = world.addCircle(ball({0.0, 2.3}, {}, 0.3));
        for (int i = 0; i < 240; ++i) world.step();
        const double upperAt = world.circle(upper).position.y, shelfAt = world.circle(onShelf).position.y;
        REQUIRE(upperAt == Approx(0.9).margin(0.02));
        REQUIRE(shelfAt == Approx(2.3).margin(0.02));
        world.remove(lower);
        world.remove(shelf);
        // Free fall onto the floor: 0.6 m in sqrt(2 x 0.6 / g) = 0.35 s; after 0.2 s it has fallen
        // g t^2 / 2, to within the g t dt / 2 of an Euler sum and the g dt t of the speed a resting
        // contact may leave it with (turn-based: measured 1.5 g t dt over).
        for (int i = 0; i < 12; ++i) world.step();
        const double t = 12 * def.timeStep, drop = 0.5 * 9.81 * t * t, slack = 2.0 * 9.81 * t * def.timeStep;
        CHECK(upperAt - world.circle(upper).position.y == Approx(drop).margin(slack));
        CHECK(shelfAt - world.circle(onShelf).position.y == Approx(drop).margin(slack));
        CHECK(!world.isValid(lower));
        CHECK(world.circles().size() == 2);
    }
}

TEST_CASE("handles: a disabled ball neither moves nor is met, and goes on as it was once enabled", "[handles]") {
    for (const Method method : kMethods) {
        CAPTURE(methodName(method));
        WorldDef def;
        def.method = method;
        def.gravity = {0.0, 0.0};
        // A ball drifting right and a ball crossing its path while it is disabled; a reference world
        // holds the drifting ball alone.
        World world(def), alone(def);
        const CircleId drifting = world.addCircle(ball({0.0, 0.0}, {1.0, 0.0}, 0.2));
        const CircleId crossing = world.addCircle(ball({1.0, 3.0}, {0.0, -3.0}, 0.2));
        alone.addCircle(ball({0.0, 0.0}, {1.0, 0.0}, 0.2));
        for (int i = 0; i < 30; ++i) {
            world.step();
            alone.step();
        }
        world.setEnabled(drifting, false);
        const Circle held = world.circle(drifting);
        CHECK(!world.isEnabled(drifting));
        CHECK(world.slot(drifting) == -1);
        for (int i = 0; i < 90; ++i) world.step();
        // Held still, and the crossing ball went straight through where it waits.
        CHECK(world.circle(drifting).position == held.position);
        CHECK(world.circle(drifting).velocity == held.velocity);
        CHECK(world.circle(crossing).velocity == Vec2{0.0, -3.0});
        const std::int64_t escapes = world.stats().escapes;
        world.setEnabled(drifting, true);
        CHECK(world.slot(drifting) == 0); // back in its place in insertion order
        for (int i = 0; i < 60; ++i) {
            world.step();
            alone.step();
        }
        CHECK(world.circle(drifting).position == alone.circles()[0].position);
        CHECK(world.circle(drifting).velocity == alone.circles()[0].velocity);
        CHECK(world.stats().escapes == escapes); // nothing left the bounds
    }
    // An escaped ball disabled and enabled again is not counted twice.
    WorldDef def;
    def.bounds = Aabb{{-1.0, -1.0}, {1.0, 1.0}};
    World world(def);
    const CircleId leaving = world.addCircle(ball({0.0, 0.0}, {30.0, 0.0}, 0.1));
    for (int i = 0; i < 10; ++i) world.step();
    REQUIRE(world.stats().escapes == 1);
    world.setEnabled(leaving, false);
    world.setEnabled(leaving, true);
    world.step();
    CHECK(world.stats().escapes == 1);
}

TEST_CASE("handles: stale handles are detected after remove and re-add into the same entry and slot", "[handles]") {
    World world;
    const CircleId a = world.addCircle(ball({0.0, 0.0}, {}, 0.5));
    const CircleId b = world.addCircle(ball({2.0, 0.0}, {}, 0.5));
    const BodyId box = world.addBody(RigidBodyDef{});
    const RopeId rope = world.addRope(RopeDef{b, {}, {2.0, 2.0}, 2.0});
    world.remove(b);
    CHECK(!world.isValid(b));
    CHECK(!world.isValid(rope)); // its rope went with it
    const CircleId c = world.addCircle(ball({4.0, 0.0}, {}, 0.5));
    CHECK(c.index == b.index); // the entry is reused...
    CHECK(c.generation != b.generation);
    CHECK(world.slot(c) == 1); // ...and so is the slot
    CHECK(!world.isValid(b));
    CHECK_THROWS_AS(world.circle(b), std::invalid_argument);
    CHECK_THROWS_AS(world.setVelocity(b, {1.0, 0.0}), std::invalid_argument);
    CHECK_THROWS_AS(world.remove(b), std::invalid_argument);
    CHECK_THROWS_AS(world.circle(CircleId{}), std::invalid_argument);
    CHECK(world.circle(c).position == Vec2{4.0, 0.0});
    CHECK(world.circleId(0) == a);
    CHECK(world.circleId(1) == c);
    const PivotId pivot = world.addPivot(PivotDef{box, {}, {}});
    world.remove(box);
    CHECK(!world.isValid(pivot)); // its pivot went with it
    CHECK(world.pivots().empty());
}

TEST_CASE("handles: user values and gravity scales come from the def, and setters change them", "[handles]") {
    World world;
    CircleDef def = ball({0.0, 0.0}, {}, 0.5);
    def.userValue = 0xfeedface12345678ull;
    def.gravityScale = -1.0;
    const CircleId first = world.addCircle(def);
    const CircleId second = world.addCircle(ball({5.0, 0.0}, {}, 0.5));
    RigidBodyDef boxDef;
    boxDef.userValue = 7;
    const BodyId box = world.addBody(boxDef);
    CHECK(world.userValue(first) == 0xfeedface12345678ull);
    CHECK(world.userValue(second) == 0);
    CHECK(world.userValue(box) == 7);
    CHECK(world.circle(first).gravityScale == -1.0);
    world.setUserValue(second, 42);
    world.setGravityScale(second, 0.5);
    world.remove(first);
    CHECK(world.userValue(second) == 42); // kept when others' slots move
    CHECK(world.circle(second).gravityScale == 0.5);
}

TEST_CASE("handles: an impulse at a point changes v by J / m and omega by r x J / I", "[handles][rigid]") {
    WorldDef def;
    def.method = Method::solver;
    World world(def);
    RigidBodyDef d;
    d.halfExtents = {1.0, 0.25};
    d.mass = 3.0;
    const BodyId plank = world.addBody(d);
    const double inertia = 3.0 * (4.0 + 0.25) / 12.0; // m (w^2 + h^2) / 12
    for (const double along : {-1.0, -0.3, 0.0, 0.6}) {
        const RigidBody before = world.body(plank);
        const Vec2 impulse{0.2, 1.5};
        world.applyImpulseAt(plank, impulse, before.position + Vec2{along, 0.0});
        const RigidBody& after = world.body(plank);
        CHECK(approxEqual(after.velocity - before.velocity, impulse / 3.0, 1e-15));
        CHECK(after.angularVelocity - before.angularVelocity == Approx(along * 1.5 / inertia).margin(1e-15));
    }
}

TEST_CASE("handles: a setter wakes a sleeping island", "[handles][sleep]") {
    WorldDef def;
    def.method = Method::solver;
    World world(def);
    addPile(world, 3);
    for (int i = 0; i < 300; ++i) world.step();
    REQUIRE(world.circles()[0].sleep.asleep);
    const Circle kicked = world.circles()[8];
    const Vec2 before = kicked.position;
    world.applyImpulse(world.circleId(8), {0.0, 0.5}); // 1 kg: 0.5 m/s up
    CHECK(!world.circles()[8].sleep.asleep);
    for (const Circle& c : world.circles())
        if (c.sleep.island == kicked.sleep.island) CHECK(!c.sleep.asleep); // its island woke with it
    world.step();
    CHECK(world.circles()[8].position.y > before.y + 0.5 * world.def().timeStep * 0.5);
}

TEST_CASE("handles: a lone ball's flight under gravity scale s is x0 + v0 t + s g t^2 / 2", "[handles][gravity]") {
    const Vec2 g{0.0, -9.81}, x0{0.0, 100.0}, v0{3.0, 4.0};
    for (const Method method : kMethods) {
        for (const double s : {-2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 1.7, 3.0}) {
            CAPTURE(methodName(method), s);
            WorldDef def;
            def.method = method;
            def.gravity = g;
            World world(def);
            CircleDef d = ball(x0, v0, 0.1);
            d.gravityScale = s;
            const CircleId id = world.addCircle(d);
            double worst = 0.0, worstSpeed = 0.0;
            for (int i = 0; i < 120; ++i) {
                world.step();
                const double t = world.time();
                const Vec2 expected = x0 + v0 * t + g * (0.5 * s * t * t);
                worst = std::max(worst, world.circle(id).position.distance(expected));
                worstSpeed = std::max(worstSpeed, world.circle(id).velocity.distance(v0 + g * (s * t)));
            }
            // Exact, auto and the solver (its free flight is exact) move it exactly: round-off of 100 m.
            // Discrete and turn-based miss by the g t dt / 2 of their Euler step for gravity itself, whatever
            // s: the difference (s - 1) g is split around the move, which makes its share exact.
            const bool exact = method == Method::exact || method == Method::automatic || method == Method::solver;
            CHECK(worst <= (exact ? 1e-12 : 9.81 * 2.0 * def.timeStep / 2.0 * (1.0 + 1e-9)));
            CHECK(worstSpeed <= 1e-12);
        }
    }
}

TEST_CASE("handles: an impact leads to its circle's handle and user value, also after a removal renumbers the slots",
          "[handles]") {
    World world;
    world.addSegment(line({-5.0, 0.0}, {5.0, 0.0}));
    const CircleId gone = world.addCircle(ball({-2.0, 0.5}, {0.0, -5.0}, 0.5)); // both land in the first step
    CircleDef def = ball({2.0, 0.6}, {0.0, -6.0}, 0.5);
    def.userValue = 99;
    const CircleId kept = world.addCircle(def);
    for (int i = 0; i < 60 && world.lastImpacts().size() < 2; ++i) world.step();
    REQUIRE(world.lastImpacts().size() == 2);
    world.remove(gone);
    // The removed circle's impact is dropped; the other's names its new slot.
    REQUIRE(world.lastImpacts().size() == 1);
    const Impact& impact = world.lastImpacts()[0];
    CHECK(impact.circle == 0);
    CHECK(world.circleId(impact.circle) == kept);
    CHECK(world.userValue(world.circleId(impact.circle)) == 99);
    CHECK(world.segmentId(impact.other) == world.segmentId(0));
}
