// The rigid narrowphase (rigid_manifold.hpp) against geometry derived by hand: a box resting flat or
// tilted on a wide box, overhanging its edge; a capsule on a box; a box on a line segment; a circle
// on a box's face and against its corner. Over ranges of offsets, angles and gaps (overlaps too),
// every manifold point must sit midway between the two surfaces at the gap the geometry gives,
// along the normal from shape A towards shape B, and points farther apart than the speculative
// distance must be left out.
#include "rigid_manifold.hpp" // internal: tests may reach inside, users may not

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace rube;

namespace {

constexpr double kTolerance = 1e-9;
constexpr double kSpeculative = 0.02;

RigidBody box(Vec2 half) {
    RigidBody b;
    b.shape = BodyShape::box;
    b.halfExtents = half;
    return b;
}

RigidBody capsule(double halfLength, double radius) {
    RigidBody b;
    b.shape = BodyShape::capsule;
    b.halfExtents = {halfLength, radius};
    return b;
}

/// What a point should be: where it is, and the gap it reports.
struct Expected {
    Vec2 point;
    double separation;
};

/// The expected points that lie within the speculative distance, in any order, match the manifold's.
void checkPoints(const Manifold& m, Vec2 normal, std::vector<Expected> expected) {
    expected.erase(
        std::remove_if(expected.begin(), expected.end(), [](const Expected& e) { return e.separation > kSpeculative; }),
        expected.end());
    REQUIRE(m.count == static_cast<int>(expected.size()));
    if (m.count == 0) return;
    CHECK(m.normal.x == Approx(normal.x).margin(kTolerance));
    CHECK(m.normal.y == Approx(normal.y).margin(kTolerance));
    for (const Expected& e : expected) {
        const auto near = [&](const ManifoldPoint& p) { return (p.point - e.point).length() < 1e-7; };
        const ManifoldPoint* match = near(m.points[0]) ? &m.points[0]
                                                       : (m.count > 1 && near(m.points[1]) ? &m.points[1] : nullptr);
        INFO("expected point (" << e.point.x << ", " << e.point.y << ") at gap " << e.separation << "; got ("
                                << m.points[0].point.x << ", " << m.points[0].point.y << ")"
                                << (m.count > 1 ? " and another" : ""));
        REQUIRE(match != nullptr);
        CHECK(match->separation == Approx(e.separation).margin(kTolerance));
    }
    if (m.count == 2) CHECK(m.points[0].id != m.points[1].id);
}

/// Corner k of a box of half extents `half` at `centre` turned by `angle`, in the order of makeRoundedPolygon.
Vec2 corner(Vec2 centre, Vec2 half, double angle, int k) {
    const Vec2 local[4] = {{-half.x, -half.y}, {half.x, -half.y}, {half.x, half.y}, {-half.x, half.y}};
    return centre + local[k].rotated(angle);
}

} // namespace

TEST_CASE("a box on a wide box touches at both bottom corners, at any offset and tilt under 40 degrees",
          "[rigid][manifold]") {
    // Ground: 10 x 1 m, its top face at y = 0.5. The upper box's bottom edge runs from corner 0 to corner 1;
    // a corner at height y is y - 0.5 from the face, and its point is midway: (x, (y + 0.5) / 2).
    const Vec2 groundHalf{5.0, 0.5};
    const RoundedPolygon ground = makeRoundedPolygon(box(groundHalf), {0.0, 0.0}, 0.0);
    int withTwo = 0, withOne = 0, withNone = 0;
    for (const Vec2 half : {Vec2{0.5, 0.5}, Vec2{1.0, 0.1}, Vec2{0.05, 0.8}})
        for (double degrees = -38.0; degrees <= 38.0; degrees += 4.75)
            for (double x = -3.0; x <= 3.0; x += 1.5)
                for (const double lowestGap : {-0.01, -0.001, 0.0, 0.003, 0.015, 0.05}) {
                    const double angle = degrees * 3.141592653589793 / 180.0;
                    // Lift the box so its lowest corner stands lowestGap above the face.
                    const double lowest = std::min(corner({0.0, 0.0}, half, angle, 0).y,
                                                   corner({0.0, 0.0}, half, angle, 1).y);
                    const Vec2 centre{x, 0.5 + lowestGap - lowest};
                    const Manifold m = collideRoundedPolygons(ground, makeRoundedPolygon(box(half), centre, angle),
                                                              kSpeculative);
                    std::vector<Expected> expected;
                    for (const int k : {0, 1}) {
                        const Vec2 c = corner(centre, half, angle, k);
                        expected.push_back({{c.x, 0.5 * (c.y + 0.5)}, c.y - 0.5});
                    }
                    INFO("half " << half.x << " x " << half.y << ", " << degrees << " degrees, x " << x << ", gap "
                                 << lowestGap);
                    checkPoints(m, {0.0, 1.0}, expected);
                    (m.count == 2 ? withTwo : m.count == 1 ? withOne : withNone) += 1;
                }
    // The ranges cover flat contact, a corner alone and boxes out of reach.
    CHECK(withTwo > 50);
    CHECK(withOne > 50);
    CHECK(withNone > 50);
}

TEST_CASE("a flat box overhanging the edge of another touches where the faces overlap", "[rigid][manifold]") {
    // The points are clipped to the lower box's side planes: x from max(-1, x - hx) to min(1, x + hx).
    const RoundedPolygon lower = makeRoundedPolygon(box({1.0, 0.25}), {0.0, 0.0}, 0.0);
    for (double x = -1.9; x <= 1.9; x += 0.2)
        for (const double gap : {-0.02, -0.004, 0.0, 0.01}) {
            const double hx = 0.4;
            const Manifold m = collideRoundedPolygons(
                lower, makeRoundedPolygon(box({hx, 0.3}), {x, 0.25 + 0.3 + gap}, 0.0), kSpeculative);
            const double left = std::max(-1.0, x - hx), right = std::min(1.0, x + hx);
            INFO("x " << x << ", gap " << gap);
            if (right - left < 0.05) continue; // at or beside the lower box's edge: a corner case, not this test's
            checkPoints(m, {0.0, 1.0}, {{{left, 0.25 + 0.5 * gap}, gap}, {{right, 0.25 + 0.5 * gap}, gap}});
        }
}

TEST_CASE("a capsule on a box touches at its core's ends, one radius out", "[rigid][manifold]") {
    // Box top at y = 0.5; a capsule end at core height y touches at gap y - r - 0.5, midway at (y - r + 0.5) / 2.
    const RoundedPolygon ground = makeRoundedPolygon(box({4.0, 0.5}), {0.0, 0.0}, 0.0);
    int points = 0;
    for (const double r : {0.05, 0.2})
        for (double degrees = -30.0; degrees <= 30.0; degrees += 5.0)
            for (const double lowestGap : {-0.01, 0.0, 0.008, 0.03}) {
                const double angle = degrees * 3.141592653589793 / 180.0;
                const double halfLength = 0.6;
                const Vec2 end0 = Vec2{-halfLength, 0.0}.rotated(angle), end1 = Vec2{halfLength, 0.0}.rotated(angle);
                const Vec2 centre{0.7, 0.5 + r + lowestGap - std::min(end0.y, end1.y)};
                const Manifold m = collideRoundedPolygons(
                    ground, makeRoundedPolygon(capsule(halfLength, r), centre, angle), kSpeculative);
                std::vector<Expected> expected;
                for (const Vec2 end : {centre + end0, centre + end1})
                    expected.push_back({{end.x, 0.5 * (end.y - r + 0.5)}, end.y - r - 0.5});
                INFO("radius " << r << ", " << degrees << " degrees, gap " << lowestGap);
                checkPoints(m, {0.0, 1.0}, expected);
                points += m.count;
            }
    CHECK(points > 80);
}

TEST_CASE("a box above a line segment touches it at its bottom corners, the normal from the box down",
          "[rigid][manifold]") {
    // The body is shape A and the segment B, as the solver pairs them: the normal runs from the box to the
    // line, (0, -1). The line is 10 m long at y = 0 with radius rs; a corner at height y is y - rs from its surface.
    for (const double rs : {0.0, 0.05}) {
        Segment line;
        line.a = {-5.0, 0.0};
        line.b = {5.0, 0.0};
        line.radius = rs;
        const RoundedPolygon seg = makeRoundedPolygon(line);
        for (double degrees = -35.0; degrees <= 35.0; degrees += 5.0)
            for (const double lowestGap : {-0.01, 0.0, 0.005, 0.05}) {
                const double angle = degrees * 3.141592653589793 / 180.0;
                const Vec2 half{0.6, 0.2};
                const double lowest = std::min(corner({0.0, 0.0}, half, angle, 0).y,
                                               corner({0.0, 0.0}, half, angle, 1).y);
                const Vec2 centre{-1.3, rs + lowestGap - lowest};
                const Manifold m = collideRoundedPolygons(makeRoundedPolygon(box(half), centre, angle), seg,
                                                          kSpeculative);
                std::vector<Expected> expected;
                for (const int k : {0, 1}) {
                    const Vec2 c = corner(centre, half, angle, k);
                    expected.push_back({{c.x, 0.5 * (c.y + rs)}, c.y - rs});
                }
                INFO("line radius " << rs << ", " << degrees << " degrees, gap " << lowestGap);
                checkPoints(m, {0.0, -1.0}, expected);
            }
    }
}

TEST_CASE("a circle touches a box's face along its normal and its corner along the line from the corner",
          "[rigid][manifold]") {
    // Box 2 x 1 centred at the origin. Above the face: gap cy - 0.5 - r, normal (0, 1). Past the corner
    // (1, 0.5) diagonally: gap |c - corner| - r, normal from the corner to the centre, the point midway
    // between the corner and the circle's surface.
    const RoundedPolygon block = makeRoundedPolygon(box({1.0, 0.5}), {0.0, 0.0}, 0.0);
    for (const double r : {0.01, 0.1, 0.5})
        for (const double gap : {-0.005, 0.0, 0.004, 0.019, 0.03}) {
            INFO("radius " << r << ", gap " << gap);
            for (double x = -0.9; x <= 0.9; x += 0.3) {
                Circle above;
                above.position = {x, 0.5 + r + gap};
                above.radius = r;
                checkPoints(collideRoundedPolygons(block, makeRoundedPolygon(above), kSpeculative), {0.0, 1.0},
                            {{{x, 0.5 + 0.5 * gap}, gap}});
            }
            if (gap <= 0.0) continue; // a circle overlapping a corner is pushed out along a face instead
            for (const double degrees : {20.0, 45.0, 70.0}) {
                const double angle = degrees * 3.141592653589793 / 180.0;
                const Vec2 n{std::cos(angle), std::sin(angle)};
                const Vec2 cornerPoint{1.0, 0.5};
                Circle beyond;
                beyond.position = cornerPoint + n * (r + gap);
                beyond.radius = r;
                const Manifold m = collideRoundedPolygons(block, makeRoundedPolygon(beyond), kSpeculative);
                INFO(degrees << " degrees off the corner");
                checkPoints(m, n, {{cornerPoint + n * (0.5 * gap), gap}});
            }
        }
}

TEST_CASE("a resting box's points keep their ids while it slides, settles and tilts a little", "[rigid][manifold]") {
    // The ids are what warm starting matches from step to step (rigid_warm_start.hpp).
    const RoundedPolygon ground = makeRoundedPolygon(box({5.0, 0.5}), {0.0, 0.0}, 0.0);
    const Vec2 half{0.4, 0.3};
    const Manifold first = collideRoundedPolygons(ground, makeRoundedPolygon(box(half), {0.0, 0.8 - 0.002}, 0.0),
                                                  kSpeculative);
    REQUIRE(first.count == 2);
    for (double dx = -1.0; dx <= 1.0; dx += 0.125)
        for (const double dy : {-0.003, 0.0, 0.004}) {
            const Manifold later = collideRoundedPolygons(
                ground, makeRoundedPolygon(box(half), {dx, 0.8 + dy}, 0.01 * dx), kSpeculative);
            REQUIRE(later.count == 2);
            // The point at the left corner keeps the left corner's id.
            const int leftFirst = first.points[0].point.x < first.points[1].point.x ? 0 : 1;
            const int leftLater = later.points[0].point.x < later.points[1].point.x ? 0 : 1;
            CHECK(later.points[leftLater].id == first.points[leftFirst].id);
            CHECK(later.points[1 - leftLater].id == first.points[1 - leftFirst].id);
        }
}
