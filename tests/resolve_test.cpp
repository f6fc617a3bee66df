// Collision resolve (lecture 3): v' = u - C (v - u) along the normal, tangential velocity kept,
// momentum conserved, walls as infinite mass; and the position reset.
#include "resolve.hpp" // internal: tests may reach inside, users may not

#include <catch2/catch.hpp>

#include <array>
#include <cmath>

using namespace rube;

namespace {

// Total momentum m1 v1 + m2 v2, from inverse masses.
Vec2 momentum(Vec2 v1, double inverseMass1, Vec2 v2, double inverseMass2) {
    return v1 / inverseMass1 + v2 / inverseMass2;
}

} // namespace

TEST_CASE("head-on, equal masses: C = 1 swaps the velocities, C = 0 stops both", "[resolve]") {
    // Body 1 on the left moving right, body 2 on the right moving left; n from 2 to 1 is (-1, 0).
    const Vec2 n{-1, 0};
    SECTION("C = 1") {
        Vec2 v1{2, 0}, v2{-2, 0};
        CHECK(resolveImpact(v1, 1.0, v2, 1.0, n, 1.0) == 4.0); // approach speed
        CHECK(v1 == Vec2{-2, 0});
        CHECK(v2 == Vec2{2, 0});
    }
    SECTION("C = 0: total momentum 0, so both stop (lecture 3, solution 2)") {
        Vec2 v1{2, 0}, v2{-2, 0};
        resolveImpact(v1, 1.0, v2, 1.0, n, 0.0);
        CHECK(v1.x == 0.0);
        CHECK(v2.x == 0.0);
    }
}

TEST_CASE("head-on, masses 1 and 3: the centre of mass frame", "[resolve]") {
    // u = (1 * 4 + 3 * 0) / 4 = 1.
    const Vec2 n{-1, 0};
    SECTION("C = 1: v1' = 1 - (4 - 1) = -2, v2' = 1 - (0 - 1) = 2") {
        Vec2 v1{4, 0}, v2{0, 0};
        resolveImpact(v1, 1.0, v2, 1.0 / 3.0, n, 1.0);
        CHECK(v1.x == Approx(-2.0));
        CHECK(v2.x == Approx(2.0));
        // Kinetic energy kept: 1/2 16 = 1/2 (4 + 3 * 4).
        CHECK(v1.lengthSquared() + 3.0 * v2.lengthSquared() == Approx(16.0));
    }
    SECTION("C = 0.5: v1' = 1 - 0.5 * 3 = -0.5, v2' = 1 + 0.5 = 1.5") {
        Vec2 v1{4, 0}, v2{0, 0};
        resolveImpact(v1, 1.0, v2, 1.0 / 3.0, n, 0.5);
        CHECK(v1.x == Approx(-0.5));
        CHECK(v2.x == Approx(1.5));
        CHECK(approxEqual(momentum(v1, 1.0, v2, 1.0 / 3.0), {4, 0}));
    }
    SECTION("C = 0: they move on together at u") {
        Vec2 v1{4, 0}, v2{0, 0};
        resolveImpact(v1, 1.0, v2, 1.0 / 3.0, n, 0.0);
        CHECK(v1.x == Approx(1.0));
        CHECK(v2.x == Approx(1.0));
    }
}

TEST_CASE("glancing: only the normal parts change, tangential velocity is kept", "[resolve]") {
    // Body 1 above body 2 (n = (0, 1)), moving (3, -4); body 2 at rest; equal masses.
    const Vec2 n{0, 1};
    SECTION("C = 1: the normal part moves across completely") {
        Vec2 v1{3, -4}, v2{0, 0};
        resolveImpact(v1, 1.0, v2, 1.0, n, 1.0);
        CHECK(approxEqual(v1, {3, 0}));
        CHECK(approxEqual(v2, {0, -4}));
    }
    SECTION("C = 0: both share the normal part, u = -2") {
        Vec2 v1{3, -4}, v2{0, 0};
        resolveImpact(v1, 1.0, v2, 1.0, n, 0.0);
        CHECK(approxEqual(v1, {3, -2}));
        CHECK(approxEqual(v2, {0, -2}));
    }
    SECTION("an angled normal: (-3, -4) is -5 n for n = (0.6, 0.8), so it all transfers") {
        Vec2 v1{-3, -4}, v2{1, -1};
        const Vec2 before = momentum(v1, 1.0, v2, 1.0);
        resolveImpact(v1, 1.0, v2, 1.0, {0.6, 0.8}, 1.0);
        CHECK(approxEqual(momentum(v1, 1.0, v2, 1.0), before));
        // The tangential parts, along (-0.8, 0.6), are untouched: 0 for v1, -1.4 for v2.
        CHECK(v1.dot({-0.8, 0.6}) == Approx(0.0).margin(1e-12));
        CHECK(v2.dot({-0.8, 0.6}) == Approx(-1.4));
    }
}

TEST_CASE("momentum is conserved and the normal relative speed becomes -C times itself", "[resolve]") {
    const std::array<double, 4> inverseMasses{1.0, 0.25, 3.0, 0.01};
    const std::array<double, 3> bouncinesses{0.0, 0.6, 1.0};
    int resolved = 0;
    for (int k = 0; k < 16; ++k) {
        const Vec2 n = Vec2::fromAngle(0.37 * k + 0.1);
        const Vec2 v1 = Vec2{std::cos(1.3 * k), std::sin(0.7 * k)} * 5.0 - n * 3.0; // always approaching
        const Vec2 v2 = Vec2{std::sin(2.1 * k), std::cos(0.4 * k)} * 2.0;
        for (const double im1 : inverseMasses)
            for (const double im2 : inverseMasses)
                for (const double c : bouncinesses) {
                    Vec2 a = v1, b = v2;
                    const double approach = resolveImpact(a, im1, b, im2, n, c);
                    if (approach <= 0.0) continue;
                    ++resolved;
                    CHECK(approxEqual(momentum(a, im1, b, im2), momentum(v1, im1, v2, im2), 1e-12));
                    CHECK(approachSpeed(a, b, n) == Approx(-c * approach).margin(1e-12));
                    CHECK((a - v1).cross(n) == Approx(0.0).margin(1e-12)); // changes only along n
                }
    }
    CHECK(resolved > 300);
}

TEST_CASE("walls have infinite mass: u is the wall's normal velocity", "[resolve]") {
    const Vec2 up{0, 1};
    SECTION("a still floor: v' = -C v along the normal (lecture 3)") {
        Vec2 ball{1, -5}, wall{0, 0};
        resolveImpact(ball, 1.0, wall, 0.0, up, 0.8);
        CHECK(approxEqual(ball, {1, 4}));
        CHECK(wall == Vec2{0, 0});
    }
    SECTION("a perfectly elastic floor reflects exactly, bit for bit") {
        Vec2 ball{0.25, -13.7}, wall{0, 0};
        resolveImpact(ball, 1.0, wall, 0.0, up, 1.0);
        CHECK(ball == Vec2{0.25, 13.7});
    }
    SECTION("a floor rising at 2 m/s: v' = 2 - 0.8 (-5 - 2) = 7.6") {
        Vec2 ball{1, -5}, wall{0, 2};
        resolveImpact(ball, 1.0, wall, 0.0, up, 0.8);
        CHECK(ball.y == Approx(7.6));
        CHECK(ball.x == 1.0);
        CHECK(wall == Vec2{0, 2});
    }
    SECTION("the infinite mass may be either body") {
        Vec2 wall{0, 0}, ball{1, 5};
        resolveImpact(wall, 0.0, ball, 1.0, up, 1.0); // n from the ball (body 2) towards the wall (body 1)
        CHECK(approxEqual(ball, {1, -5}));
        CHECK(wall == Vec2{0, 0});
    }
    SECTION("two walls: nothing gives") {
        Vec2 a{0, -1}, b{0, 1};
        resolveImpact(a, 0.0, b, 0.0, up, 1.0);
        CHECK(a == Vec2{0, -1});
        CHECK(b == Vec2{0, 1});
    }
}

TEST_CASE("separating bodies are left alone (lecture 3 tip)", "[resolve]") {
    Vec2 v1{0, 3}, v2{0, 0};
    CHECK(resolveImpact(v1, 1.0, v2, 1.0, {0, 1}, 1.0) == -3.0);
    CHECK(v1 == Vec2{0, 3});
    CHECK(v2 == Vec2{0, 0});
    CHECK(pairBounciness(Material{0.5, 0.0}, Material{0.8, 0.0}) == 0.4);
}

TEST_CASE("position reset: pushed apart by the overlap, split by inverse mass", "[resolve]") {
    Vec2 p1{0, 0}, p2{1, 0};
    pushApart(p1, 1.0, p2, 3.0, {-1, 0}, 0.4); // the lighter body 2 moves three times as far
    CHECK(approxEqual(p1, {-0.1, 0}));
    CHECK(approxEqual(p2, {1.3, 0}));
    Vec2 ball{0, 0.3}, wall{0, 0};
    pushApart(ball, 1.0, wall, 0.0, {0, 1}, 0.2);
    CHECK(approxEqual(ball, {0, 0.5}));
    CHECK(wall == Vec2{0, 0});
}

TEST_CASE("segment overlap on a chosen side: a sunk ball goes back where it came from", "[resolve]") {
    Segment floor;
    floor.a = {0, 0};
    floor.b = {4, 0};
    CHECK(approxEqual(segmentSide(floor, {2, 3}), {0, 1}));
    CHECK(approxEqual(segmentSide(floor, {2, -3}), {0, -1}));
    // The centre sank 0.2 below the line; the step started above it.
    const auto sunk = circleSegmentOverlapOnSide({2, -0.2}, 0.5, floor, {0, 1});
    REQUIRE(sunk);
    CHECK(approxEqual(sunk->overlap.normal, {0, 1}));
    CHECK(sunk->overlap.depth == Approx(0.7));
    CHECK_FALSE(sunk->lineCap);
    // Wholly below: it has tunnelled, nothing to push.
    CHECK_FALSE(circleSegmentOverlapOnSide({2, -0.5}, 0.5, floor, {0, 1}));
    // Past the end: the line cap, whatever the side.
    const auto cap = circleSegmentOverlapOnSide({4.3, 0.4}, 0.6, floor, {0, -1});
    REQUIRE(cap);
    CHECK(cap->lineCap);
    CHECK(approxEqual(cap->overlap.normal, {0.6, 0.8}));
    CHECK(cap->overlap.depth == Approx(0.1));
}
