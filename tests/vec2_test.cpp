// Vec2: every operation, with the zero vector and very large and very small values.
#include "rube/physics/vec2.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>

using namespace rube;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kHuge = 1e300;
constexpr double kTiny = 1e-300;
} // namespace

TEST_CASE("Vec2 arithmetic", "[vec2]") {
    constexpr Vec2 a{1, 2}, b{3, -4};
    STATIC_REQUIRE(a + b == Vec2{4, -2});
    STATIC_REQUIRE(a - b == Vec2{-2, 6});
    STATIC_REQUIRE(-a == Vec2{-1, -2});
    STATIC_REQUIRE(a * 2.0 == Vec2{2, 4});
    STATIC_REQUIRE(2.0 * a == Vec2{2, 4});
    STATIC_REQUIRE(b / 2.0 == Vec2{1.5, -2});
    Vec2 c = a;
    c += b;
    CHECK(c == Vec2{4, -2});
    c -= b;
    CHECK(c == a);
    c *= 3;
    CHECK(c == Vec2{3, 6});
    c /= 3;
    CHECK(c == a);
    CHECK(Vec2{} == Vec2{0, 0});
}

TEST_CASE("Vec2 dot and cross", "[vec2]") {
    STATIC_REQUIRE(Vec2{1, 2}.dot(Vec2{3, 4}) == 11);
    STATIC_REQUIRE(Vec2{1, 0}.dot(Vec2{0, 1}) == 0);   // perpendicular
    STATIC_REQUIRE(Vec2{1, 0}.cross(Vec2{0, 1}) == 1); // counter-clockwise is positive
    STATIC_REQUIRE(Vec2{0, 1}.cross(Vec2{1, 0}) == -1);
    STATIC_REQUIRE(Vec2{2, 3}.cross(Vec2{4, 6}) == 0); // parallel
    CHECK(Vec2{}.dot(Vec2{5, 5}) == 0);
    CHECK(Vec2{}.cross(Vec2{5, 5}) == 0);
}

TEST_CASE("Vec2 length and squared length", "[vec2]") {
    CHECK(Vec2{3, 4}.length() == 5);
    CHECK(Vec2{3, 4}.lengthSquared() == 25);
    CHECK(Vec2{}.length() == 0);
    SECTION("huge components do not overflow") {
        CHECK(Vec2{3 * kHuge, 4 * kHuge / 1e10}.length() == Approx(3 * kHuge));
        CHECK(std::isfinite(Vec2{kHuge, kHuge}.length()));
        CHECK(Vec2{kHuge, kHuge}.length() == Approx(kHuge * std::sqrt(2.0)));
    }
    SECTION("tiny components do not underflow to zero") {
        CHECK(Vec2{3 * kTiny, 4 * kTiny}.length() == Approx(5 * kTiny));
        CHECK(Vec2{3 * kTiny, 4 * kTiny}.length() > 0);
    }
}

TEST_CASE("Vec2 safe normalize", "[vec2]") {
    CHECK(approxEqual(Vec2{3, 4}.normalized(), {0.6, 0.8}));
    CHECK(Vec2{}.normalized() == Vec2{}); // zero stays zero, never NaN
    CHECK(Vec2{kHuge, kHuge}.normalized().length() == Approx(1.0));
    CHECK(Vec2{kTiny, -kTiny}.normalized().length() == Approx(1.0));
    CHECK(approxEqual(Vec2{-kTiny, 0}.normalized(), {-1, 0}));
}

TEST_CASE("Vec2 perpendicular and normal", "[vec2]") {
    STATIC_REQUIRE(Vec2{1, 2}.perpendicular() == Vec2{-2, 1});
    CHECK(Vec2{1, 2}.perpendicular().dot(Vec2{1, 2}) == 0);
    CHECK(approxEqual(Vec2{4, 0}.normal(), {0, 1})); // left-hand normal of a line going right
    CHECK(approxEqual(Vec2{0, -2}.normal(), {1, 0}));
    CHECK(Vec2{}.normal() == Vec2{});
}

TEST_CASE("Vec2 rotate and angle", "[vec2]") {
    CHECK(approxEqual(Vec2{1, 0}.rotated(kPi / 2), {0, 1}));
    CHECK(approxEqual(Vec2{1, 1}.rotated(kPi), {-1, -1}));
    CHECK(approxEqual(Vec2{2, 0}.rotated(-kPi / 2), {0, -2}));
    CHECK(approxEqual(Vec2{1, 0}.rotated(2 * kPi), {1, 0}));
    CHECK(Vec2{}.rotated(1.0) == Vec2{});
    CHECK(approxEqual(Vec2{2, 1}.rotatedAround({1, 1}, kPi / 2), {1, 2}));
    CHECK(Vec2{0, 1}.angle() == Approx(kPi / 2));
    CHECK(Vec2{-1, 0}.angle() == Approx(kPi));
    CHECK(Vec2{1, -1}.angle() == Approx(-kPi / 4));
    CHECK(Vec2{}.angle() == 0);
    CHECK(approxEqual(Vec2::fromAngle(kPi / 3), {0.5, std::sqrt(3.0) / 2}));
    CHECK(Vec2::fromAngle(0.7).angle() == Approx(0.7));
    CHECK(Vec2{kHuge, kHuge}.angle() == Approx(kPi / 4));
}

TEST_CASE("Vec2 scalar and vector projection", "[vec2]") {
    CHECK(Vec2{3, 4}.scalarProjection({1, 0}) == 3);
    CHECK(Vec2{3, 4}.scalarProjection({10, 0}) == 3); // onto is normalized: not |onto| times too big
    CHECK(Vec2{3, 4}.scalarProjection({0, -2}) == -4);
    CHECK(Vec2{3, 4}.scalarProjection({}) == 0);
    CHECK(approxEqual(Vec2{3, 4}.projectedOnto({2, 0}), {3, 0}));
    CHECK(Vec2{3, 4}.projectedOnto({}) == Vec2{});
}

TEST_CASE("Vec2 reflect with bounciness", "[vec2]") {
    const Vec2 up{0, 1};
    CHECK(approxEqual(Vec2{2, -3}.reflected(up), {2, 3}));        // C = 1: mirror
    CHECK(approxEqual(Vec2{2, -3}.reflected(up, 0.5), {2, 1.5})); // C = 0.5: half the normal speed
    CHECK(approxEqual(Vec2{2, -3}.reflected(up, 0.0), {2, 0}));   // C = 0: slides along
    const Vec2 n = Vec2{1, 1}.normalized();
    const Vec2 v{-3, -1};
    CHECK(v.reflected(n).length() == Approx(v.length())); // elastic keeps the speed
    CHECK(Vec2{}.reflected(up) == Vec2{});
}

TEST_CASE("lerp, distance and approximate equality", "[vec2]") {
    STATIC_REQUIRE(lerp(Vec2{0, 0}, Vec2{10, 20}, 0.25) == Vec2{2.5, 5});
    STATIC_REQUIRE(lerp(Vec2{1, 1}, Vec2{3, 3}, 0.0) == Vec2{1, 1});
    STATIC_REQUIRE(lerp(Vec2{1, 1}, Vec2{3, 3}, 1.0) == Vec2{3, 3});
    CHECK(Vec2{1, 1}.distance({4, 5}) == 5);
    CHECK(approxEqual({1, 1}, {1 + 1e-12, 1}));
    CHECK_FALSE(approxEqual({1, 1}, {1 + 1e-6, 1}));
    CHECK(approxEqual({1e12, 0}, {1e12 + 1, 0}));      // relative for large values
    CHECK_FALSE(approxEqual({0, 0}, {0, 1e-3}, 1e-4)); // absolute near zero
    CHECK(isFinite({1, 2}));
    CHECK_FALSE(isFinite({std::numeric_limits<double>::quiet_NaN(), 0}));
    CHECK_FALSE(isFinite({0, std::numeric_limits<double>::infinity()}));
}
