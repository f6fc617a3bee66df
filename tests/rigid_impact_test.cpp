// Rigid bodies' impacts under the solver: a box or domino that strikes something is reported in
// World::lastImpacts as lecture 3's blocks are (circle -1, body the box), a ball striking a body as
// the ball's impact (otherKind body), each once, at the free-fall speed sqrt(2 g h), and counted in
// the stats; resting contact is never an impact. Rigid bodies count as escapes and NaNs as circles do.
#include "rube/physics/world.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace rube;

namespace {

constexpr double kG = 9.81;

World solverWorld() {
    WorldDef def;
    def.method = Method::solver;
    def.gravity = {0.0, -kG};
    return World(def);
}

void addFloor(World& world) {
    SegmentDef floor;
    floor.a = {-20.0, 0.0};
    floor.b = {20.0, 0.0};
    floor.material = {0.0, 0.5};
    world.addSegment(floor);
}

RigidBodyDef box(Vec2 position, Vec2 size, double mass, double angle = 0.0) {
    RigidBodyDef d;
    d.position = position;
    d.halfExtents = size * 0.5;
    d.mass = mass;
    d.angle = angle;
    d.material = {0.0, 0.5};
    return d;
}

/// Steps for `seconds` and returns every impact reported.
std::vector<Impact> collect(World& world, double seconds) {
    std::vector<Impact> all;
    const int steps = static_cast<int>(std::lround(seconds / world.def().timeStep));
    for (int i = 0; i < steps; ++i) {
        world.step();
        all.insert(all.end(), world.lastImpacts().begin(), world.lastImpacts().end());
    }
    return all;
}

} // namespace

TEST_CASE("a box dropped on the floor is one impact at sqrt(2 g h), reported as the box's", "[rigid][impact]") {
    World world = solverWorld();
    addFloor(world);
    const double h = 1.0; // the underside starts 1 m above the floor
    world.addBody(box({0.0, h + 0.25}, {0.8, 0.5}, 2.0));
    const std::vector<Impact> impacts = collect(world, 3.0);
    REQUIRE(impacts.size() == 1);
    const Impact& impact = impacts.front();
    const double speed = std::sqrt(2.0 * kG * h), time = std::sqrt(2.0 * h / kG);
    std::printf(
        "box on floor: approach %.4f m/s (sqrt(2 g h) %.4f), time %.4f s (sqrt(2 h / g) %.4f), point [%.3f, %.3f]\n",
        impact.approachSpeed, speed, impact.time, time, impact.pointOfImpact.x, impact.pointOfImpact.y);
    CHECK(impact.circle == -1);
    CHECK(impact.body == 0);
    CHECK(impact.otherKind == Other::segment);
    CHECK(impact.other == 0);
    CHECK(impact.normal.y == Approx(1.0));
    // The approach speed is measured before the substep in which it first pushes, a substep or two early.
    CHECK(std::abs(impact.approachSpeed - speed) < 0.02 * speed);
    CHECK(std::abs(impact.time - time) < world.def().timeStep);
    // The point is where the box's anchor stands at the step's end: the soft contact lets it overlap
    // the floor by a few centimetres in its landing step.
    CHECK(std::abs(impact.pointOfImpact.y) < 0.05);
    CHECK(std::abs(impact.pointOfImpact.x) <= 0.4 + 1e-9);
    // Afterwards it rests: resting contact is counted every step until it has been slow for
    // timeToSleep and falls asleep (issue 26), never another impact.
    CHECK(world.stats().impacts == 1);
    CHECK(world.bodies().front().sleep.asleep);
    CHECK(world.stats().restingContacts >= static_cast<std::int64_t>(world.def().timeToSleep / world.def().timeStep));
}

TEST_CASE("a box striking a fixed ball is the box's impact, a ball striking a box is the ball's", "[rigid][impact]") {
    {
        World world = solverWorld();
        addFloor(world);
        CircleDef post;
        post.position = {2.0, 0.3};
        post.radius = 0.3;
        post.motion = Motion::fixed;
        world.addCircle(post);
        RigidBodyDef d = box({0.0, 0.25}, {0.5, 0.5}, 1.0);
        d.velocity = {3.0, 0.0};
        d.material = {0.0, 0.0}; // slides without friction: it meets the post at 3 m/s
        world.addBody(d);
        std::vector<Impact> impacts = collect(world, 1.0);
        // Struck above its centre it tips and lands again on the floor: only the post's impact is checked.
        std::erase_if(impacts, [](const Impact& m) { return m.otherKind != Other::circle; });
        REQUIRE(impacts.size() == 1);
        std::printf("box into a fixed ball: approach %.4f m/s (3)\n", impacts[0].approachSpeed);
        CHECK(impacts[0].circle == -1);
        CHECK(impacts[0].body == 0);
        CHECK(impacts[0].otherKind == Other::circle);
        CHECK(impacts[0].other == 0);
        CHECK(impacts[0].normal.x == Approx(-1.0).margin(1e-6)); // from the ball towards the box
        CHECK(impacts[0].approachSpeed == Approx(3.0).margin(1e-6));
    }
    {
        World world = solverWorld();
        addFloor(world);
        world.addBody(box({0.0, 0.25}, {1.0, 0.5}, 5.0));
        CircleDef ball;
        ball.position = {0.1, 0.5 + 0.8 + 0.2}; // 0.8 m above the box's top
        ball.radius = 0.2;
        world.addCircle(ball);
        std::vector<Impact> impacts = collect(world, 0.5);
        REQUIRE_FALSE(impacts.empty());
        const Impact& impact = impacts.front();
        std::printf("ball on a box: approach %.4f m/s (sqrt(2 g 0.8) %.4f)\n", impact.approachSpeed,
                    std::sqrt(2.0 * kG * 0.8));
        CHECK(impact.circle == 0);
        CHECK(impact.otherKind == Other::body);
        CHECK(impact.other == 0);
        CHECK(impact.body == -1);
        CHECK(impact.normal.y == Approx(1.0)); // from the body towards the ball
        CHECK(std::abs(impact.approachSpeed - std::sqrt(2.0 * kG * 0.8)) < 0.02 * std::sqrt(2.0 * kG * 0.8));
    }
}

TEST_CASE("a box dropped on a resting box: one impact between the two bodies, none from the resting one",
          "[rigid][impact]") {
    World world = solverWorld();
    addFloor(world);
    world.addBody(box({0.0, 0.25}, {1.0, 0.5}, 2.0));
    collect(world, 1.0); // the lower box settles (it starts touching: no impact)
    const std::int64_t before = world.stats().impacts;
    CHECK(before == 0);
    world.addBody(box({0.0, 0.5 + 0.5 + 0.25}, {0.6, 0.5}, 1.0)); // 0.5 m above it
    const std::vector<Impact> impacts = collect(world, 2.0);
    REQUIRE(impacts.size() == 1);
    std::printf("box on a box: approach %.4f m/s (sqrt(2 g 0.5) %.4f)\n", impacts[0].approachSpeed,
                std::sqrt(2.0 * kG * 0.5));
    CHECK(impacts[0].circle == -1);
    CHECK(impacts[0].body == 0); // the pair's lower index, struck from above
    CHECK(impacts[0].otherKind == Other::body);
    CHECK(impacts[0].other == 1);
    CHECK(impacts[0].normal.y == Approx(-1.0)); // towards body 0, from body 1
    CHECK(std::abs(impacts[0].approachSpeed - std::sqrt(2.0 * kG * 0.5)) < 0.02 * std::sqrt(2.0 * kG * 0.5));
    CHECK(world.stats().impacts == 1);
}

TEST_CASE("a rigid body leaving the bounds is one escape, a NaN in its state is flagged", "[rigid][invariants]") {
    WorldDef def;
    def.method = Method::solver;
    def.bounds = {{-5.0, -5.0}, {5.0, 5.0}};
    World world(def);
    RigidBodyDef d = box({0.0, 0.0}, {0.4, 0.2}, 1.0);
    d.velocity = {20.0, 0.0};
    world.addBody(d);
    world.addBody(box({-3.0, -4.0}, {0.4, 0.2}, 1.0)); // falls 1 m in 0.45 s: leaves through the bottom
    for (int i = 0; i < 60; ++i) world.step();
    CHECK(world.stats().escapes == 2); // each once, though both stay out
    CHECK_FALSE(world.stats().nonFinite);
    world.setAngularVelocity(world.bodyId(1), std::nan(""));
    world.step();
    CHECK(world.stats().nonFinite);
}
