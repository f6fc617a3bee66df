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

TEST_CASE("rayCast: a turned box is entered where the ray first lies inside all four of its faces, and a "
          "capsule body as a capsule",
          "[raycast]") {
    // Against an independent form: in the box's own frame the box is axis-aligned, and the ray enters
    // at the largest of the slab entries max(t_x, t_y) (the classic slab test), hitting the face of
    // that slab. Random boxes, turns, origins and directions; a ray from inside a box does not meet it.
    std::mt19937_64 rng(26);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int hits = 0, misses = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const Vec2 centre{4.0 * unit(rng) - 2.0, 4.0 * unit(rng) - 2.0};
        const Vec2 half{0.1 + unit(rng), 0.1 + unit(rng)};
        const double angle = 2.0 * std::numbers::pi * unit(rng);
        World world;
        RigidBodyDef d;
        d.shape = BodyShape::box;
        d.position = centre;
        d.halfExtents = half;
        d.angle = angle;
        d.motion = unit(rng) < 0.5 ? Motion::fixed : Motion::dynamic;
        world.addBody(d);
        const Vec2 origin{10.0 * unit(rng) - 5.0, 10.0 * unit(rng) - 5.0};
        // Half the rays aim near the box, so that both hits and misses are many.
        const Vec2 aim = centre + Vec2{2.0 * unit(rng) - 1.0, 2.0 * unit(rng) - 1.0} - origin;
        const Vec2 direction = trial % 2 == 0 ? Vec2::fromAngle(2.0 * std::numbers::pi * unit(rng))
                                              : aim / aim.length();
        // The ray in the box's frame: rotate by -angle about the centre.
        const double c = std::cos(angle), s = std::sin(angle);
        const auto local = [&](Vec2 v) { return Vec2{c * v.x + s * v.y, -s * v.x + c * v.y}; };
        const Vec2 o = local(origin - centre), dir = local(direction);
        double enter = -1e300, leave = 1e300;
        bool parallelMiss = false;
        for (int axis = 0; axis < 2; ++axis) {
            const double p = axis == 0 ? o.x : o.y, v = axis == 0 ? dir.x : dir.y, h = axis == 0 ? half.x : half.y;
            if (std::abs(v) < 1e-12) {
                parallelMiss = parallelMiss || std::abs(p) > h;
                continue;
            }
            const double t0 = (-h - p) / v, t1 = (h - p) / v;
            enter = std::max(enter, std::min(t0, t1));
            leave = std::min(leave, std::max(t0, t1));
        }
        const bool inside = std::abs(o.x) <= half.x && std::abs(o.y) <= half.y;
        const bool expected = !parallelMiss && !inside && enter >= 0.0 && enter <= leave && enter <= 100.0;
        const auto hit = rayCast(world, origin, direction, 100.0);
        INFO("trial " << trial << ": expected " << expected << " at " << enter);
        REQUIRE(hit.has_value() == expected);
        if (!hit) {
            ++misses;
            continue;
        }
        ++hits;
        CHECK(hit->shape == RayHit::Shape::body);
        CHECK(hit->slot == 0);
        CHECK(hit->distance == Approx(enter).margin(1e-9));
        // The normal is a face's: unit, against the ray, and the point lies on that face's line.
        CHECK(hit->normal.length() == Approx(1.0).margin(1e-12));
        CHECK(hit->normal.dot(direction) < 0.0);
        const Vec2 n = local(hit->normal);
        const double reach = std::abs(n.x) > 0.5 ? half.x : half.y;
        CHECK(local(hit->point - centre).dot(n) == Approx(reach).margin(1e-9));
    }
    CHECK(hits > 200);
    CHECK(misses > 200);

    // A capsule body is met as a capsule segment is: square to its side, r before its core line.
    World world;
    RigidBodyDef capsule;
    capsule.shape = BodyShape::capsule;
    capsule.position = {3.0, 1.0};
    capsule.halfExtents = {1.0, 0.2};       // core 2 m long, radius 0.2 m
    capsule.angle = std::numbers::pi / 2.0; // standing up: its core runs from y = 0 to y = 2
    world.addBody(capsule);
    const auto side = rayCast(world, {0.0, 1.5}, {1.0, 0.0}, 100.0);
    REQUIRE(side);
    CHECK(side->shape == RayHit::Shape::body);
    CHECK(side->distance == Approx(2.8).margin(1e-12));
    const auto cap = rayCast(world, {3.0, 5.0}, {0.0, -1.0}, 100.0);
    REQUIRE(cap);
    CHECK(cap->distance == Approx(5.0 - 2.0 - 0.2).margin(1e-12));
    CHECK_FALSE(rayCast(world, {3.0, 1.0}, {1.0, 0.0}, 100.0)); // from inside
}
