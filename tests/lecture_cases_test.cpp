// One test per case the lectures name: where each time-step method and each time-of-impact rule
// fails, shown failing, and the robust versions shown holding. Methods go through the public World API.
#include "rube/physics/time_of_impact.hpp"
#include "rube/physics/world.hpp"
#include "scene_builders.hpp"

#include "resolve.hpp" // internal: the lecture loops below resolve by hand

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace rube;
using rube::test::line;

namespace {

constexpr double kDt = 1.0 / 60;

WorldDef weightless(Method method) {
    WorldDef def;
    def.method = method;
    def.gravity = {0, 0};
    return def;
}

// A ball of radius r coming straight down at `speed` towards a floor line y = 0 (of `thickness`
// radius), starting with its centre at startY. True when it ends up below the floor: tunnelled.
bool tunnels(Method method, double speed, double startY, double r, double thickness = 0.0) {
    World world(weightless(method));
    world.addSegment(line({-10, 0}, {10, 0}, thickness));
    CircleDef ball;
    ball.position = {0, startY};
    ball.velocity = {0, -speed};
    ball.radius = r;
    world.addCircle(ball);
    const int steps = static_cast<int>(std::ceil(startY / (speed * kDt))) + 4;
    for (int i = 0; i < steps; ++i) world.step();
    return world.circles()[0].position.y < 0.0;
}

// Signed distance of point p from the line through a and b, positive on the left-hand normal's side.
double distanceFromLine(Vec2 p, Vec2 a, Vec2 b) { return (p - a).dot((b - a).normal()); }

} // namespace

TEST_CASE("discrete tunnels when speed x dt > 2r, exact never does", "[lecture][tunnel]") {
    const double r = 0.1;
    for (const double ratio : {1.01, 1.5, 3.0, 10.0}) {
        const double speed = ratio * 2.0 * r / kDt;
        const double travel = speed * kDt;
        // Start so that one step ends with the centre at R + (travel - 2R) / 2 above the line: the next
        // step moves it to (2R - travel) / 2 < -R below it, wholly past the line, never overlapping.
        const double startY = r + (travel - 2.0 * r) / 2 + 5.0 * travel;
        INFO("speed x dt / 2r = " << ratio);
        CHECK(tunnels(Method::discrete, speed, startY, r));
        CHECK_FALSE(tunnels(Method::exact, speed, startY, r));
        // Every start offset is caught by the exact method.
        for (int k = 0; k < 50; ++k) CHECK_FALSE(tunnels(Method::exact, speed, 1.0 + k * travel / 50, r));
    }
}

TEST_CASE("discrete never tunnels below speed x dt = 2 (r + segment radius)", "[lecture][tunnel]") {
    const double r = 0.1;
    for (const double thickness : {0.0, 0.05}) {
        const double reach = r + thickness;
        for (const double ratio : {0.1, 0.5, 0.9, 0.99, 0.999}) {
            const double travel = ratio * 2.0 * reach;
            int tunnelled = 0;
            // 200 start offsets spread over one step's travel: every phase of the crossing step.
            for (int k = 0; k < 200; ++k)
                if (tunnels(Method::discrete, travel / kDt, 1.0 + k * travel / 200, r, thickness)) ++tunnelled;
            INFO("thickness " << thickness << ", speed x dt / 2(r + radius) = " << ratio);
            CHECK(tunnelled == 0);
        }
        // Just above the threshold a start offset exists that tunnels, thick segment or not.
        const double travel = 1.01 * 2.0 * reach;
        CHECK(tunnels(Method::discrete, travel / kDt, reach + (travel - 2.0 * reach) / 2 + 5 * travel, r, thickness));
    }
}

TEST_CASE("a stack of balls under gravity: discrete lets them pass through each other (scene 3), exact holds",
          "[lecture][stack]") {
    const auto crossings = [](Method method, double& deepest) {
        WorldDef def;
        def.method = method;
        World world(def);
        world.addSegment(line({-10, 0}, {10, 0}));
        const double r = 0.05;
        for (int i = 0; i < 10; ++i) {
            CircleDef ball;
            ball.position = {0, r + i * (2 * r + 1e-3)};
            ball.radius = r;
            ball.material.bounciness = 0.5;
            world.addCircle(ball);
        }
        int crossed = 0;
        deepest = 0.0;
        for (int step = 0; step < 600; ++step) {
            world.step();
            const auto balls = world.circles();
            for (std::size_t i = 0; i + 1 < balls.size(); ++i) {
                if (balls[i + 1].position.y < balls[i].position.y) ++crossed; // the upper ball got below
                deepest = std::max(deepest, 2 * r - balls[i].position.distance(balls[i + 1].position));
            }
            deepest = std::max(deepest, r - balls[0].position.y);
        }
        return crossed;
    };
    double deepest = 0.0;
    CHECK(crossings(Method::discrete, deepest) > 0);
    CHECK(deepest > 0.05); // deeper than a radius
    CHECK(crossings(Method::exact, deepest) == 0);
    CHECK(deepest < 1e-9);
}

TEST_CASE("a ball coming to rest sinks through a line by rounding when a < 0 is ignored (scene 4)",
          "[lecture][sinking]") {
    // The lecture's loop: gravity, then one impact per frame: reset to the point of impact, reflect.
    const auto sinks = [](TimeOfImpactRule rule, double x0) {
        const Vec2 a{-50, -5}, b{50, 5};
        const Vec2 n = (b - a).normal();
        const double r = 0.5;
        Vec2 p = lerp(a, b, (x0 + 50) / 100) + n * (r + 1.0);
        Vec2 v;
        for (int frame = 0; frame < 600; ++frame) {
            v += Vec2{0, -9.81} * kDt;
            if (const auto hit = circleSegmentCollision({p, v, r}, a, b, 0.0, kDt, rule)) {
                p = hit->pointOfImpact;
                if (v.dot(hit->normal) < 0.0) v = v.reflected(hit->normal, 0.5);
            } else {
                p += v * kDt;
            }
            if (distanceFromLine(p, a, b) < 0.0) return true;
        }
        return false;
    };
    int sankIgnoring = 0, sankRobust = 0;
    for (int k = 0; k < 20; ++k) {
        const double x0 = -5.0 + 0.37 * k;
        if (sinks(TimeOfImpactRule::attempt1, x0)) ++sankIgnoring;
        if (sinks(TimeOfImpactRule::attempt3, x0)) ++sankRobust;
    }
    CHECK(sankIgnoring > 0);
    CHECK(sankRobust == 0);
}

TEST_CASE("balls stick together with attempt 2, not with attempt 3", "[lecture][sticking]") {
    // Two balls that rounding left overlapping by 1e-12 m, moving apart. The lecture's loop: find the
    // time of impact, move both to it, resolve (only if approaching), and the frame ends there.
    const auto apartAfter = [](TimeOfImpactRule rule) {
        Vec2 p1{0, 0}, p2{1.0 - 1e-12, 0};
        Vec2 v1{-1, 0}, v2{1, 0};
        for (int frame = 0; frame < 60; ++frame) {
            const auto t = circleCircleTimeOfImpact(p1 - p2, v1 - v2, 1.0, kDt, rule);
            const double move = t ? *t : kDt;
            p1 += v1 * move;
            p2 += v2 * move;
            if (t) resolveImpact(v1, 1.0, v2, 1.0, (p1 - p2).normalized(), 1.0);
        }
        return p1.distance(p2);
    };
    CHECK(apartAfter(TimeOfImpactRule::attempt2) < 1.0);          // stuck where they were
    CHECK(apartAfter(TimeOfImpactRule::attempt3) == Approx(3.0)); // 1 + 2 m/s for a second
}

TEST_CASE("turn-based: positions are slightly off and order matters (lecture 3)", "[lecture][turn]") {
    // Two equal balls meeting head-on. In each step the first in index order moves first, so the
    // collision happens nearer the second ball's side; the exact method meets in the middle.
    const auto sumOfPositions = [](Method method, bool leftFirst) {
        World world(weightless(method));
        CircleDef left, right;
        left.position = {-1.025, 0};
        left.velocity = {3, 0};
        right.position = {1.025, 0};
        right.velocity = {-3, 0};
        world.addCircle(leftFirst ? left : right);
        world.addCircle(leftFirst ? right : left);
        for (int i = 0; i < 30; ++i) world.step();
        REQUIRE(world.stats().impacts == 1);
        // Both move apart at 3 m/s again; a symmetric collision leaves x_left + x_right = 0.
        return world.circles()[0].position.x + world.circles()[1].position.x;
    };
    CHECK(std::fabs(sumOfPositions(Method::exact, true)) < 1e-12);
    const double leftFirst = sumOfPositions(Method::turnBased, true);
    const double rightFirst = sumOfPositions(Method::turnBased, false);
    CHECK(std::fabs(leftFirst) > 1e-3);
    CHECK(leftFirst == Approx(-rightFirst)); // mirrored by the order, not by the physics
}

TEST_CASE("balls bounce off both sides of a line, under every method", "[lecture][line]") {
    for (const Method method : {Method::discrete, Method::turnBased, Method::exact}) {
        World world(weightless(method));
        world.addSegment(line({-5, 0}, {5, 0}));
        CircleDef ball;
        ball.radius = 0.25;
        ball.position = {-1, 2};
        ball.velocity = {0, -6};
        world.addCircle(ball);
        ball.position = {1, -2};
        ball.velocity = {0, 6};
        world.addCircle(ball);
        for (int i = 0; i < 60; ++i) world.step();
        INFO(methodName(method));
        CHECK(world.circles()[0].position.y > 0.25);
        CHECK(world.circles()[0].velocity.y == Approx(6.0));
        CHECK(world.circles()[1].position.y < -0.25);
        CHECK(world.circles()[1].velocity.y == Approx(-6.0));
        CHECK(world.stats().impacts >= 2);
    }
}

TEST_CASE("hitting a line cap: it bounces off the end like off a circle of radius 0", "[lecture][cap]") {
    World world(weightless(Method::exact));
    world.addSegment(line({0, 0}, {4, 0}));
    CircleDef ball;
    ball.radius = 0.5;
    ball.position = {-3, 0.3};
    ball.velocity = {5, 0};
    world.addCircle(ball);
    bool hit = false;
    for (int i = 0; i < 60 && !hit; ++i) {
        world.step();
        for (const Impact& impact : world.lastImpacts()) {
            hit = true;
            // It touches the cap with its centre at (-0.4, 0.3): normal (-0.8, 0.6), time (3 - 0.4) / 5.
            CHECK(impact.otherKind == Other::segmentCap);
            CHECK(approxEqual(impact.normal, {-0.8, 0.6}, 1e-12));
            CHECK(approxEqual(impact.pointOfImpact, {0, 0}, 1e-12));
            CHECK(impact.time == Approx(0.52).epsilon(1e-12));
        }
    }
    REQUIRE(hit);
    // v' = v - 2 (v . n) n = (5, 0) - 2 (-4) (-0.8, 0.6) = (-1.4, 4.8).
    CHECK(approxEqual(world.circles()[0].velocity, {-1.4, 4.8}, 1e-12));
}

TEST_CASE("of two impacts possible in one step, the earliest is resolved first", "[lecture][order]") {
    // A ball heading into a corner at (-60, -30) m/s: the wall x = 0 is 0.4 m away (t = 0.4 / 60),
    // the floor y = 0 too (t = 0.4 / 30), both within the step. The floor is added first, so taking
    // the first impact found instead of the earliest would send the ball through the wall.
    World world(weightless(Method::exact));
    world.addSegment(line({-1, 0}, {2, 0}));
    world.addSegment(line({0, -1}, {0, 2}));
    CircleDef ball;
    ball.radius = 0.1;
    ball.position = {0.5, 0.5};
    ball.velocity = {-60, -30};
    world.addCircle(ball);
    world.step();
    const auto impacts = world.lastImpacts();
    REQUIRE(impacts.size() == 2);
    CHECK(impacts[0].other == 1);
    CHECK(impacts[0].time == Approx(0.4 / 60).epsilon(1e-12));
    CHECK(impacts[1].other == 0);
    CHECK(impacts[1].time == Approx(0.4 / 30).epsilon(1e-12));
    CHECK(approxEqual(world.circles()[0].velocity, {60, 30}, 1e-12));
    CHECK(world.circles()[0].position.x > 0.1);
    CHECK(world.circles()[0].position.y > 0.1);
}

TEST_CASE("several impacts in one step are resolved in time order", "[lecture][order]") {
    // A ball at 30 m/s in a corridor with 0.2 m of room hits both walls every step.
    World world(weightless(Method::exact));
    world.addSegment(line({0.3, -1}, {0.3, 1}));
    world.addSegment(line({0, -1}, {0, 1}));
    CircleDef ball;
    ball.radius = 0.05;
    ball.position = {0.15, 0};
    ball.velocity = {-30, 0};
    world.addCircle(ball);
    world.step();
    const auto impacts = world.lastImpacts();
    REQUIRE(impacts.size() >= 2);
    // Left wall (index 1) at x = 0.05 after 0.1 / 30 s, then the right wall after another 0.2 / 30 s.
    CHECK(impacts[0].other == 1);
    CHECK(impacts[0].time == Approx(0.1 / 30).epsilon(1e-12));
    CHECK(impacts[1].other == 0);
    CHECK(impacts[1].time == Approx(0.3 / 30).epsilon(1e-12));
    for (int i = 0; i < 600; ++i) {
        world.step();
        const double x = world.circles()[0].position.x;
        REQUIRE(x >= 0.05 - 1e-12);
        REQUIRE(x <= 0.25 + 1e-12);
    }
}

TEST_CASE("a ball resting on a slope does not sink: it slides without friction", "[lecture][slope]") {
    // A 1-in-4 slope; the ball placed touching it at rest.
    const Vec2 a{0, 0}, b{40, -10};
    const Vec2 n = (b - a).normal(); // points up and to the right of the downhill direction
    const Vec2 down = (b - a).normalized();
    const double r = 0.5;
    WorldDef def;
    def.method = Method::exact;
    World world(def);
    world.addSegment(line(a, b));
    CircleDef ball;
    ball.radius = r;
    ball.position = a + down * 2.0 + n * r;
    world.addCircle(ball);
    const Vec2 start = ball.position;
    const double gAlong = Vec2{0, -9.81}.dot(down);
    double lowest = r, highest = r;
    for (int step = 1; step <= 120; ++step) {
        world.step();
        const double d = distanceFromLine(world.circles()[0].position, a, b);
        lowest = std::min(lowest, d);
        highest = std::max(highest, d);
    }
    // Measured: the distance stays r to within a few 1e-15 m; 1e-12 m leaves room for other compilers.
    CHECK(lowest >= r - 1e-12);
    CHECK(highest <= r + 1e-12);
    // Sliding without friction: s = g sin(angle) t^2 / 2 along the slope, exactly as on a frictionless incline.
    const double t = world.time();
    CHECK((world.circles()[0].position - start).dot(down) == Approx(0.5 * gAlong * t * t).epsilon(1e-9));
    CHECK(world.stats().restingContacts > 0);
}

TEST_CASE("walls and kinematic bodies are infinite mass", "[lecture][wall]") {
    SECTION("a static wall reverses the normal velocity: v' = -C v") {
        World world(weightless(Method::exact));
        SegmentDef wall = line({1, -1}, {1, 1});
        wall.material.bounciness = 0.5;
        world.addSegment(wall);
        CircleDef ball;
        ball.radius = 0.25;
        ball.velocity = {3, 1};
        world.addCircle(ball);
        for (int i = 0; i < 30; ++i) world.step();
        CHECK(approxEqual(world.circles()[0].velocity, {-1.5, 1}, 1e-12));
    }
    SECTION("a kinematic circle keeps its path; the ball leaves at v' = u - C (v - u)") {
        World world(weightless(Method::exact));
        KinematicPath path;
        path.keys = {{0.0, {0, 0}}, {10.0, {-20, 0}}}; // 2 m/s to the left
        const int p = world.addPath(path);
        CircleDef pusher;
        pusher.motion = Motion::kinematic;
        pusher.path = p;
        pusher.position = {3, 0};
        pusher.radius = 0.5;
        world.addCircle(pusher);
        CircleDef ball;
        ball.radius = 0.25;
        ball.velocity = {1, 0};
        world.addCircle(ball);
        for (int i = 0; i < 60; ++i) world.step();
        // u = -2, C = 1: v' = -2 - (1 + 2) = -5, and the pusher is where its path says.
        CHECK(world.circles()[1].velocity.x == Approx(-5.0));
        CHECK(world.circles()[0].position.x == Approx(3.0 - 2.0 * world.time()));
        CHECK(world.stats().impacts == 1);
    }
}

TEST_CASE("a ball rides a rising platform without sinking, under every method", "[lecture][wall]") {
    for (const Method method : {Method::discrete, Method::turnBased, Method::exact}) {
        WorldDef def;
        def.method = method;
        World world(def);
        KinematicPath lift;
        lift.keys = {{0.0, {0, 0}}, {2.0, {0, 2}}}; // up at 1 m/s for 2 s
        SegmentDef platform = line({-2, 0}, {2, 0});
        platform.path = world.addPath(lift);
        world.addSegment(platform);
        CircleDef ball;
        ball.position = {0, 0.5};
        ball.material.bounciness = 0.0;
        world.addCircle(ball);
        INFO(methodName(method));
        for (int step = 0; step < 118; ++step) {
            world.step();
            const double gap = world.circles()[0].position.y - world.segments()[0].a.y - 0.5;
            REQUIRE(gap >= -1e-9);
            REQUIRE(gap <= 1e-9);
        }
    }
}
