// `auto` per island: a body's method is chosen by what it could meet within the step, not by what
// the rest of the world is doing. A ball far from a pile of friction balls (the solver's) must take
// exact's steps bit for bit, as if it were alone; a ball that reaches the pile must join it.
#include "rube/physics/collision.hpp"
#include "rube/physics/world.hpp"
#include "scene_builders.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace rube;
using rube::test::ball;
using rube::test::line;

namespace {

constexpr double kPileX = 100.0; // the pile's box, far from the free ball
constexpr double kPileRadius = 0.1;

WorldDef defWith(Method method) {
    WorldDef def;
    def.method = method;
    return def;
}

// The free ball's part of the scene: a thin line whose right cap it strikes at `speed` (a little
// below the cap's top, so it leaves at an angle), and a floor far below to land on.
int addCapScene(World& world, double speed) {
    world.addSegment(line({-3, 0}, {0, 0}, 0.05));
    world.addSegment(line({-10, -2}, {10, -2}));
    const double r = 0.1, t = 0.05; // it reaches the cap after about t
    return world.slot(world.addCircle(ball({r + 0.05 + speed * t, 0.08 + 0.5 * 9.81 * t * t}, {-speed, 0.0}, r)));
}

// `columns` x `rows` balls with friction in a box with friction, all 2 m wide; `touching`: packed
// as they rest (each row in the hollows of the one below), else in rows 4 cm apart, falling.
void addFrictionPile(World& world, int columns, int rows, bool touching) {
    for (const auto& [a, b] : {std::pair<Vec2, Vec2>{{kPileX - 1, 0}, {kPileX + 1, 0}},
                               {{kPileX - 1, 0}, {kPileX - 1, 10}},
                               {{kPileX + 1, 0}, {kPileX + 1, 10}}}) {
        SegmentDef side = line(a, b);
        side.material = {0.3, 0.5};
        world.addSegment(side);
    }
    const double r = kPileRadius;
    const double dx = touching ? 2 * r : 0.24, dy = touching ? std::sqrt(3.0) * r : 0.24;
    for (int row = 0; row < rows; ++row)
        for (int col = 0; col < columns; ++col) {
            CircleDef c = ball({kPileX - 0.8 + dx * col + (row % 2) * r * 0.5, r + (touching ? 0.0 : 0.3) + dy * row},
                               {}, r);
            if (touching) c.position.x = kPileX - 0.8 + dx * col + (row % 2) * r;
            c.mass = 0.1;
            c.material = {0.3, 0.5};
            world.addCircle(c);
        }
}

double overlapWithOthers(const World& world, int i) {
    const Circle& c = world.circles()[static_cast<std::size_t>(i)];
    double worst = 0.0;
    for (std::size_t j = 0; j < world.circles().size(); ++j)
        if (static_cast<int>(j) != i)
            worst = std::max(worst,
                             c.radius + world.circles()[j].radius - c.position.distance(world.circles()[j].position));
    return worst;
}

} // namespace

TEST_CASE("auto per island: a ball far from a friction pile takes exact's steps as if alone, bit for bit",
          "[auto][island]") {
    for (const bool touching : {true, false})
        for (const double speed : {0.5, 2.0, 10.0, 20.0, 60.0}) {
            INFO("impact speed " << speed << " m/s, pile " << (touching ? "at rest" : "falling"));
            World alone(defWith(Method::exact)), shared(defWith(Method::automatic));
            const int ball = addCapScene(alone, speed);
            REQUIRE(addCapScene(shared, speed) == ball);
            addFrictionPile(shared, 6, touching ? 5 : 10,
                            touching); // 61 balls falling: more than exact affords at once
            bool struckCap = false;
            for (int step = 0; step < 300; ++step) {
                alone.step();
                shared.step();
                for (const Impact& impact : alone.lastImpacts()) struckCap |= impact.otherKind == Other::segmentCap;
                const Circle& a = alone.circles()[static_cast<std::size_t>(ball)];
                const Circle& s = shared.circles()[static_cast<std::size_t>(ball)];
                INFO("step " << step);
                REQUIRE(s.position == a.position);
                REQUIRE(s.velocity == a.velocity);
            }
            CHECK(struckCap);
            const StepStats& stats = shared.stats();
            const int pile = touching ? 30 : 60;
            CHECK(stats.exactBodySteps + stats.solverBodySteps == 300 * (pile + 1));
            CHECK(stats.exactBodySteps >= 300); // the free ball, every step
            // The pile: a falling one's free flight may be exact's until its balls could meet
            // something with friction, a few steps; from then on it is the solver's.
            CHECK(stats.solverBodySteps >= (300 - 30) * pile);
            CHECK(stats.capsHit == 0);
            // The pile came to rest on the solver's side and fell asleep there.
            int asleep = 0;
            for (const Circle& c : shared.circles()) asleep += c.sleep.asleep;
            CHECK(asleep == pile);
        }
}

TEST_CASE("auto per island: a turning plank on a pivot far away leaves a bouncing ball exact's", "[auto][island]") {
    for (const double speed : {2.0, 20.0}) {
        INFO("impact speed " << speed << " m/s");
        World alone(defWith(Method::exact)), shared(defWith(Method::automatic));
        const int ball = addCapScene(alone, speed);
        addCapScene(shared, speed);
        RigidBodyDef plank;
        plank.position = {kPileX, 1.0};
        plank.halfExtents = {1.5, 0.05};
        plank.mass = 2.0;
        const BodyId body = shared.addBody(plank);
        shared.addPivot(PivotDef{body, {-0.5, 0.0}, {kPileX - 0.5, 1.0}}); // off centre: it swings
        for (int step = 0; step < 240; ++step) {
            alone.step();
            shared.step();
            INFO("step " << step);
            REQUIRE(shared.circles()[static_cast<std::size_t>(ball)].position ==
                    alone.circles()[static_cast<std::size_t>(ball)].position);
            REQUIRE(shared.circles()[static_cast<std::size_t>(ball)].velocity ==
                    alone.circles()[static_cast<std::size_t>(ball)].velocity);
        }
        CHECK(shared.stats().solverBodySteps == 240);    // the plank
        CHECK(std::abs(shared.bodies()[0].angle) > 0.5); // and it swung
    }
}

TEST_CASE("auto per island: a ball thrown into a friction pile joins it and neither tunnels nor sinks in",
          "[auto][island]") {
    for (int k = 0; k <= 6; ++k) {
        const double speed = 2.0 * std::pow(10.0, k / 3.0); // 2 to 200 m/s
        INFO("speed " << speed << " m/s");
        World world(defWith(Method::automatic));
        addFrictionPile(world, 6, 3, true);
        const int thrown = world.slot(
            world.addCircle(ball({kPileX - 0.5, 3.0}, Vec2{0.2, -1.0}.normalized() * speed, 0.1)));
        for (int step = 0; step < 180; ++step) {
            world.step();
            const Circle& c = world.circles()[static_cast<std::size_t>(thrown)];
            REQUIRE(c.position.y > 0.1 - 0.01); // above the pile's floor
            REQUIRE(std::abs(c.position.x - kPileX) < 1.0);
        }
        CHECK(overlapWithOthers(world, thrown) < 0.05 * 0.1); // the solver's promise for a pile
        CHECK(world.stats().capsHit == 0);
    }
}

TEST_CASE("auto per island: a roped pendulum pair and a ball on a moving platform beside a friction pile move as alone "
          "under exact",
          "[auto][island]") {
    const auto addScene = [](World& world) {
        // A double pendulum: a ball on a rope from a fixed anchor, a second ball on a rope from it.
        const CircleId upper = world.addCircle(ball({-4.0, 3.0}, {}, 0.1));
        const CircleId lower = world.addCircle(ball({-3.0, 3.0}, {}, 0.1));
        world.addRope(RopeDef{upper, {}, {-5.0, 3.0}, 1.0});
        world.addRope(RopeDef{lower, upper, {}, 1.0});
        // A lift rising 1 m in 2 s and coming back, with a ball dropped on it.
        const int path = world.addPath(
            KinematicPath{{PathKey{0.0, {0.0, 0.0}}, PathKey{2.0, {0.0, 1.0}}, PathKey{4.0, {0.0, 0.0}}}, true});
        SegmentDef platform = line({-9.0, 0.0}, {-7.0, 0.0});
        platform.path = path;
        world.addSegment(platform);
        CircleDef rider = ball({-8.0, 1.0}, {}, 0.1);
        rider.material.bounciness = 0.5;
        world.addCircle(rider);
    };
    World alone(defWith(Method::exact)), shared(defWith(Method::automatic));
    addScene(alone);
    addScene(shared);
    addFrictionPile(shared, 6, 5, true);
    double riderAtTop = 0.0;
    for (int step = 0; step < 300; ++step) {
        alone.step();
        shared.step();
        if (step + 1 == 120) riderAtTop = alone.circles()[2].position.y; // t = 2 s: the lift at its top
        INFO("step " << step);
        for (std::size_t i = 0; i < alone.circles().size(); ++i) {
            INFO("circle " << i);
            REQUIRE(shared.circles()[i].position == alone.circles()[i].position);
            REQUIRE(shared.circles()[i].velocity == alone.circles()[i].velocity);
        }
    }
    // The pendulum swung and the rider rode: the scene did what it says.
    CHECK(alone.circles()[1].position.y < 2.5);
    CHECK(riderAtTop > 1.0);
    CHECK(shared.stats().exactBodySteps == 300 * 3);
}
