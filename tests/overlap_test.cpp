// Discrete detection (lecture 5): circle-circle, circle-point, circle-segment with line caps.
#include "rube/physics/collision.hpp"

#include <catch2/catch.hpp>

using namespace rube;

TEST_CASE("circles overlap when the distance is less than the sum of radii", "[overlap]") {
    CHECK_FALSE(circleCircleOverlap({0, 0}, 1, {3, 0}, 1));
    CHECK_FALSE(circleCircleOverlap({0, 0}, 1, {2, 0}, 1)); // touching is not overlapping
    const auto o = circleCircleOverlap({0, 0}, 1, {1.5, 0}, 1);
    REQUIRE(o);
    CHECK(o->depth == Approx(0.5));
    CHECK(approxEqual(o->normal, {-1, 0})); // from the other circle towards this one
    CHECK(approxEqual(o->point, {0.5, 0}));
}

TEST_CASE("coincident centres still give a unit normal", "[overlap]") {
    const auto o = circleCircleOverlap({2, 2}, 1, {2, 2}, 1);
    REQUIRE(o);
    CHECK(o->normal.length() == Approx(1.0));
    CHECK(o->depth == Approx(2.0));
}

TEST_CASE("a circle overlaps a point closer than its radius", "[overlap]") {
    CHECK(circlePointOverlap({0, 0}, 1, {0.5, 0.5}));
    CHECK_FALSE(circlePointOverlap({0, 0}, 1, {1, 1}));
}

TEST_CASE("circle against a segment: both faces and both caps", "[overlap]") {
    const Vec2 a{0, 0}, b{4, 0};
    SECTION("above the face") {
        const auto o = circleSegmentOverlap({2, 0.5}, 1, a, b);
        REQUIRE(o);
        CHECK(approxEqual(o->normal, {0, 1}));
        CHECK(o->depth == Approx(0.5));
    }
    SECTION("below the face: the segment is two-sided") {
        const auto o = circleSegmentOverlap({2, -0.25}, 1, a, b);
        REQUIRE(o);
        CHECK(approxEqual(o->normal, {0, -1}));
        CHECK(o->depth == Approx(0.75));
    }
    SECTION("past the end: the line cap, a zero-radius circle") {
        const auto o = circleSegmentOverlap({4.6, 0.8}, 1.01, a, b);
        REQUIRE(o);
        CHECK(approxEqual(o->normal, Vec2{0.6, 0.8}));
        CHECK(approxEqual(o->point, b));
        CHECK_FALSE(circleSegmentOverlap({4.6, 0.8}, 0.99, a, b));
    }
    SECTION("a thick segment adds its radius") {
        CHECK_FALSE(circleSegmentOverlap({2, 1.5}, 1, a, b));
        CHECK(circleSegmentOverlap({2, 1.5}, 1, a, b, 0.6));
    }
}

TEST_CASE("closest point on a segment clamps to the ends", "[overlap]") {
    CHECK(approxEqual(closestPointOnSegment({-3, 1}, {0, 0}, {4, 0}), {0, 0}));
    CHECK(approxEqual(closestPointOnSegment({2, 1}, {0, 0}, {4, 0}), {2, 0}));
    CHECK(approxEqual(closestPointOnSegment({9, 1}, {0, 0}, {4, 0}), {4, 0}));
    CHECK(approxEqual(closestPointOnSegment({9, 1}, {1, 1}, {1, 1}), {1, 1})); // degenerate segment
}
