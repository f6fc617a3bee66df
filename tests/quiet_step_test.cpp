// Quiet steps (issue 26, engine/physics/src/quiet_step.hpp): a solver world whose every dynamic circle
// is asleep and still is stepped without its per-body passes. Two things must hold. The shortcut is
// taken exactly when it may be: in every step that starts with all asleep and still, and in no
// other (StepStats::quietSteps counts them). And it changes nothing: a world that takes it ends
// every step bit-identical to the same world kept from it by a kinematic segment that stands still
// far away (any body on a path makes every step a full one), through settling, quiet steps, a
// sleeping rope pulled by its moved fixed end, a fixed circle moved out of bounds and then made
// non-finite, and wake-ups by a push, a cut rope and a removed circle.
#include "quiet_step.hpp"
#include "rube/physics/rope.hpp"
#include "rube/physics/world.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

using namespace rube;

namespace {

WorldDef quietDef() {
    WorldDef def;
    def.method = Method::solver;
    def.gravity = {0.0, -9.81};
    return def;
}

/// What a scene builder returns: the circles a test pushes, and the rope it cuts.
struct Scene {
    std::vector<CircleId> weights; // one per pendulum
    RopeId chainTop;               // the upper rope of the double pendulum
    CircleId pileBall;             // a ball of the pile, removed in one case
    CircleId hook;                 // a fixed circle a weight hangs from
    CircleId marker;               // a fixed circle on its own, moved out of bounds in one case
};

/// A V-shaped bin with friction, its bottom at `bottom`.
void addBin(World& world, Vec2 bottom) {
    for (const double side : {-1.0, 1.0}) {
        SegmentDef wall;
        wall.a = bottom;
        wall.b = bottom + Vec2{2.0 * side, 2.0};
        wall.material.friction = 0.6;
        world.addSegment(wall);
    }
}

/// `pendulums` weights hanging still on ropes of lengths 0.5 to 2 m, a fixed circle on its own, a
/// small pile of balls with friction in a bin, and with `chains` a double pendulum (a rope between
/// two circles: the rope pass's chain passes) and a weight roped to a fixed circle.
Scene build(World& world, int pendulums, bool chains) {
    Scene scene;
    for (int i = 0; i < pendulums; ++i) {
        const double length = 0.5 + 1.5 * i / std::max(1, pendulums - 1);
        const Vec2 anchor{-20.0 + 0.7 * i, 10.0};
        CircleDef ball;
        ball.position = anchor - Vec2{0.0, length};
        ball.radius = 0.2;
        ball.mass = 0.5 + 0.25 * i;
        scene.weights.push_back(world.addCircle(ball));
        world.addRope(RopeDef{scene.weights.back(), {}, anchor, length});
    }
    CircleDef marker;
    marker.position = {30.0, 0.0};
    marker.radius = 0.1;
    marker.motion = Motion::fixed;
    scene.marker = world.addCircle(marker);
    addBin(world, {0.0, 0.0});
    for (int i = 0; i < 6; ++i) {
        CircleDef ball;
        ball.position = {-0.5 + 0.2 * i, 0.6 + 0.45 * i};
        ball.radius = 0.2;
        ball.material.friction = 0.6;
        const CircleId id = world.addCircle(ball);
        if (i == 3) scene.pileBall = id;
    }
    if (!chains) return scene;
    CircleDef upper;
    upper.position = {10.0, 8.0};
    upper.radius = 0.15;
    upper.material.friction = 0.6; // to come to rest in the bin below once cut
    const CircleId a = world.addCircle(upper);
    CircleDef lower = upper;
    lower.position = {10.0, 7.0};
    const CircleId b = world.addCircle(lower);
    scene.chainTop = world.addRope(RopeDef{a, {}, {10.0, 9.0}, 1.0});
    world.addRope(RopeDef{b, a, {}, 1.0});
    addBin(world, {10.0, 4.0}); // what the double pendulum falls into once cut
    CircleDef hook = marker;
    hook.position = {14.0, 9.0};
    scene.hook = world.addCircle(hook);
    CircleDef hung;
    hung.position = {14.0, 7.8};
    hung.radius = 0.2;
    world.addRope(RopeDef{world.addCircle(hung), scene.hook, {}, 1.2});
    return scene;
}

/// A kinematic segment standing still on its path, far from everything: it touches nothing, and
/// keeps every step of its world a full one.
void addStillPaddle(World& world) {
    const int path = world.addPath(KinematicPath{{PathKey{0.0, {}, 0.0}}, false});
    SegmentDef paddle;
    paddle.a = {60.0, 40.0};
    paddle.b = {61.0, 40.0};
    paddle.path = path;
    world.addSegment(paddle);
}

bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same(Vec2 a, Vec2 b) { return same(a.x, b.x) && same(a.y, b.y); }

/// Every circle's state bit for bit (the quiet world's circles are the first of the other's).
void requireSameCircles(const World& quiet, const World& full, int step) {
    REQUIRE(quiet.circles().size() == full.circles().size());
    for (std::size_t i = 0; i < quiet.circles().size(); ++i) {
        const Circle& q = quiet.circles()[i];
        const Circle& f = full.circles()[i];
        INFO("step " << step << ", circle " << i);
        REQUIRE(same(q.position, f.position));
        REQUIRE(same(q.velocity, f.velocity));
        REQUIRE(same(q.angle, f.angle));
        REQUIRE(same(q.angularVelocity, f.angularVelocity));
        REQUIRE(q.sleep.asleep == f.sleep.asleep);
        REQUIRE(same(q.sleep.slowFor, f.sleep.slowFor));
    }
    REQUIRE(quiet.stats().escapes == full.stats().escapes);
    REQUIRE(quiet.stats().impacts == full.stats().impacts);
    REQUIRE(quiet.stats().isolatedBodies == full.stats().isolatedBodies);
}

/// Every dynamic circle asleep with velocity and spin exactly zero: what a quiet step starts from
/// in a world of circles, fixed segments and ropes that are within their lengths.
std::vector<int> awakeCircles(const World& world) {
    std::vector<int> awake;
    for (std::size_t i = 0; i < world.circles().size(); ++i) {
        const Circle& c = world.circles()[i];
        if (c.motion != Motion::fixed && !(c.sleep.asleep && c.velocity == Vec2{} && c.angularVelocity == 0.0))
            awake.push_back(static_cast<int>(i));
    }
    return awake;
}

bool allAsleepAndStill(const World& world) { return awakeCircles(world).empty(); }

} // namespace

TEST_CASE("quiet step: a settled world steps quietly exactly while all is asleep and still", "[sleep][rope][quiet]") {
    const int pendulums = GENERATE(1, 4, 30);
    const int pushed = GENERATE(1, 3);
    const bool chains = GENERATE(false, true);
    World world(quietDef());
    const Scene scene = build(world, pendulums, chains);
    INFO(pendulums << " pendulums, " << pushed << " pushed" << (chains ? ", chains" : ""));
    std::int64_t quietSteps = 0, awakeSteps = 0, expectedQuiet = 0;
    const auto step = [&] {
        const bool still = allAsleepAndStill(world);
        expectedQuiet += still;
        awakeSteps += !still;
        world.step();
        quietSteps = world.stats().quietSteps;
        REQUIRE(quietSteps == expectedQuiet);
    };
    for (int s = 0; s < 600; ++s) step();
    // All of it settled within 10 s, and each step since has been quiet.
    INFO("awake: " << Catch::Detail::stringify(awakeCircles(world)));
    REQUIRE(allAsleepAndStill(world));
    REQUIRE(quietSteps > 0);
    const std::int64_t settledAt = awakeSteps;
    // A push wakes an island: full steps until it sleeps again, then quiet ones. Pushed up along the
    // rope, as a pendulum without drag set swinging would swing for ever.
    for (int k = 0; k < std::min(pushed, pendulums); ++k)
        world.setVelocity(scene.weights[static_cast<std::size_t>(k)], {0.0, 0.3});
    world.setVelocity(scene.pileBall, {0.4, 0.0});
    for (int s = 0; s < 600 || (!allAsleepAndStill(world) && s < 3000); ++s) step();
    CHECK(awakeSteps > settledAt);
    INFO("awake: " << Catch::Detail::stringify(awakeCircles(world)));
    CHECK(allAsleepAndStill(world));
    const std::int64_t resettled = quietSteps;
    for (int s = 0; s < 60; ++s) step();
    CHECK(quietSteps == resettled + 60);
    // A world that never sleeps never steps quietly.
    WorldDef awakeDef = quietDef();
    awakeDef.sleepSpeed = 0.0;
    World awake(awakeDef);
    build(awake, pendulums, chains);
    for (int s = 0; s < 300; ++s) awake.step();
    CHECK(awake.stats().quietSteps == 0);
}

TEST_CASE("quiet step: the quiet world ends every step bit-identical to the full one", "[sleep][rope][quiet]") {
    const int pendulums = GENERATE(1, 7, 25);
    const int substeps = GENERATE(4, 8);
    const bool chains = GENERATE(false, true);
    WorldDef def = quietDef();
    def.substeps = substeps;
    World quiet(def), full(def);
    const Scene scene = build(quiet, pendulums, chains);
    build(full, pendulums, chains);
    addStillPaddle(full);
    INFO(pendulums << " pendulums, " << substeps << " substeps" << (chains ? ", chains" : ""));
    int step = 0;
    const auto run = [&](int steps) {
        for (int s = 0; s < steps; ++s, ++step) {
            quiet.step();
            full.step();
            requireSameCircles(quiet, full, step);
        }
    };
    run(600);
    REQUIRE(quiet.stats().quietSteps > 0); // else this compares two full worlds
    REQUIRE(full.stats().quietSteps == 0);
    // Without chains every rope is plainly within its length: the quiet steps skip the rope pass
    // and check only what is not asleep. With them, a weight an ulp past its rope's length on a
    // fixed circle makes them run the rope pass and the whole check (quiet_step.hpp).
    const Stillness settled = asleepAndStill(quiet.circles(), quiet.segments(), quiet.ropes());
    REQUIRE(settled == (chains ? Stillness::ropesToPull : Stillness::still));
    std::int64_t quietSteps = quiet.stats().quietSteps;
    // A fixed circle moved out of bounds escapes in a quiet step as in a full one; made non-finite, it
    // is frozen (by the next step, a full one) where it last was finite: where it was moved to.
    const Vec2 outside{quiet.def().bounds.max.x + 1.0, 0.0};
    quiet.setPosition(scene.marker, outside);
    full.setPosition(scene.marker, outside);
    const std::int64_t escapes = quiet.stats().escapes;
    run(30);
    REQUIRE(quiet.stats().escapes == escapes + 1);
    REQUIRE(quiet.stats().quietSteps == quietSteps + 30);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    quiet.setPosition(scene.marker, {nan, nan});
    full.setPosition(scene.marker, {nan, nan});
    run(2);
    REQUIRE(quiet.stats().isolatedBodies == 1);
    REQUIRE(quiet.circle(scene.marker).position == outside);
    quietSteps = quiet.stats().quietSteps;
    if (chains) {
        // Its fixed end moved, a weight asleep on its rope is pulled after it (the rope pass moves a
        // sleeping rope's ends back within its length) and stays asleep.
        const Vec2 hookAt = quiet.circle(scene.hook).position + Vec2{0.1, 0.05};
        quiet.setPosition(scene.hook, hookAt);
        full.setPosition(scene.hook, hookAt);
        run(60);
        REQUIRE(quiet.stats().quietSteps == quietSteps + 60);
    }
    // Woken from outside after quiet steps: warm starts and islands must be as the full step left them.
    quiet.setVelocity(scene.weights.front(), {0.0, 0.3}); // up along its rope: it jerks taut, and rests
    full.setVelocity(scene.weights.front(), {0.0, 0.3});
    quiet.setVelocity(scene.pileBall, {0.0, 2.0});
    full.setVelocity(scene.pileBall, {0.0, 2.0});
    run(400);
    if (chains) {
        quiet.cutRope(scene.chainTop);
        full.cutRope(scene.chainTop);
        run(400);
    }
    quiet.remove(scene.pileBall);
    full.remove(scene.pileBall);
    run(600);
    while (!allAsleepAndStill(quiet) && step < 6000) run(1);
    run(60);
    INFO("awake: " << Catch::Detail::stringify(awakeCircles(quiet)));
    CHECK(quiet.stats().quietSteps > quietSteps);
    CHECK(full.stats().quietSteps == 0);
}
