// Continuous detection (lecture 5): every branch of every time-of-impact function, with figures
// worked out by hand in the comments, and the root finder behind the accelerated cases.
#include "rube/physics/time_of_impact.hpp"

#include "polynomial.hpp" // internal: tests may reach inside, users may not

#include <catch2/catch.hpp>

#include <cmath>

using namespace rube;

namespace {
constexpr auto attempt1 = TimeOfImpactRule::attempt1;
constexpr auto attempt2 = TimeOfImpactRule::attempt2;
constexpr auto attempt3 = TimeOfImpactRule::attempt3;
} // namespace

TEST_CASE("circle-circle: the abc formula finds the smaller root", "[toi]") {
    // u = (-5, 0), v = (2, 0), R = 1: a = 4, b = -20, c = 24, D = 16, t = (20 - 4) / 8 = 2.
    CHECK(circleCircleTimeOfImpact({-5, 0}, {2, 0}, 1.0, 3.0) == Approx(2.0));
    // The same impact lies after a horizon of 1.5 s: not this step.
    CHECK_FALSE(circleCircleTimeOfImpact({-5, 0}, {2, 0}, 1.0, 1.5));
    // Glancing: (t - 5)^2 + 0.6^2 = 1 gives t = 5 - 0.8 = 4.2.
    CHECK(circleCircleTimeOfImpact({-5, 0.6}, {1, 0}, 1.0, 10.0) == Approx(4.2));
}

TEST_CASE("circle-circle: no solutions, two negative solutions, a ~ 0", "[toi]") {
    // Passing at distance 2 > R = 1: a = 1, b = -10, c = 28, D = 100 - 112 < 0.
    CHECK_FALSE(circleCircleTimeOfImpact({-5, 2}, {1, 0}, 1.0, 100.0));
    // Moving apart: both roots negative.
    CHECK_FALSE(circleCircleTimeOfImpact({5, 0}, {1, 0}, 1.0, 100.0));
    // Not moving (a = 0), or so slowly no gap closes: skip the test.
    CHECK_FALSE(circleCircleTimeOfImpact({-5, 0}, {0, 0}, 1.0, 100.0));
    CHECK_FALSE(circleCircleTimeOfImpact({-1.5, 0}, {1e-13, 0}, 1.0, 1e9));
}

TEST_CASE("circle-circle: the three attempts for an overlap at the start", "[toi]") {
    // Overlapping and approaching: u = (-1.5, 0), v = (1, 0), R = 2: c = 2.25 - 4 < 0, b = -3 < 0.
    // Attempt 1 computes t = (3 - 4) / 2 = -0.5 and ignores it: the balls pass through each other.
    CHECK_FALSE(circleCircleTimeOfImpact({-1.5, 0}, {1, 0}, 2.0, 1.0, attempt1));
    CHECK(circleCircleTimeOfImpact({-1.5, 0}, {1, 0}, 2.0, 1.0, attempt2) == 0.0);
    CHECK(circleCircleTimeOfImpact({-1.5, 0}, {1, 0}, 2.0, 1.0, attempt3) == 0.0);
    // Overlapping and separating (b = 3 > 0): attempt 2 still reports an impact now (the balls stick),
    // attempt 3 lets them go.
    CHECK_FALSE(circleCircleTimeOfImpact({1.5, 0}, {1, 0}, 2.0, 1.0, attempt1));
    CHECK(circleCircleTimeOfImpact({1.5, 0}, {1, 0}, 2.0, 1.0, attempt2) == 0.0);
    CHECK_FALSE(circleCircleTimeOfImpact({1.5, 0}, {1, 0}, 2.0, 1.0, attempt3));
    // Rounding after a reset to the point of impact: overlapping by 1e-15 m only.
    CHECK_FALSE(circleCircleTimeOfImpact({-(2.0 - 1e-15), 0}, {1, 0}, 2.0, 1.0, attempt1));
    CHECK(circleCircleTimeOfImpact({-(2.0 - 1e-15), 0}, {1, 0}, 2.0, 1.0, attempt3) == 0.0);
    // Exactly touching and approaching: c = 0, t = 0 under every rule.
    CHECK(circleCircleTimeOfImpact({-2, 0}, {1, 0}, 2.0, 1.0, attempt1) == 0.0);
    CHECK(circleCircleTimeOfImpact({-2, 0}, {1, 0}, 2.0, 1.0, attempt3) == 0.0);
}

TEST_CASE("circle-circle: the smaller root is computed without cancellation", "[toi]") {
    // A gap of 3e-12 m closed at 7.3 m/s: t = gap / 7.3 (the gap as a double: x - 1 is exact).
    // The textbook (-b - sqrt(D)) / 2a subtracts two numbers near 14.6 and is off by 2e-5 of t here;
    // 2c / (-b + sqrt(D)) is good to an ulp or two.
    const double x = 1.0 + 3e-12;
    const auto t = circleCircleTimeOfImpact({-x, 0}, {7.3, 0}, 1.0, 1.0);
    REQUIRE(t);
    CHECK(*t == Approx((x - 1.0) / 7.3).epsilon(1e-14));
}

TEST_CASE("line: the lecture's a/b time of impact", "[toi]") {
    CHECK_FALSE(lineTimeOfImpact(1.0, 0.0, 0.5, 10.0));  // b = 0: moving along the line
    CHECK_FALSE(lineTimeOfImpact(1.0, -1.0, 0.5, 10.0)); // b < 0: moving away
    CHECK(lineTimeOfImpact(0.5, 2.0, 0.5, 1.0) == 0.25); // t = a / b
    CHECK(lineTimeOfImpact(0.0, 1.0, 0.5, 1.0) == 0.0);  // touching now
    CHECK_FALSE(lineTimeOfImpact(0.5, 2.0, 0.5, 0.2));   // after the horizon
    // -r <= a < 0: slightly inside and going deeper: t = 0, except for the sinking first pseudo code.
    CHECK(lineTimeOfImpact(-0.1, 1.0, 0.5, 1.0) == 0.0);
    CHECK(lineTimeOfImpact(-0.5, 1.0, 0.5, 1.0) == 0.0);
    CHECK(lineTimeOfImpact(-0.1, 1.0, 0.5, 1.0, attempt2) == 0.0);
    CHECK_FALSE(lineTimeOfImpact(-0.1, 1.0, 0.5, 1.0, attempt1));
    CHECK_FALSE(lineTimeOfImpact(-0.6, 1.0, 0.5, 1.0)); // a < -r: the centre is past the line
}

TEST_CASE("circle-segment: faces on both sides, with the point of impact", "[toi]") {
    const Vec2 a{0, 0}, b{4, 0};
    SECTION("from above: a = 3 - 0.5, b = 5, t = 0.5") {
        const auto hit = circleSegmentCollision({{1, 3}, {1, -5}, 0.5}, a, b, 0.0, 1.0);
        REQUIRE(hit);
        CHECK(hit->timeOfImpact == Approx(0.5));
        CHECK(approxEqual(hit->pointOfImpact, {1.5, 0.5}));
        CHECK(approxEqual(hit->normal, {0, 1}));
        CHECK(approxEqual(hit->contactPoint, {1.5, 0}));
        CHECK_FALSE(hit->lineCap);
    }
    SECTION("from below: the opposite normal, a = 1.5, b = 3") {
        const auto hit = circleSegmentCollision({{2, -2}, {0, 3}, 0.5}, a, b, 0.0, 1.0);
        REQUIRE(hit);
        CHECK(hit->timeOfImpact == Approx(0.5));
        CHECK(approxEqual(hit->pointOfImpact, {2, -0.5}));
        CHECK(approxEqual(hit->normal, {0, -1}));
    }
    SECTION("moving away or after the horizon: nothing") {
        CHECK_FALSE(circleSegmentCollision({{2, 1}, {0, 1}, 0.5}, a, b, 0.0, 1.0));
        CHECK_FALSE(circleSegmentCollision({{1, 3}, {1, -5}, 0.5}, a, b, 0.0, 0.4));
    }
    SECTION("a thick segment: the face is radius 0.25 further out, a = 3 - 0.75") {
        const auto hit = circleSegmentCollision({{2, 3}, {0, -5}, 0.5}, a, b, 0.25, 1.0);
        REQUIRE(hit);
        CHECK(hit->timeOfImpact == Approx(0.45));
        CHECK(approxEqual(hit->pointOfImpact, {2, 0.75}));
        CHECK(approxEqual(hit->contactPoint, {2, 0.25}));
    }
}

TEST_CASE("circle-segment: overlaps at the start, the robust rule and the sinking variant", "[toi]") {
    const Vec2 a{0, 0}, b{4, 0};
    // 1e-4 m inside the line and still falling: a = -1e-4.
    const CircleMotion sunk{{2, 0.4999}, {0, -1}, 0.5};
    const auto robust = circleSegmentCollision(sunk, a, b, 0.0, 1.0);
    REQUIRE(robust);
    CHECK(robust->timeOfImpact == 0.0);
    CHECK(approxEqual(robust->normal, {0, 1}));
    CHECK_FALSE(circleSegmentCollision(sunk, a, b, 0.0, 1.0, attempt1)); // "ignore a < 0": it sinks
    // Inside and moving out: nothing, under every rule.
    CHECK_FALSE(circleSegmentCollision({{2, 0.4999}, {0, 1}, 0.5}, a, b, 0.0, 1.0));
    CHECK_FALSE(circleSegmentCollision({{2, 0.4999}, {0, 1}, 0.5}, a, b, 0.0, 1.0, attempt2));
    // Centre exactly on the line: both faces have a = -r; the one it moves into pushes it back.
    const auto onLine = circleSegmentCollision({{2, 0}, {0, -1}, 0.5}, a, b, 0.0, 1.0);
    REQUIRE(onLine);
    CHECK(onLine->timeOfImpact == 0.0);
    CHECK(approxEqual(onLine->normal, {0, 1}));
    // Centre 0.4 below the line moving up: the upper face has a = -0.9 < -r (past it), the lower face
    // a = -0.1 and approaching: t = 0 with the downward normal.
    const auto below = circleSegmentCollision({{2, -0.4}, {0, 1}, 0.5}, a, b, 0.0, 1.0);
    REQUIRE(below);
    CHECK(approxEqual(below->normal, {0, -1}));
}

TEST_CASE("circle-segment: line caps", "[toi]") {
    const Vec2 a{0, 0}, b{4, 0};
    SECTION("the face's point of impact is past the end: the cap at b") {
        // Face POI (4.3, 0.5) lies 4.3 along a line 4 long. Cap: 0.3^2 + (3 - 5t)^2 = 0.5^2, t = 0.52.
        const auto hit = circleSegmentCollision({{4.3, 3}, {0, -5}, 0.5}, a, b, 0.0, 1.0);
        REQUIRE(hit);
        CHECK(hit->lineCap);
        CHECK(hit->timeOfImpact == Approx(0.52));
        CHECK(approxEqual(hit->pointOfImpact, {4.3, 0.4}));
        CHECK(approxEqual(hit->normal, {0.6, 0.8}));
        CHECK(approxEqual(hit->contactPoint, b));
    }
    SECTION("along the line from outside: b = 0 for both faces, the cap at a stops it") {
        const auto hit = circleSegmentCollision({{-2, 0}, {4, 0}, 0.5}, a, b, 0.0, 1.0);
        REQUIRE(hit);
        CHECK(hit->lineCap);
        CHECK(hit->timeOfImpact == Approx(0.375)); // |-2 + 4t| = 0.5
        CHECK(approxEqual(hit->normal, {-1, 0}));
    }
    SECTION("past the cap at a distance above the radius: nothing") {
        CHECK_FALSE(circleSegmentCollision({{5, 3}, {0, -5}, 0.5}, a, b, 0.0, 1.0));
    }
    SECTION("a rounded cap of a thick segment, and a point-like segment") {
        const auto thick = circleSegmentCollision({{-2, 0}, {4, 0}, 0.5}, a, b, 0.25, 1.0);
        REQUIRE(thick);
        CHECK(thick->timeOfImpact == Approx(0.3125)); // |-2 + 4t| = 0.75
        CHECK(approxEqual(thick->contactPoint, {-0.25, 0}));
        const auto point = circleSegmentCollision({{-2, 0}, {4, 0}, 0.5}, a, a, 0.0, 1.0);
        REQUIRE(point);
        CHECK(point->lineCap);
        CHECK(point->timeOfImpact == Approx(0.375));
    }
    SECTION("circle-point is circle-circle with r2 = 0") {
        const auto hit = circlePointCollision({{-2, 0}, {4, 0}, 0.5}, {0, 0}, 1.0);
        REQUIRE(hit);
        CHECK(hit->timeOfImpact == Approx(0.375));
        CHECK(approxEqual(hit->contactPoint, {0, 0}));
    }
}

TEST_CASE("under gravity: the line face is a quadratic", "[toi][gravity]") {
    const Vec2 a{-10, 0}, b{10, 0};
    const Vec2 g{0, -9.81};
    SECTION("dropped from rest: 9.5 = 4.905 t^2") {
        const auto hit = circleSegmentCollision({{0, 10}, {0, 0}, 0.5, g}, a, b, 0.0, 2.0);
        REQUIRE(hit);
        CHECK(hit->timeOfImpact == Approx(std::sqrt(9.5 / 4.905)).epsilon(1e-14));
        CHECK(hit->pointOfImpact.y == Approx(0.5).epsilon(1e-14));
    }
    SECTION("thrown up at a ceiling: 4 - 10 t + 5 t^2 = 0, t = 1 - sqrt(0.2)") {
        const CircleMotion up{{0, 0}, {0, 10}, 0.5, {0, -10}};
        const auto hit = circleSegmentCollision(up, {-10, 4.5}, {10, 4.5}, 0.0, 2.0);
        REQUIRE(hit);
        CHECK(hit->timeOfImpact == Approx(1.0 - std::sqrt(0.2)).epsilon(1e-14));
        CHECK(approxEqual(hit->normal, {0, -1}));
        // A ceiling at 6: 5.5 - 10 t + 5 t^2 has no real root, the ball turns back first.
        CHECK_FALSE(circleSegmentCollision(up, {-10, 6}, {10, 6}, 0.0, 2.0));
    }
    SECTION("touching and moving apart: it lands again at t = 2 v / g") {
        const CircleMotion hop{{0, 0.5}, {0, 1}, 0.5, {0, -10}};
        const auto hit = circleSegmentCollision(hop, a, b, 0.0, 1.0);
        REQUIRE(hit);
        CHECK(hit->timeOfImpact == Approx(0.2));
        CHECK_FALSE(circleSegmentCollision(hop, a, b, 0.0, 0.1));
    }
    SECTION("resting: no normal speed, gravity towards the line decides") {
        const auto touching = circleSegmentCollision({{0, 0.5}, {3, 0}, 0.5, g}, a, b, 0.0, 1.0);
        REQUIRE(touching);
        CHECK(touching->timeOfImpact == 0.0);
        const auto sunk = circleSegmentCollision({{0, 0.5 - 1e-12}, {3, 0}, 0.5, g}, a, b, 0.0, 1.0);
        REQUIRE(sunk);
        CHECK(sunk->timeOfImpact == 0.0);
        CHECK_FALSE(circleSegmentCollision({{0, 0.5 - 1e-12}, {3, 0}, 0.5, g}, a, b, 0.0, 1.0, attempt1));
        // Gravity pointing away from the line (a ceiling): no impact.
        CHECK_FALSE(circleSegmentCollision({{0, -0.5 + 1e-12}, {3, 0}, 0.5, g}, a, b, 0.0, 1.0));
    }
    SECTION("slightly inside and separating, but gravity turns it back") {
        // Gap -1e-3 + 1e-3 t - 5 t^2: it stops rising at t = 1e-4, still inside: impact then.
        const auto turns = circleSegmentCollision({{0, 0.499}, {0, 1e-3}, 0.5, {0, -10}}, a, b, 0.0, 1.0);
        REQUIRE(turns);
        CHECK(turns->timeOfImpact == Approx(1e-4));
        // Gap -1e-6 + t - 5 t^2: it leaves the line and lands at the larger root.
        const auto lands = circleSegmentCollision({{0, 0.5 - 1e-6}, {0, 1}, 0.5, {0, -10}}, a, b, 0.0, 1.0);
        REQUIRE(lands);
        CHECK(lands->timeOfImpact == Approx((1.0 + std::sqrt(1.0 - 2e-5)) / 10).epsilon(1e-12));
        // The first two rules do not look ahead.
        CHECK_FALSE(circleSegmentCollision({{0, 0.499}, {0, 1e-3}, 0.5, {0, -10}}, a, b, 0.0, 1.0, attempt1));
        const auto sticks = circleSegmentCollision({{0, 0.499}, {1, 0}, 0.5, {0, -10}}, {-1, 0}, {1, 0}, 0.0, 1.0,
                                                   attempt2);
        REQUIRE(sticks);
        CHECK(sticks->timeOfImpact == 0.0);
    }
}

TEST_CASE("under gravity: circle against a point or circle is a quartic", "[toi][gravity]") {
    SECTION("dropped onto a ball below: |5 - 5 t^2| = 1, t = sqrt(0.8)") {
        const auto hit = circleCircleCollision({{0, 5}, {0, 0}, 0.5, {0, -10}}, {0, 0}, 0.5, 2.0);
        REQUIRE(hit);
        CHECK(hit->timeOfImpact == Approx(std::sqrt(0.8)).epsilon(1e-14));
        CHECK(approxEqual(hit->normal, {0, 1}));
    }
    SECTION("dropped beside it: 0.36 + (5 - 5 t^2)^2 = 1, t = sqrt(0.84), normal (-0.6, 0.8)") {
        const auto hit = circleCircleCollision({{0, 5}, {0, 0}, 0.5, {0, -10}}, {0.6, 0}, 0.5, 2.0);
        REQUIRE(hit);
        CHECK(hit->timeOfImpact == Approx(std::sqrt(0.84)).epsilon(1e-14));
        CHECK(approxEqual(hit->normal, {-0.6, 0.8}, 1e-12));
        CHECK(approxEqual(hit->contactPoint, {0.3, 0.4}, 1e-12));
    }
    SECTION("a thrown ball: d(t) = (-3 + 6t, 3t - 3t^2) reaches |d|^2 = 13/9 at t = 1/3") {
        const CircleMotion thrown{{-3, 0}, {6, 3}, 0.0, {0, -6}};
        const auto hit = circlePointCollision(
            {thrown.centre, thrown.velocity, std::sqrt(13.0) / 3, thrown.acceleration}, {0, 0}, 1.0);
        REQUIRE(hit);
        CHECK(hit->timeOfImpact == Approx(1.0 / 3).epsilon(1e-14));
        CHECK(approxEqual(hit->pointOfImpact, {-1, 2.0 / 3}, 1e-12));
    }
    SECTION("the same rules at the start") {
        const Vec2 g{0, -10};
        // Overlapping, no speed, gravity pulling it in: approaching by acceleration.
        CHECK(circleCircleCollision({{0, 0.999}, {0, 0}, 0.5, g}, {0, 0}, 0.5, 1.0)->timeOfImpact == 0.0);
        CHECK_FALSE(circleCircleCollision({{0, 0.999}, {0, 0}, 0.5, g}, {0, 0}, 0.5, 1.0, attempt1));
        // Overlapping and moving apart fast: separating all step.
        CHECK_FALSE(circleCircleCollision({{0, 0.999}, {0, 5}, 0.5, g}, {0, 0}, 0.5, 0.1));
        CHECK(circleCircleCollision({{0, 0.999}, {0, 5}, 0.5, g}, {0, 0}, 0.5, 0.1, attempt2)->timeOfImpact == 0.0);
        // Touching and approaching: t = 0; touching and moving apart: lands again at 2 v / g = 0.2.
        CHECK(circleCircleCollision({{0, 1}, {0, -1}, 0.5, g}, {0, 0}, 0.5, 1.0)->timeOfImpact == 0.0);
        CHECK(circleCircleCollision({{0, 1}, {0, 1}, 0.5, g}, {0, 0}, 0.5, 1.0)->timeOfImpact == Approx(0.2));
        // No acceleration: the lecture's quadratic.
        CHECK(circleCircleCollision({{-5, 0}, {2, 0}, 0.5}, {0, 0}, 0.5, 3.0)->timeOfImpact == Approx(2.0));
    }
}

TEST_CASE("polynomial roots: isolated by the derivative, refined to round-off", "[toi][polynomial]") {
    // (t - 1)(t - 2)(t - 3)(t - 4) = t^4 - 10 t^3 + 35 t^2 - 50 t + 24.
    const Polynomial quartic{{24, -50, 35, -10, 1}};
    CHECK(quartic.degree() == 4);
    // Round-off here: p(t) is evaluated with an error of about 360 eps (the sum of |c_i t^i|) where its
    // slope is 2 to 6, so a root is good to a few hundred eps.
    std::array<double, 4> roots{};
    REQUIRE(rootsBetween(quartic, 0.0, 5.0, roots) == 4);
    for (int i = 0; i < 4; ++i) CHECK(roots[i] == Approx(i + 1.0).epsilon(1e-13));
    CHECK(rootsBetween(quartic, 1.5, 3.5, roots) == 2);
    CHECK(*earliestRoot(quartic, 0.0, 5.0) == Approx(1.0).epsilon(1e-13));
    CHECK(*earliestRoot(quartic, 1.5, 5.0) == Approx(2.0).epsilon(1e-13));
    CHECK_FALSE(earliestRoot(quartic, 4.5, 5.0));
    // A double root touching zero at a critical point: found because p is exactly zero there.
    CHECK(*earliestRoot(Polynomial{{1, -2, 1}}, 0.0, 3.0) == 1.0);
    // Constants and the zero polynomial have no isolated roots; a line has one.
    CHECK_FALSE(earliestRoot(Polynomial{{2}}, 0.0, 1.0));
    CHECK_FALSE(earliestRoot(Polynomial{}, 0.0, 1.0));
    CHECK(*earliestRoot(Polynomial{{-1, 2}}, 0.0, 1.0) == 0.5);
    // A root at the start counts, unless skipped (touching and moving apart): t (t - 1).
    CHECK(*earliestRoot(Polynomial{{0, -1, 1}}, 0.0, 2.0) == 0.0);
    CHECK(*earliestRoot(Polynomial{{0, -1, 1}}, 0.0, 2.0, true) == 1.0);
}

TEST_CASE("polynomial roots: the answer is the last double before the sign change", "[toi][polynomial]") {
    // t^2 - 2 on [0, 2]: p(t) < 0 before sqrt(2), and the next double up is past it.
    const Polynomial p{{-2, 0, 1}};
    const double t = *earliestRoot(p, 0.0, 2.0);
    CHECK(p(t) <= 0.0);
    CHECK(p(std::nextafter(t, 3.0)) >= 0.0);
    CHECK(t == Approx(std::sqrt(2.0)).epsilon(1e-15));
    // Falling onto a line 1 m below from rest: 1 - 4.905 t^2, positive before the root.
    const Polynomial fall{{1, 0, -4.905}};
    const double tf = *earliestRoot(fall, 0.0, 1.0);
    CHECK(fall(tf) >= 0.0);
    CHECK(fall(std::nextafter(tf, 1.0)) <= 0.0);
}

TEST_CASE("out of reach: a pair is only passed over when its gap cannot close, found at the very edge of reach",
          "[toi][gravity]") {
    // The searches skip a pair whose surfaces are farther apart than a centre can move within the
    // horizon, |v| h + |acc| h^2 / 2 (time_of_impact.cpp). A ball moving straight at the other, with
    // its acceleration along its velocity, travels exactly that far: placed at the reach times
    // (1 + delta) it must be hit for every delta < 0, a millionth inside the skip's margin as much
    // as a thousandth, and never past it. Over speeds, accelerations (with, against and across the
    // motion: reach is an upper bound there), horizons, radii and directions.
    int hits = 0, cases = 0;
    for (const double speed : {0.0, 0.3, 4.0, 60.0})
        for (const double accel : {0.0, 9.81, 400.0})
            for (const double horizon : {1.0 / 60.0, 0.01, 0.5})
                for (const double radiusSum : {0.05, 0.45, 3.0})
                    for (const double angle : {0.0, 1.0, 2.5, 4.0})
                        for (const double delta : {-1e-3, -1e-5, -1e-7, -1e-9, 1e-4, 1e-2}) {
                            if (speed == 0.0 && accel == 0.0) continue;
                            const Vec2 dir{std::cos(angle), std::sin(angle)};
                            const double reach = speed * horizon + 0.5 * accel * horizon * horizon;
                            const Vec2 start{1.5, -2.0};
                            const Vec2 other = start + dir * ((radiusSum + reach * (1.0 + delta)));
                            // The gap R + reach delta: hit when delta < 0, the last instants of the horizon.
                            const auto hit = circleCircleCollision({start, dir * speed, radiusSum, dir * accel}, other,
                                                                   0.0, horizon);
                            CAPTURE(speed, accel, horizon, radiusSum, angle, delta);
                            ++cases;
                            if (delta < 0.0) {
                                REQUIRE(hit);
                                CHECK(hit->timeOfImpact <= horizon);
                                ++hits;
                            } else {
                                CHECK_FALSE(hit);
                            }
                            // Across the motion (or against it), the reach over-states the travel:
                            // the same gap is never met.
                            const Vec2 across{-dir.y, dir.x};
                            CHECK_FALSE(circleCircleCollision(
                                {start, across * speed, radiusSum, -across * accel},
                                start + dir * (radiusSum + reach * (1.0 + std::abs(delta))), 0.0, horizon));
                        }
    CHECK(hits > 0);
    CHECK(cases > hits);
}

TEST_CASE("out of reach: a segment is passed over only when neither its faces nor its caps can be met",
          "[toi][gravity]") {
    // The same edge for a segment: a ball moving straight at its face (hit just inside reach) and at
    // the point beyond one end, within the segment's own radius of its cap.
    for (const double speed : {0.5, 8.0})
        for (const double accel : {0.0, 9.81})
            for (const double segmentRadius : {0.0, 0.1})
                for (const double delta : {-1e-3, -1e-7, -1e-9, 1e-4}) {
                    CAPTURE(speed, accel, segmentRadius, delta);
                    const double horizon = 1.0 / 60.0, r = 0.2;
                    const double reach = speed * horizon + 0.5 * accel * horizon * horizon;
                    const double gap = reach * (1.0 + delta);
                    // Face: the segment from (-1, 0) to (1, 0), the ball coming straight down at it.
                    const double y = r + segmentRadius + gap;
                    const auto face = circleSegmentCollision({{0.3, y}, {0.0, -speed}, r, {0.0, -accel}}, {-1.0, 0.0},
                                                             {1.0, 0.0}, segmentRadius, horizon);
                    // Cap: the ball coming along the segment's line at its end b.
                    const auto cap = circleSegmentCollision(
                        {{1.0 + r + segmentRadius + gap, 0.0}, {-speed, 0.0}, r, {-accel, 0.0}}, {-1.0, 0.0},
                        {1.0, 0.0}, segmentRadius, horizon);
                    if (delta < 0.0) {
                        REQUIRE(face);
                        CHECK_FALSE(face->lineCap);
                        REQUIRE(cap);
                        CHECK(cap->lineCap);
                    } else {
                        CHECK_FALSE(face);
                        CHECK_FALSE(cap);
                    }
                }
}
