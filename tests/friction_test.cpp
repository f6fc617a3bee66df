// Rolling and Coulomb friction in the solver, against their analytic answers: a disc rolling
// without slipping down an incline, a sliding disc that ends rolling, a spinning disc set down on a
// floor, and that a frictionless pair never turns anything.
#include "rube/physics/world.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace rube;

namespace {

constexpr double g = 9.81;

World solverWorld() {
    WorldDef def;
    def.gravity = {0.0, -g};
    def.method = Method::solver;
    def.timeStep = 1.0 / 60;
    return World(def);
}

void addFloor(World& world, double friction, Vec2 a = {-100, 0}, Vec2 b = {100, 0}) {
    SegmentDef floor;
    floor.a = a;
    floor.b = b;
    floor.material = {0.0, friction};
    world.addSegment(floor);
}

int addDisc(World& world, Vec2 position, Vec2 velocity, double omega, double friction, double r = 0.5, double m = 2.0) {
    CircleDef disc;
    disc.position = position;
    disc.velocity = velocity;
    disc.angularVelocity = omega;
    disc.radius = r;
    disc.mass = m;
    disc.material = {0.0, friction};
    return world.slot(world.addCircle(disc));
}

void run(World& world, double seconds) {
    const int steps = static_cast<int>(std::lround(seconds / world.def().timeStep));
    for (int i = 0; i < steps; ++i) world.step();
}

} // namespace

TEST_CASE("friction: a disc rolls down an incline at (2/3) g sin(theta) without slipping", "[friction][rolling]") {
    for (const double degrees : {15.0, 30.0}) {
        CAPTURE(degrees);
        const double theta = degrees * std::numbers::pi / 180.0;
        const Vec2 down{std::cos(theta), -std::sin(theta)}; // along the slope, downhill to the right
        const Vec2 normal{std::sin(theta), std::cos(theta)};
        World world = solverWorld();
        // mu = 0.8 x 0.8 = 0.64 > tan(theta) / 3: the disc rolls, never slips.
        addFloor(world, 0.8, down * -50.0, down * 50.0);
        const double r = 0.5;
        const int disc = addDisc(world, normal * r, {}, 0.0, 0.8, r);
        run(world, 0.5); // settle into rolling
        const double t0 = world.time();
        const double v0 = world.circles()[disc].velocity.dot(down);
        run(world, 1.0);
        const Circle& c = world.circles()[disc];
        const double acceleration = (c.velocity.dot(down) - v0) / (world.time() - t0);
        CHECK(acceleration == Approx(2.0 / 3.0 * g * std::sin(theta)).epsilon(0.01));
        // Rolling without slipping: the contact point is still, v = -omega r.
        CHECK(c.velocity.dot(down) == Approx(-c.angularVelocity * r).epsilon(0.01));
        CHECK(std::abs(c.velocity.dot(normal)) < 1e-3); // it stays on the slope
    }
}

TEST_CASE("friction: on a slope steeper than the friction allows, the disc slips", "[friction][rolling]") {
    // A disc rolls only while mu >= tan(theta) / 3; at 60 degrees with mu = 0.09 it slides and
    // accelerates at g (sin(theta) - mu cos(theta)), faster than it would roll.
    const double theta = 60.0 * std::numbers::pi / 180.0;
    const Vec2 down{std::cos(theta), -std::sin(theta)};
    const Vec2 normal{std::sin(theta), std::cos(theta)};
    World world = solverWorld();
    addFloor(world, 0.3, down * -50.0, down * 50.0);
    const int disc = addDisc(world, normal * 0.5, {}, 0.0, 0.3);
    run(world, 0.5);
    const double v0 = world.circles()[disc].velocity.dot(down);
    run(world, 1.0);
    const double acceleration = world.circles()[disc].velocity.dot(down) - v0;
    CHECK(acceleration == Approx(g * (std::sin(theta) - 0.09 * std::cos(theta))).epsilon(0.01));
}

TEST_CASE("friction: a disc set sliding on a floor ends rolling at two thirds of its speed", "[friction][rolling]") {
    // Angular momentum about the contact point is kept: m r v0 = m r v + I v / r, I = m r^2 / 2,
    // so v = v0 / (1 + 1/2) = (2/3) v0, reached after t = v0 / (3 mu g).
    World world = solverWorld();
    addFloor(world, 0.5);
    const double r = 0.5, v0 = 6.0;
    const int disc = addDisc(world, {0.0, r}, {v0, 0.0}, 0.0, 0.5, r);
    run(world, 0.1);
    CHECK(world.circles()[disc].velocity.x < v0 - 0.1); // still sliding, slowing down
    CHECK(world.circles()[disc].velocity.x > 2.0 / 3.0 * v0 + 0.1);
    run(world, 3.0); // well past v0 / (3 mu g) = 0.82 s
    const Circle& c = world.circles()[disc];
    CHECK(c.velocity.x == Approx(2.0 / 3.0 * v0).epsilon(0.01));
    CHECK(c.angularVelocity == Approx(-c.velocity.x / r).epsilon(0.01));
}

TEST_CASE("friction: a spinning disc set down on a floor rolls off at the speed theory predicts",
          "[friction][rolling]") {
    // Backspin and forward speed: L about the contact point is I omega0 - m r v0 (omega counter-clockwise),
    // and rolling at v needs omega = -v / r, so v = (m r v0 - I omega0) / (I / r + m r) = (2/3)(v0 - r omega0 / 2).
    const double r = 0.4, v0 = 2.0, omega0 = 30.0;
    World world = solverWorld();
    addFloor(world, 0.6);
    const int disc = addDisc(world, {0.0, r}, {v0, 0.0}, omega0, 0.6, r);
    run(world, 4.0);
    const double expected = 2.0 / 3.0 * (v0 - r * omega0 / 2.0); // -2.67 m/s: the backspin wins, it rolls back
    const Circle& c = world.circles()[disc];
    CHECK(c.velocity.x == Approx(expected).epsilon(0.01));
    CHECK(c.angularVelocity == Approx(-expected / r).epsilon(0.01));
    CHECK(c.angle != 0.0);
}

TEST_CASE("friction: a frictionless pair neither turns a ball nor slows its slide", "[friction]") {
    World world = solverWorld();
    addFloor(world, 0.0); // a plain wall: friction 0, so the product is 0 whatever the ball's
    const int ball = addDisc(world, {0.0, 0.5}, {3.0, 0.0}, 0.0, 0.7);
    run(world, 2.0);
    CHECK(world.circles()[ball].velocity.x == Approx(3.0).epsilon(1e-12));
    CHECK(world.circles()[ball].angularVelocity == 0.0);
    CHECK(world.circles()[ball].angle == 0.0);
}

TEST_CASE("friction: a spin in flight is kept, and turns the angle at omega under every method", "[friction]") {
    for (const Method method : {Method::discrete, Method::turnBased, Method::exact, Method::solver}) {
        CAPTURE(methodName(method));
        WorldDef def;
        def.method = method;
        World world(def);
        const int ball = addDisc(world, {0.0, 10.0}, {1.0, 0.0}, 2.0, 0.5);
        run(world, 1.0);
        CHECK(world.circles()[ball].angularVelocity == 2.0);
        CHECK(world.circles()[ball].angle == Approx(2.0).epsilon(1e-12));
    }
}

TEST_CASE("friction: a ball set down on a conveyor is carried at a third of the belt's speed", "[friction][conveyor]") {
    // The belt's friction impulse J brings the contact point to the belt speed u:
    // v + omega r = u with v = J / m and omega = J r / I, so for a disc (I = m r^2 / 2) v = u / 3.
    const double u = 3.0, r = 0.5;
    World world = solverWorld();
    SegmentDef belt;
    belt.a = {-100, 0};
    belt.b = {100, 0};
    belt.material = {0.0, 0.8};
    belt.surfaceSpeed = u;
    world.addSegment(belt);
    const int ball = addDisc(world, {0.0, r}, {}, 0.0, 0.8, r);
    run(world, 2.0);
    const Circle& c = world.circles()[ball];
    CHECK(c.velocity.x == Approx(u / 3.0).epsilon(0.01));
    CHECK(c.velocity.x + c.angularVelocity * r == Approx(u).epsilon(0.01)); // the contact point moves with the belt
    CHECK(world.segments()[0].a == Vec2{-100, 0});                          // the belt itself stays where it is
}
