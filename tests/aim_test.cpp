// Aiming and shooting: every aimed shot is checked by flying it. Gravity-influenced shots are launched
// as a ball in a World stepped with Method::exact and must pass the aimed point within 1 % of the ball's
// radius; leads and timed shots must meet the target to 1e-6 of the distance; with figures worked out
// by hand where the numbers allow.
#include "rube/physics/aim.hpp"
#include "rube/physics/world.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

using namespace rube;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kG = 9.81;
constexpr double kBallRadius = 0.25;

// The least |f(t)| over [lo, hi]: the best of 2000 samples, then golden-section search between its
// neighbours (|f| is V-shaped or a parabola there, so unimodal).
double closestApproach(const std::function<Vec2(double)>& f, double lo, double hi) {
    constexpr int kSamples = 2000;
    const double h = (hi - lo) / kSamples;
    int best = 0;
    for (int i = 1; i <= kSamples; ++i)
        if (f(lo + h * i).length() < f(lo + h * best).length()) best = i;
    double a = lo + h * std::max(0, best - 1), b = lo + h * std::min(kSamples, best + 1);
    const double r = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int k = 0; k < 200 && b - a > 1e-15 * std::max(1.0, hi); ++k) {
        const double x1 = b - r * (b - a), x2 = a + r * (b - a);
        if (f(x1).length() < f(x2).length()) b = x2;
        else a = x1;
    }
    return f(0.5 * (a + b)).length();
}

// A ball of radius kBallRadius launched from `muzzle` in a World stepped with Method::exact, no obstacles,
// for `duration` seconds; returns its closest approach to `target` (moving at targetVelocity from t = 0).
// Between the world's steps the ball's exact path from the stepped state is searched, p + v tau + g tau^2 / 2.
double simulatedMiss(Vec2 muzzle, Vec2 velocity, Vec2 gravity, Vec2 target, double duration, Vec2 targetVelocity = {}) {
    WorldDef def;
    def.gravity = gravity;
    def.method = Method::exact;
    World world(def);
    CircleDef ball;
    ball.position = muzzle;
    ball.velocity = velocity;
    ball.radius = kBallRadius;
    world.addCircle(ball);
    const double dt = def.timeStep;
    double miss = std::numeric_limits<double>::infinity();
    while (world.time() < duration + dt) {
        const double t0 = world.time();
        const Circle c = world.circles()[0];
        auto offset = [&](double tau) {
            return c.position + c.velocity * tau + gravity * (0.5 * tau * tau) - (target + targetVelocity * (t0 + tau));
        };
        miss = std::min(miss, closestApproach(offset, 0.0, dt));
        world.step();
    }
    REQUIRE(world.stats().impacts == 0);
    return miss;
}

double degrees(double radians) { return radians * 180.0 / kPi; }

} // namespace

TEST_CASE("aiming in the current direction and at a target", "[aim]") {
    const Shot shot = aimInDirection(kPi / 6, 10.0);
    CHECK(shot.direction.x == Approx(std::sqrt(3.0) / 2));
    CHECK(shot.direction.y == Approx(0.5));
    CHECK(shot.velocity.length() == Approx(10.0));
    CHECK(shot.angle == Approx(kPi / 6));

    // From (1, 1) to (4, 5): the 3-4-5 triangle.
    const std::optional<Shot> atTarget = aimAtTarget({1, 1}, {4, 5}, 20.0);
    REQUIRE(atTarget);
    CHECK(approxEqual(atTarget->direction, {0.6, 0.8}, 1e-15));
    CHECK(approxEqual(atTarget->velocity, {12.0, 16.0}, 1e-14));
    CHECK(atTarget->angle == Approx(std::atan2(4.0, 3.0)));
    CHECK_FALSE(aimAtTarget({2, 3}, {2, 3}, 20.0));
}

TEST_CASE("gravity shot: on flat ground the two arcs are complementary angles", "[aim][ballistic]") {
    // Range x = s^2 sin(2 theta) / g: at s = 10 both 30 and 60 degrees land at 100 sin(60) / 9.81.
    const double range = 100.0 * std::sin(kPi / 3) / kG;
    const GravityShot shot = aimGravityShot({0, 0}, {range, 0}, 10.0, {0, -kG});
    REQUIRE(shot.reachable());
    REQUIRE(shot.highArc);
    CHECK(degrees(shot.lowArc->shot.angle) == Approx(30.0).epsilon(1e-12));
    CHECK(degrees(shot.highArc->shot.angle) == Approx(60.0).epsilon(1e-12));
    // Time of flight x / (s cos theta).
    CHECK(shot.lowArc->timeOfFlight == Approx(range / (10.0 * std::cos(kPi / 6))).epsilon(1e-12));
    CHECK(shot.highArc->timeOfFlight == Approx(range / (10.0 * std::cos(kPi / 3))).epsilon(1e-12));
    CHECK(shot.lowArc->shot.velocity.length() == Approx(10.0).epsilon(1e-14));
    CHECK(shot.reason.empty());
}

TEST_CASE("gravity shot: the angles are the course's tan(theta) formula", "[aim][ballistic]") {
    const Vec2 muzzle{1, 2};
    const double s = 25.0;
    for (const Vec2 target : {Vec2{31, 7}, Vec2{21, -8}, Vec2{6, 17}, Vec2{-24, 5}}) {
        // tan(theta) = (s^2 +- sqrt(s^4 - g (g x^2 + 2 y s^2))) / (g x), mirrored for targets on the left.
        const double x = std::fabs(target.x - muzzle.x), y = target.y - muzzle.y;
        const double root = std::sqrt(s * s * s * s - kG * (kG * x * x + 2 * y * s * s));
        const double low = std::atan((s * s - root) / (kG * x)), high = std::atan((s * s + root) / (kG * x));
        const GravityShot shot = aimGravityShot(muzzle, target, s, {0, -kG});
        REQUIRE(shot.highArc);
        const bool left = target.x < muzzle.x;
        CHECK(shot.lowArc->shot.angle == Approx(left ? kPi - low : low).epsilon(1e-12));
        CHECK(shot.highArc->shot.angle == Approx(left ? kPi - high : high).epsilon(1e-12));
    }
}

TEST_CASE("gravity shot: both arcs, flown by the exact method, pass the aimed point", "[aim][ballistic]") {
    const Vec2 muzzle{1, 2};
    struct Case {
        Vec2 target;
        Vec2 gravity;
    };
    // Below -y gravity, then sideways and tilted gravity (the solution never assumes a direction).
    const Case cases[] = {{{31, 7}, {0, -kG}}, {{21, -8}, {0, -kG}}, {{6, 17}, {0, -kG}}, {{-24, 5}, {0, -kG}},
                          {{18, 12}, {3, -8}}, {{-5, 20}, {kG, 0}},  {{1, 30}, {0, -kG}}};
    double worst = 0.0;
    for (const Case& c : cases) {
        const GravityShot shot = aimGravityShot(muzzle, c.target, 25.0, c.gravity);
        REQUIRE(shot.lowArc);
        REQUIRE(shot.highArc);
        CHECK(shot.lowArc->timeOfFlight < shot.highArc->timeOfFlight);
        for (const Arc& arc : {*shot.lowArc, *shot.highArc}) {
            const double miss = simulatedMiss(muzzle, arc.shot.velocity, c.gravity, c.target, arc.timeOfFlight);
            worst = std::max(worst, miss);
            CHECK(miss < 0.01 * kBallRadius);
        }
    }
    // Measured: 1.2e-13 m worst over 14 arcs (g++, x86-64), against the 2.5e-3 m allowed.
    CHECK(worst < 1e-9);
}

TEST_CASE("gravity shot: out of reach, and the minimum speed gives one arc", "[aim][ballistic]") {
    // s_min^2 = g (y + sqrt(x^2 + y^2)): on flat ground at 100 m, sqrt(981) = 31.321 m/s.
    const GravityShot far = aimGravityShot({0, 0}, {100, 0}, 10.0, {0, -kG});
    CHECK_FALSE(far.reachable());
    CHECK_FALSE(far.highArc);
    CHECK(far.minimumSpeed == Approx(std::sqrt(981.0)));
    CHECK(far.reason == "target out of reach: needs at least 31.321 m/s, muzzle speed is 10.000 m/s");

    const Vec2 target{30, 10};
    const double minimum = std::sqrt(kG * (10.0 + std::sqrt(1000.0)));
    const GravityShot edge = aimGravityShot({0, 0}, target, minimum, {0, -kG});
    CHECK(edge.minimumSpeed == Approx(minimum).epsilon(1e-15));
    REQUIRE(edge.reachable());
    CHECK_FALSE(edge.highArc);
    // At the minimum speed the launch angle bisects the vertical and the target's elevation: 45 deg + alpha / 2.
    CHECK(edge.lowArc->shot.angle == Approx(kPi / 4 + 0.5 * std::atan2(10.0, 30.0)).epsilon(1e-12));
    CHECK(simulatedMiss({0, 0}, edge.lowArc->shot.velocity, {0, -kG}, target, edge.lowArc->timeOfFlight) <
          0.01 * kBallRadius);

    // Just above: two arcs either side of it; just below: out of reach.
    const GravityShot above = aimGravityShot({0, 0}, target, minimum * (1 + 1e-9), {0, -kG});
    REQUIRE(above.highArc);
    CHECK(above.lowArc->shot.angle < edge.lowArc->shot.angle);
    CHECK(above.highArc->shot.angle > edge.lowArc->shot.angle);
    const GravityShot below = aimGravityShot({0, 0}, target, minimum * (1 - 1e-9), {0, -kG});
    CHECK_FALSE(below.reachable());
    CHECK(below.reason.rfind("target out of reach: needs at least", 0) == 0);

    // Without gravity any speed reaches: one straight arc, t = |d| / s.
    const GravityShot straight = aimGravityShot({0, 0}, {3, 4}, 2.0, {});
    REQUIRE(straight.reachable());
    CHECK_FALSE(straight.highArc);
    CHECK(straight.lowArc->timeOfFlight == Approx(2.5));
    CHECK(approxEqual(straight.lowArc->shot.velocity, {1.2, 1.6}, 1e-15));
    CHECK_FALSE(aimGravityShot({1, 1}, {1, 1}, 20.0, {0, -kG}).reachable());
}

TEST_CASE("leading a moving target without gravity", "[aim][lead]") {
    // Target at (10, 0) moving (0, 3), s = 5: 100 + 9 t^2 = 25 t^2 gives t = 2.5 at (10, 7.5).
    const std::optional<Intercept> hand = leadMovingTarget({0, 0}, {10, 0}, {0, 3}, 5.0);
    REQUIRE(hand);
    CHECK(hand->time == Approx(2.5).epsilon(1e-15));
    CHECK(approxEqual(hand->pointOfImpact, {10, 7.5}, 1e-15));
    CHECK(approxEqual(hand->shot.direction, {0.8, 0.6}, 1e-15));

    const Vec2 muzzle{-3, 2}, target{14, 9}, velocity{-2.5, 4};
    const std::optional<Intercept> lead = leadMovingTarget(muzzle, target, velocity, 8.0);
    REQUIRE(lead);
    CHECK(lead->shot.velocity.length() == Approx(8.0).epsilon(1e-15));
    auto gap = [&](double t) { return muzzle + lead->shot.velocity * t - (target + velocity * t); };
    const double miss = closestApproach(gap, 0.0, 2.0 * lead->time);
    // Measured: 4.4e-15 m over an 18 m lead (2.4e-16 relative).
    CHECK(miss < 1e-6 * (target - muzzle).length());

    // Moving away faster than the shot: never caught; an intercept after maxTime is not one.
    CHECK_FALSE(leadMovingTarget({0, 0}, {10, 0}, {10, 0}, 5.0));
    CHECK_FALSE(leadMovingTarget({0, 0}, {10, 0}, {0, 3}, 5.0, {}, 2.4));
}

TEST_CASE("leading a moving target with gravity", "[aim][lead]") {
    const Vec2 muzzle{0, 1}, gravity{0, -kG};
    const Vec2 target{40, 10}, velocity{-4, 3};
    const double s = 30.0;
    const std::optional<Intercept> lead = leadMovingTarget(muzzle, target, velocity, s, gravity);
    REQUIRE(lead);
    CHECK(lead->shot.velocity.length() == Approx(s).epsilon(1e-15));
    auto gap = [&](double t) {
        return muzzle + lead->shot.velocity * t + gravity * (0.5 * t * t) - (target + velocity * t);
    };
    const double miss = closestApproach(gap, 0.5 * lead->time, 1.5 * lead->time);
    // Measured: 0 analytically, 4.0e-14 m flown by the exact method.
    CHECK(miss < 1e-6 * (target - muzzle).length());
    CHECK(simulatedMiss(muzzle, lead->shot.velocity, gravity, target, lead->time, velocity) < 0.01 * kBallRadius);
    // The earliest: no shot at speed s reaches the target sooner, |d + v t - g t^2 / 2| > s t before it.
    for (int i = 1; i < 100; ++i) {
        const double t = lead->time * i / 100.0;
        CHECK((target - muzzle + velocity * t - gravity * (0.5 * t * t)).length() > s * t);
    }

    // A target standing still is the ballistic low arc; under sideways gravity too.
    for (const Vec2 g : {gravity, Vec2{-4, -6}}) {
        const GravityShot ballistic = aimGravityShot(muzzle, target, s, g);
        const std::optional<Intercept> still = leadMovingTarget(muzzle, target, {}, s, g);
        REQUIRE(still);
        CHECK(still->time == Approx(ballistic.lowArc->timeOfFlight).epsilon(1e-12));
        CHECK(approxEqual(still->shot.velocity, ballistic.lowArc->shot.velocity, 1e-12));
    }
    // Running away faster than the shot can follow.
    CHECK_FALSE(leadMovingTarget(muzzle, {200, 0}, {25, 0}, 20.0, gravity));
}

TEST_CASE("timing a fixed-angle shot at a moving target", "[aim][timing]") {
    // Straight up at 10 m/s; the target crosses x = 0 at y = 20 after 30 / 5 = 6 s; the shot needs 2 s.
    ShotTiming timing = timeFixedAngleShot({0, 0}, {0, 1}, 10.0, {-30, 20}, {5, 0});
    REQUIRE(timing.possible);
    CHECK(timing.delay == Approx(4.0).epsilon(1e-15));
    CHECK(timing.flightTime == Approx(2.0).epsilon(1e-15));
    CHECK(approxEqual(timing.pointOfImpact, {0, 20}, 1e-14));

    // With gravity at 30 m/s, 30 sigma - g sigma^2 / 2 = 20 twice: up after 0.76 s, down after 5.35 s.
    // The smallest delay is the one coming down: fire at 6 - 5.35 = 0.65 s rather than at 5.24 s.
    const Vec2 gravity{0, -kG};
    timing = timeFixedAngleShot({0, 0}, {0, 1}, 30.0, {-30, 20}, {5, 0}, gravity);
    REQUIRE(timing.possible);
    const double sigma = (30.0 + std::sqrt(900.0 - 2.0 * kG * 20.0)) / kG;
    CHECK(timing.flightTime == Approx(sigma).epsilon(1e-14));
    CHECK(timing.delay == Approx(6.0 - sigma).epsilon(1e-14));

    // An angled shot under gravity at a target on a slant: built to meet after a delay of 1.5 s and a
    // flight of 2 s; flown by the exact method from the moment it is fired.
    const Vec2 muzzle{2, 1}, direction = Vec2::fromAngle(1.0), velocity{-3, 1.5};
    const Vec2 meet = muzzle + direction * 20.0 * 2.0 + gravity * 2.0;
    const Vec2 target = meet - velocity * 3.5;
    timing = timeFixedAngleShot(muzzle, direction, 20.0, target, velocity, gravity);
    REQUIRE(timing.possible);
    CHECK(timing.delay == Approx(1.5).epsilon(1e-12));
    CHECK(timing.flightTime == Approx(2.0).epsilon(1e-12));
    CHECK(approxEqual(timing.pointOfImpact, meet, 1e-12));
    CHECK(simulatedMiss(muzzle, direction * 20.0, gravity, target + velocity * timing.delay, timing.flightTime,
                        velocity) < 0.01 * kBallRadius);

    // Along the target's own line: fire now (20 = 10 sigma + 5 sigma) unless it runs away faster than the shot.
    timing = timeFixedAngleShot({0, 0}, {1, 0}, 10.0, {20, 0}, {-5, 0});
    REQUIRE(timing.possible);
    CHECK(timing.delay == 0.0);
    CHECK(timing.flightTime == Approx(4.0 / 3.0));
    CHECK_FALSE(timeFixedAngleShot({0, 0}, {1, 0}, 10.0, {20, 0}, {15, 0}).possible);

    // A target standing on the path is hit at any time (delay 0); one beside it never.
    const Vec2 onPath = direction * 20.0 * 1.7 + gravity * (0.5 * 1.7 * 1.7);
    timing = timeFixedAngleShot({0, 0}, direction, 20.0, onPath, {}, gravity);
    REQUIRE(timing.possible);
    CHECK(timing.delay == 0.0);
    CHECK(timing.flightTime == Approx(1.7).epsilon(1e-12));
    CHECK_FALSE(timeFixedAngleShot({0, 0}, direction, 20.0, onPath + Vec2{0, 0.01}, {}, gravity).possible);
}

TEST_CASE("timing a fixed-angle shot: impossible cases say so", "[aim][timing]") {
    const Vec2 gravity{0, -kG};
    // Already past the line of fire: it would have had to be fired 2 s ago.
    ShotTiming late = timeFixedAngleShot({0, 0}, {0, 1}, 10.0, {10, 20}, {5, 0});
    CHECK_FALSE(late.possible);
    CHECK_FALSE(late.reason.empty());
    // Above the shot's highest point, 30^2 / 2g = 45.9 m.
    CHECK_FALSE(timeFixedAngleShot({0, 0}, {0, 1}, 30.0, {-30, 100}, {5, 0}, gravity).possible);
    // Parallel paths never cross.
    const ShotTiming parallel = timeFixedAngleShot({0, 0}, {1, 0}, 10.0, {0, 5}, {3, 0});
    CHECK_FALSE(parallel.possible);
    CHECK(parallel.reason.find("parallel") != std::string::npos);
    CHECK_FALSE(timeFixedAngleShot({0, 0}, {}, 10.0, {0, 5}, {3, 0}).possible);
}

TEST_CASE("predicted arc: points on the parabola, ending where it leaves the box", "[aim][arc]") {
    const Vec2 p{1, 2}, v{10, 10}, g{0, -kG};
    const std::vector<Vec2> arc = predictedArc(p, v, g, 2.0, 11);
    REQUIRE(arc.size() == 11);
    for (int i = 0; i < 11; ++i) {
        const double t = 0.2 * i;
        CHECK(approxEqual(arc[static_cast<std::size_t>(i)], p + v * t + g * (0.5 * t * t), 1e-14));
    }

    // The floor y = 0 of the box is crossed when 2 + 10 t - 4.905 t^2 = 0.
    const Aabb box{{-5, 0}, {50, 50}};
    const std::vector<Vec2> clipped = predictedArc(p, v, g, 10.0, 101, box);
    REQUIRE(clipped.size() >= 3);
    REQUIRE(clipped.size() < 101);
    for (const Vec2 q : clipped) CHECK(box.contains(q));
    const double landing = (10.0 + std::sqrt(100.0 + 4.0 * 4.905 * 2.0)) / (2.0 * 4.905);
    CHECK(clipped.back().x == Approx(1.0 + 10.0 * landing).epsilon(1e-12));
    CHECK(clipped.back().y == Approx(0.0).margin(1e-12));
    CHECK(predictedArc({-10, 1}, v, g, 1.0, 5, box).empty());
}
