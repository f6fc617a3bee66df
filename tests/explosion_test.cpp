// Explosion force: exactly the dynamic circles inside the radius are pushed, radially, by an impulse that
// falls off with distance, and Delta v = J / m makes heavier bodies move less for the same momentum.
#include "rube/physics/explosion.hpp"
#include "rube/physics/world.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace rube;

namespace {

Circle circleAt(Vec2 position, double mass = 1.0, Motion motion = Motion::dynamic) {
    Circle c;
    c.position = position;
    c.motion = motion;
    c.inverseMass = motion == Motion::dynamic ? 1.0 / mass : 0.0;
    return c;
}

Explosion blast(Falloff falloff = Falloff::linear) {
    Explosion e;
    e.centre = {2, 3};
    e.radius = 4.0;
    e.strength = 10.0;
    e.falloff = falloff;
    return e;
}

} // namespace

TEST_CASE("explosion: exactly the bodies within the radius are pushed", "[explosion]") {
    const Explosion e = blast();
    const Vec2 c = e.centre;
    std::vector<Circle> circles{
        circleAt(c + Vec2{1, 0}),                             // 0: well inside
        circleAt(c + Vec2{0, 4.0 * 0.999}),                   // 1: just inside
        circleAt(c + Vec2{-4.0 * 1.001, 0}),                  // 2: just outside
        circleAt(c + Vec2{2.4, 3.2}),                         // 3: exactly at the edge, |(2.4, 3.2)| = 4
        circleAt(c + Vec2{10, -10}),                          // 4: far away
        circleAt(c + Vec2{0.5, 0.5}, 1.0, Motion::kinematic), // 5: infinite mass
        circleAt(c + Vec2{-0.5, 0}, 1.0, Motion::fixed),      // 6: infinite mass
    };
    const std::vector<int> affected = applyExplosion(circles, e);
    CHECK(affected == std::vector<int>{0, 1});

    // Linear fall-off: J = 10 (1 - 1 / 4) = 7.5 at 1 m, and 10 * 0.001 = 0.01 just inside the edge.
    CHECK(approxEqual(circles[0].velocity, {7.5, 0}, 1e-15));
    CHECK(circles[1].velocity.y == Approx(0.01).epsilon(1e-9));
    CHECK(circles[1].velocity.x == 0.0);
    CHECK(circles[1].velocity.y < 0.011);
    for (std::size_t i = 2; i < circles.size(); ++i) CHECK(circles[i].velocity == Vec2{});
}

TEST_CASE("explosion: every fall-off is full at the centre, monotonic, and zero at the edge", "[explosion]") {
    for (const Falloff falloff : {Falloff::linear, Falloff::inverseSquareClamped, Falloff::constant}) {
        const Explosion e = blast(falloff);
        CHECK(explosionImpulse(e, 0.0) == 10.0);
        double previous = explosionImpulse(e, 0.0);
        for (int i = 1; i <= 400; ++i) {
            const double j = explosionImpulse(e, 0.01 * i);
            CHECK(j <= previous);
            CHECK(j >= 0.0);
            previous = j;
        }
        CHECK(explosionImpulse(e, 4.0) == 0.0);
        CHECK(explosionImpulse(e, 5.0) == 0.0);
    }
    // Linear halves at mid-radius; inverse square is full in the core (0.4 m) and 1 / d^2 beyond:
    // (0.4 / 0.8)^2 = 1 / 4 at 0.8 m and 1 / 25 at 2 m; constant stays full.
    CHECK(explosionImpulse(blast(), 2.0) == Approx(5.0));
    CHECK(explosionImpulse(blast(Falloff::inverseSquareClamped), 0.3) == 10.0);
    CHECK(explosionImpulse(blast(Falloff::inverseSquareClamped), 0.8) == Approx(2.5));
    CHECK(explosionImpulse(blast(Falloff::inverseSquareClamped), 2.0) == Approx(0.4));
    CHECK(explosionImpulse(blast(Falloff::constant), 3.99) == 10.0);
}

TEST_CASE("explosion: the change of momentum points away from the centre", "[explosion]") {
    const Explosion e = blast();
    std::vector<Circle> circles;
    for (int k = 0; k < 12; ++k) {
        Circle c = circleAt(e.centre + Vec2::fromAngle(0.5 * k) * (0.3 * (k + 1)), 0.5 + 0.25 * k);
        c.velocity = {1.0, -2.0}; // the impulse adds to what the body already had
        circles.push_back(c);
    }
    const std::vector<Circle> before = circles;
    REQUIRE(applyExplosion(circles, e).size() == 12);
    for (std::size_t k = 0; k < circles.size(); ++k) {
        const Vec2 radial = (before[k].position - e.centre).normalized();
        const Vec2 momentumChange = (circles[k].velocity - before[k].velocity) / circles[k].inverseMass;
        CHECK(std::fabs(momentumChange.cross(radial)) < 1e-12);
        CHECK(momentumChange.dot(radial) > 0.0);
        // |Delta p| = J at that distance, whatever the mass.
        CHECK(momentumChange.length() ==
              Approx(explosionImpulse(e, (before[k].position - e.centre).length())).epsilon(1e-12));
    }
}

TEST_CASE("explosion: heavier bodies get a smaller kick, the same momentum", "[explosion]") {
    const Explosion e = blast(Falloff::inverseSquareClamped);
    std::vector<Circle> circles{circleAt(e.centre + Vec2{0, -1}, 1.0), circleAt(e.centre + Vec2{0, 1}, 4.0)};
    applyExplosion(circles, e);
    // Delta v = J / m: a quarter of the speed for four times the mass, equal and opposite momenta.
    CHECK(circles[0].velocity.length() == Approx(4.0 * circles[1].velocity.length()));
    CHECK(circles[1].velocity.length() < circles[0].velocity.length());
    CHECK(approxEqual(circles[0].velocity * 1.0 + circles[1].velocity * 4.0, {}, 1e-15));
}

TEST_CASE("explosion: a body at the very centre is pushed up, and a world works the same", "[explosion]") {
    const Explosion e = blast();
    std::vector<Circle> circles{circleAt(e.centre, 2.0)};
    CHECK(applyExplosion(circles, e) == std::vector<int>{0});
    CHECK(circles[0].velocity == Vec2{0, 5.0}); // J = 10, m = 2, along +y

    World world;
    CircleDef ball;
    ball.position = e.centre + Vec2{-2, 0};
    world.addCircle(ball);
    ball.position = e.centre + Vec2{0, 6};
    world.addCircle(ball);
    world.addSegment(SegmentDef{}); // segments never move
    CHECK(applyExplosion(world, e).circles == std::vector<CircleId>{world.circleId(0)});
    CHECK(approxEqual(world.circles()[0].velocity, {-5.0, 0}, 1e-15));
    CHECK(world.circles()[1].velocity == Vec2{});
    CHECK(world.segments()[0].a == Vec2{});
}

TEST_CASE("explosion: boxes and capsules in the blast take the same impulse through their centre, no spin",
          "[explosion]") {
    // The bomb part says it pushes every body near it; crates, planks and dominoes were left standing.
    for (const Falloff falloff : {Falloff::linear, Falloff::inverseSquareClamped, Falloff::constant}) {
        const Explosion e{.centre = {1.0, 2.0}, .radius = 3.0, .strength = 4.0, .falloff = falloff};
        World world;
        const Vec2 offsets[] = {{1.0, 0.0}, {-0.5, 1.5}, {0.0, -2.9}, {2.5, 2.5}}; // the last is outside
        const double masses[] = {0.5, 2.0, 8.0, 1.0};
        std::vector<BodyId> ids;
        for (int k = 0; k < 4; ++k) {
            RigidBodyDef d;
            d.shape = k % 2 == 0 ? BodyShape::box : BodyShape::capsule;
            d.position = e.centre + offsets[k];
            d.halfExtents = {0.4, 0.1};
            d.mass = masses[k];
            d.angle = 0.3 * k;
            d.velocity = {0.25, -0.5};
            ids.push_back(world.addBody(d));
        }
        RigidBodyDef fixed;
        fixed.position = e.centre + Vec2{0.5, 0.0};
        fixed.motion = Motion::fixed;
        world.addBody(fixed);
        const ExplosionPushed pushed = applyExplosion(world, e);
        CHECK(pushed.circles.empty());
        CHECK(pushed.bodies == std::vector<BodyId>{ids[0], ids[1], ids[2]});
        for (int k = 0; k < 4; ++k) {
            const RigidBody& b = world.bodies()[static_cast<std::size_t>(world.slot(ids[static_cast<std::size_t>(k)]))];
            const double d = offsets[k].length();
            // Delta p = J along the radius: m (v - v0) = strength falloff(d) (p - c) / d.
            const Vec2 expected = offsets[k] / d * (explosionImpulse(e, d) / masses[k]);
            INFO("body " << k << ", " << static_cast<int>(falloff) << ": v " << b.velocity.x << ", " << b.velocity.y);
            CHECK(approxEqual(b.velocity - Vec2{0.25, -0.5}, expected, 1e-14));
            CHECK(b.angularVelocity == 0.0);
        }
        CHECK(world.bodies()[4].velocity == Vec2{});
    }
}
