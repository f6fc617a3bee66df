// Sleeping islands (solver and auto): a settled pile rests at no cost and holds still, and whatever
// reaches a sleeper wakes its island (and only its island) before it can pass through it.
#include "rube/physics/explosion.hpp"
#include "rube/physics/world.hpp"
#include "scene_builders.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using namespace rube;
using rube::test::ball;
using rube::test::line;

namespace {

WorldDef sleepyDef(Method method = Method::solver) {
    WorldDef def;
    def.method = method;
    return def;
}

/// A ball of radius 0.1 m, 0.1 kg, with the pile's material (bounciness 0.3, friction 0.4).
CircleDef pileBall(Vec2 position) {
    CircleDef c = ball(position, {}, 0.1);
    c.mass = 0.1;
    c.material = {0.3, 0.4};
    return c;
}

/// `count` balls dropped in a loose grid into a box `width` wide (floor and walls with friction 1).
World makeBox(int count, double width, WorldDef def = sleepyDef()) {
    World world(def);
    SegmentDef floor = line({-width / 2, 0.0}, {width / 2, 0.0});
    floor.material = {1.0, 1.0};
    world.addSegment(floor);
    SegmentDef left = line({-width / 2, 0.0}, {-width / 2, 10.0}), right = line({width / 2, 0.0}, {width / 2, 10.0});
    left.material = right.material = floor.material;
    world.addSegment(left);
    world.addSegment(right);
    const int columns = static_cast<int>(width / 0.24);
    for (int i = 0; i < count; ++i) {
        const double shift = (i / columns) % 2 == 1 ? 0.06 : 0.0;
        world.addCircle(pileBall({-width / 2 + 0.15 + (i % columns) * 0.24 + shift, 0.5 + (i / columns) * 0.24}));
    }
    return world;
}

int asleepCount(const World& world) {
    return static_cast<int>(
        std::count_if(world.circles().begin(), world.circles().end(), [](const Circle& c) { return c.sleep.asleep; }));
}

double largestOverlap(const World& world) {
    double worst = 0.0;
    const auto circles = world.circles();
    for (std::size_t i = 0; i < circles.size(); ++i)
        for (std::size_t j = i + 1; j < circles.size(); ++j) {
            const double reach = circles[i].radius + circles[j].radius;
            worst = std::max(worst, reach - circles[i].position.distance(circles[j].position));
        }
    return worst;
}

/// Steps until every circle sleeps (or `maxSteps`); returns the steps taken.
int stepUntilAsleep(World& world, int maxSteps) {
    for (int step = 1; step <= maxSteps; ++step) {
        world.step();
        if (asleepCount(world) == static_cast<int>(world.circles().size())) return step;
    }
    return maxSteps + 1;
}

} // namespace

TEST_CASE("a settled pile falls asleep as one island, only after every ball was slow for the time to sleep",
          "[sleep]") {
    World world = makeBox(300, 3.0);
    const int needed = static_cast<int>(std::lround(world.def().timeToSleep / world.def().timeStep));
    std::vector<double> fastest; // per step: the fastest ball's speed (or its surface's spin speed)
    int firstAsleep = -1;
    for (int step = 0; step < 600 && firstAsleep < 0; ++step) {
        double v = 0.0;
        for (const Circle& c : world.circles())
            v = std::max({v, c.velocity.length(), std::abs(c.angularVelocity) * c.radius});
        world.step();
        fastest.push_back(v);
        const int asleep = asleepCount(world);
        if (asleep > 0) {
            // One island: all of them at once, never a part.
            CHECK(asleep == 300);
            firstAsleep = step;
        }
    }
    INFO("all 300 asleep after step " << firstAsleep);
    REQUIRE(firstAsleep > 0);
    CHECK(firstAsleep < 420); // settled within 7 s
    // Every ball stayed under sleep_speed for the whole time to sleep before the island slept.
    REQUIRE(static_cast<int>(fastest.size()) > needed);
    for (int k = static_cast<int>(fastest.size()) - needed + 1; k < static_cast<int>(fastest.size()); ++k)
        CHECK(fastest[static_cast<std::size_t>(k)] < world.def().sleepSpeed);
    // Asleep, the pile holds still exactly, with zero velocity and spin, and no overlap beyond 5 % r.
    std::vector<Vec2> before;
    for (const Circle& c : world.circles()) before.push_back(c.position);
    for (int step = 0; step < 120; ++step) world.step();
    for (std::size_t i = 0; i < before.size(); ++i) {
        REQUIRE(world.circles()[i].position == before[i]);
        REQUIRE(world.circles()[i].velocity == Vec2{});
        REQUIRE(world.circles()[i].angularVelocity == 0.0);
    }
    CHECK(largestOverlap(world) < 0.005);
}

TEST_CASE("a ball dropped on a sleeping pile wakes it and comes to rest on top without sinking in", "[sleep]") {
    World world = makeBox(120, 2.0);
    REQUIRE(stepUntilAsleep(world, 600) <= 600);
    double top = 0.0;
    for (const Circle& c : world.circles()) top = std::max(top, c.position.y);
    world.addCircle(pileBall({0.03, top + 1.5}));
    bool woke = false;
    double worst = 0.0;
    for (int step = 0; step < 600; ++step) {
        world.step();
        woke = woke || asleepCount(world) == 0;
        worst = std::max(worst, largestOverlap(world));
    }
    CHECK(woke);
    INFO("largest overlap after the drop: " << worst << " m");
    CHECK(worst < 0.005);
    const Circle& dropped = world.circles().back();
    CHECK(dropped.position.y > top - 0.2);                                 // on the pile, not inside it
    CHECK(asleepCount(world) == static_cast<int>(world.circles().size())); // and all asleep again
}

TEST_CASE("an explosion wakes the island it pushes and leaves another island asleep", "[sleep]") {
    World world(sleepyDef());
    SegmentDef floor = line({-10.0, 0.0}, {10.0, 0.0});
    floor.material = {1.0, 1.0};
    world.addSegment(floor);
    // Two islands: a ball on the floor at x = -3, and two balls stacked in a corner-free row at x = 3.
    world.addCircle(pileBall({-3.0, 0.1}));
    world.addCircle(pileBall({3.0, 0.1}));
    world.addCircle(pileBall({3.2, 0.1}));
    REQUIRE(stepUntilAsleep(world, 120) <= 120);
    CHECK(world.circles()[1].sleep.island == world.circles()[2].sleep.island);
    CHECK(world.circles()[0].sleep.island != world.circles()[1].sleep.island);
    const Vec2 right = world.circles()[1].position;
    const ExplosionPushed pushed = applyExplosion(world,
                                                  Explosion{.centre = {-3.5, 0.1}, .radius = 1.0, .strength = 0.2});
    REQUIRE(pushed.circles == std::vector<CircleId>{world.circleId(0)});
    world.step();
    CHECK_FALSE(world.circles()[0].sleep.asleep);
    CHECK(world.circles()[0].position.x > -3.0);
    CHECK(world.circles()[1].sleep.asleep);
    CHECK(world.circles()[1].position == right);
}

TEST_CASE("a moving paddle wakes a sleeping ball and pushes it instead of passing through", "[sleep]") {
    World world(sleepyDef());
    world.addSegment(line({-10.0, 0.0}, {10.0, 0.0}));
    // A vertical paddle still for 2 s, then moving right at 1 m/s.
    KinematicPath path;
    path.keys = {{0.0, {}}, {2.0, {}}, {6.0, {4.0, 0.0}}};
    const int p = world.addPath(path);
    SegmentDef paddle = line({-1.0, 0.05}, {-1.0, 0.6}, 0.02);
    paddle.path = p;
    world.addSegment(paddle);
    world.addCircle(pileBall({0.0, 0.1}));
    for (int step = 0; step < 100; ++step) world.step();
    REQUIRE(world.circles()[0].sleep.asleep); // asleep long before the paddle moves
    for (int step = 0; step < 200; ++step) world.step();
    const Circle& c = world.circles()[0];
    const double paddleX = world.segments()[1].a.x;
    INFO("ball x " << c.position.x << ", paddle x " << paddleX);
    CHECK(c.position.x > paddleX + 0.02 + 0.1 - 0.005); // ahead of the paddle's surface
    CHECK(c.position.x > 0.5);
}

TEST_CASE("a ball carried by a platform slower than sleep_speed stays awake and rides along", "[sleep]") {
    World world(sleepyDef());
    KinematicPath path;
    path.keys = {{0.0, {}}, {10.0, {0.05, 0.0}}}; // 5 mm/s
    const int p = world.addPath(path);
    SegmentDef platform = line({-1.0, 0.0}, {1.0, 0.0});
    platform.path = p;
    platform.material = {1.0, 1.0};
    world.addSegment(platform);
    world.addCircle(pileBall({0.0, 0.1}));
    for (int step = 0; step < 480; ++step) world.step();
    CHECK_FALSE(world.circles()[0].sleep.asleep);
    // The belt starts under a ball at rest: friction sets it rolling with v + omega r = u and
    // m v = J, (m r^2 / 2) omega = J r, so v = u / 3 for a disc, carried 8 s at 5 mm/s / 3.
    CHECK(world.circles()[0].position.x == Approx(0.04 / 3.0).margin(2e-4));
}

TEST_CASE("a bullet into a sleeping ball hits it", "[sleep]") {
    World world(sleepyDef());
    world.addSegment(line({-100.0, 0.0}, {100.0, 0.0}));
    world.addCircle(pileBall({0.0, 0.1}));
    REQUIRE(stepUntilAsleep(world, 120) <= 120);
    CircleDef bullet = ball({-5.0, 0.1}, {2000.0, 0.0}, 0.05);
    bullet.mass = 0.01;
    world.addCircle(bullet);
    world.step();
    world.step();
    CHECK(world.circles()[0].velocity.x > 1.0);                           // struck
    CHECK(world.circles()[1].position.x < world.circles()[0].position.x); // not through it
}

TEST_CASE("sleep_speed 0, and methods that do not keep sleep, keep every circle awake", "[sleep]") {
    WorldDef never = sleepyDef();
    never.sleepSpeed = 0.0;
    World world(never);
    world.addSegment(line({-1.0, 0.0}, {1.0, 0.0}));
    world.addCircle(pileBall({0.0, 0.1}));
    for (int step = 0; step < 120; ++step) world.step();
    CHECK_FALSE(world.circles()[0].sleep.asleep);

    World solver(sleepyDef());
    solver.addSegment(line({-1.0, 0.0}, {1.0, 0.0}));
    solver.addCircle(pileBall({0.0, 0.1}));
    REQUIRE(stepUntilAsleep(solver, 120) <= 120);
    solver.setMethod(Method::exact);
    solver.step();
    CHECK_FALSE(solver.circles()[0].sleep.asleep);
}

TEST_CASE("auto lets a pile sleep as the solver does, and exact steps wake it", "[sleep]") {
    World solver = makeBox(120, 2.0);
    World automatic = makeBox(120, 2.0, sleepyDef(Method::automatic));
    const int solverSteps = stepUntilAsleep(solver, 600);
    CHECK(stepUntilAsleep(automatic, 600) == solverSteps);
}

namespace {

/// A frictionless ball of radius 0.1 m set at rest on a line tilted `degrees` down to the right; returns
/// how far along the line it has slid after `seconds`, the distance x = g sin(theta) t^2 / 2 would give.
struct Slide {
    double travelled = 0.0;
    double expected = 0.0;
    bool everAsleep = false;
};

Slide slideDown(Method method, double degrees, double seconds) {
    World world(sleepyDef(method));
    const double theta = degrees * std::numbers::pi / 180.0;
    const Vec2 along{std::cos(theta), -std::sin(theta)}, up{std::sin(theta), std::cos(theta)};
    SegmentDef slope = line(along * -1.0, along * 20.0);
    slope.material = {0.0, 0.0};
    world.addSegment(slope);
    CircleDef c = ball(up * 0.1, {}, 0.1);
    c.material = {0.0, 0.0};
    world.addCircle(c);
    const int steps = static_cast<int>(std::lround(seconds / world.def().timeStep));
    Slide slide;
    for (int step = 0; step < steps; ++step) {
        world.step();
        slide.everAsleep = slide.everAsleep || world.circles()[0].sleep.asleep;
    }
    slide.travelled = (world.circles()[0].position - up * 0.1).dot(along);
    slide.expected = 0.5 * world.def().gravity.length() * std::sin(theta) * world.time() * world.time();
    return slide;
}

} // namespace

TEST_CASE("a frictionless ball on a shallow incline slides as g sin(theta) t^2 / 2: slow is not asleep",
          "[sleep][incline]") {
    // 0.01 degree pushes it 1.7 mm/s^2 along the line: under sleep_speed for its first 5.9 s.
    for (const Method method : {Method::solver, Method::automatic}) {
        for (const double degrees : {0.01, 0.02, 0.05, 0.1, 0.12, 0.2, 0.5, 1.0}) {
            const Slide slide = slideDown(method, degrees, 10.0);
            INFO(methodName(method) << ", " << degrees << " degrees: slid " << slide.travelled << " m, expected "
                                    << slide.expected);
            CHECK_FALSE(slide.everAsleep);
            CHECK(slide.travelled == Approx(slide.expected).epsilon(0.01));
        }
    }
}

TEST_CASE("a ball at rest on a level floor or in a bowl is held there and sleeps", "[sleep][incline]") {
    for (const double friction : {0.0, 0.5}) {
        INFO("friction " << friction);
        World floor(sleepyDef());
        SegmentDef level = line({-2.0, 0.0}, {2.0, 0.0});
        level.material = {0.0, friction};
        floor.addSegment(level);
        CircleDef c = ball({0.3, 0.1}, {}, 0.1);
        c.material = {0.0, friction};
        floor.addCircle(c);
        CHECK(stepUntilAsleep(floor, 60) <= 60);

        // A bowl of five lines, its sides 30 and 60 degrees about a flat bottom: dropped off-centre,
        // the ball slides (or rolls) about the bottom until the corners' losses slow it under
        // sleep_speed there (a rolling ball, which loses nothing on the flat, only at a corner).
        World bowl(sleepyDef());
        const std::vector<Vec2> rim{{-1.5, 1.6}, {-0.8, 0.4}, {-0.2, 0.05}, {0.2, 0.05}, {0.8, 0.4}, {1.5, 1.6}};
        for (std::size_t k = 0; k + 1 < rim.size(); ++k) {
            SegmentDef side = line(rim[k], rim[k + 1]);
            side.material = {0.0, friction};
            bowl.addSegment(side);
        }
        CircleDef dropped = ball({-0.5, 1.2}, {}, 0.1);
        dropped.material = {0.0, friction};
        bowl.addCircle(dropped);
        const int steps = stepUntilAsleep(bowl, 3600);
        INFO("asleep after " << steps << " steps at " << bowl.circles()[0].position.x << ", "
                             << bowl.circles()[0].position.y);
        CHECK(steps <= 3600);
        CHECK(std::abs(bowl.circles()[0].position.x) < 0.2 + 1e-9); // on the flat bottom
    }
}

TEST_CASE("a spin counts against sleeping only where friction lets it act", "[sleep]") {
    // Spinning in place on a frictionless floor, nothing the ball touches can turn it or be turned by
    // it: slow in translation, it sleeps (and the spin stops). On a floor with friction the spin sets
    // it rolling, faster than sleep_speed, and it stays awake.
    for (const double friction : {0.0, 0.5}) {
        World world(sleepyDef());
        SegmentDef floor = line({-5.0, 0.0}, {5.0, 0.0});
        floor.material = {0.0, friction};
        world.addSegment(floor);
        CircleDef c = ball({0.0, 0.1}, {}, 0.1);
        c.material = {0.0, 0.5};
        c.angularVelocity = 20.0; // a surface speed of 2 m/s
        world.addCircle(c);
        const int steps = stepUntilAsleep(world, 120);
        INFO("floor friction " << friction << ": " << steps << " steps, v " << world.circles()[0].velocity.x);
        if (friction == 0.0) CHECK(steps <= 60);
        else CHECK((steps > 120 && std::abs(world.circles()[0].velocity.x) > 0.1));
    }
}
