// Ray casts (engine/physics ray_cast.hpp): the first surface a ray enters, against closed forms over
// random circles and capsules: a ray at distance h from a circle's centre enters it sqrt(r^2 - h^2)
// before its closest approach; a ray square to a capsule's side meets it r before the centre line;
// the nearest of several is the one reported; a ray that starts inside or on a shape leaves it unmet.
#include "rube/physics/ray_cast.hpp"
#include "rube/physics/world.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

using namespace rube;

namespace {

CircleDef fixedCircle(Vec2 at, double r) {
    CircleDef c;
    c.position = at;
    c.radius = r;
    c.motion = Motion::fixed;
    return c;
}

} // namespace

TEST_CASE("rayCast: a ray enters a circle sqrt(r^2 - h^2) before its closest approach to the centre", "[raycast]") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 500; ++i) {
        const Vec2 centre{20.0 * unit(rng) - 10.0, 20.0 * unit(rng) - 10.0};
        const double r = 0.1 + 2.0 * unit(rng);
        const double along = 3.0 + 10.0 * unit(rng);        // how far the closest approach is from the origin
        const double h = (2.0 * unit(rng) - 1.0) * 1.2 * r; // how far the ray passes from the centre
        const Vec2 d = Vec2::fromAngle(2.0 * std::numbers::pi * unit(rng));
        const Vec2 origin = centre - d * along + d.perpendicular() * h;
        World world;
        world.addCircle(fixedCircle(centre, r));
        const auto hit = rayCast(world, origin, d, 100.0);
        CAPTURE(i, r, h, along);
        if (std::abs(h) >= r) {
            CHECK_FALSE(hit);
            continue;
        }
        REQUIRE(hit);
        CHECK(hit->shape == RayHit::Shape::circle);
        CHECK(hit->distance == Approx(along - std::sqrt(r * r - h * h)).margin(1e-9));
        CHECK(hit->point.distance(centre) == Approx(r).margin(1e-9));
        CHECK(hit->normal.dot(d) < 0.0); // it faces the ray
        CHECK(hit->normal.length() == Approx(1.0).margin(1e-12));
        // Beyond the reach: nothing.
        CHECK_FALSE(rayCast(world, origin, d, hit->distance - 1e-6));
        // From the point it entered, onwards: it does not meet the circle again.
        CHECK_FALSE(rayCast(world, hit->point, d.reflected(hit->normal), 100.0));
    }
}

TEST_CASE("rayCast: a capsule is met r before its centre line on its sides, and on its round caps past its ends",
          "[raycast]") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 500; ++i) {
        const Vec2 a{10.0 * unit(rng) - 5.0, 10.0 * unit(rng) - 5.0};
        const Vec2 axis = Vec2::fromAngle(2.0 * std::numbers::pi * unit(rng));
        const double length = 0.5 + 3.0 * unit(rng), r = 0.3 * unit(rng);
        const Vec2 b = a + axis * length;
        const double u = 1.4 * unit(rng) - 0.2;           // where along it the ray aims (past the ends too)
        const double side = unit(rng) < 0.5 ? 1.0 : -1.0; // which side it comes from
        const double away = 1.0 + 5.0 * unit(rng);
        const Vec2 n = axis.perpendicular() * side;
        const Vec2 origin = a + axis * (u * length) + n * away;
        World world;
        world.addSegment(SegmentDef{a, b, r, Material{}, -1});
        const auto hit = rayCast(world, origin, n * -1.0, 100.0);
        CAPTURE(i, u, r, away);
        // Past an end by e, the ray meets the cap sqrt(r^2 - e^2) above the centre line, or misses it.
        const double e = u < 0.0 ? -u * length : u > 1.0 ? (u - 1.0) * length : 0.0;
        if (e >= r && e > 0.0) {
            CHECK_FALSE(hit);
            continue;
        }
        REQUIRE(hit);
        CHECK(hit->shape == RayHit::Shape::segment);
        CHECK(hit->slot == 0);
        CHECK(hit->distance == Approx(away - std::sqrt(r * r - e * e)).margin(1e-9));
        if (e == 0.0) CHECK(hit->normal.dot(n) == Approx(1.0).margin(1e-12));
        // The reflection leaves it: not met again.
        CHECK_FALSE(rayCast(world, hit->point, (n * -1.0).reflected(hit->normal), 100.0));
    }
}

TEST_CASE("rayCast: the nearest of several shapes is reported, and a ray from inside a shape passes out of it",
          "[raycast]") {
    World world;
    world.addCircle(fixedCircle({5.0, 0.0}, 0.5));
    world.addCircle(fixedCircle({3.0, 0.0}, 0.25));
    world.addSegment(SegmentDef{{8.0, -1.0}, {8.0, 1.0}, 0.1, Material{}, -1});
    const auto hit = rayCast(world, {0.0, 0.0}, {1.0, 0.0}, 100.0);
    REQUIRE(hit);
    CHECK(hit->slot == 1);
    CHECK(hit->distance == Approx(2.75).margin(1e-12));
    // From inside the small circle: it meets the large one next.
    const auto next = rayCast(world, {3.0, 0.0}, {1.0, 0.0}, 100.0);
    REQUIRE(next);
    CHECK(next->slot == 0);
    CHECK(next->distance == Approx(1.5).margin(1e-12));
    // Past both circles: the segment's side, 0.1 before its line.
    const auto wall = rayCast(world, {6.0, 0.0}, {1.0, 0.0}, 100.0);
    REQUIRE(wall);
    CHECK(wall->shape == RayHit::Shape::segment);
    CHECK(wall->distance == Approx(1.9).margin(1e-12));
    CHECK_FALSE(rayCast(world, {6.0, 0.0}, {1.0, 0.0}, 1.8));
}
