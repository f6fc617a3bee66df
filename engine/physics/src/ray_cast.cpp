// Ray casts (ray_cast.hpp): the first circle or capsule surface a ray enters. Exact closed forms,
// no marching: the laser's path through mirrors is checked against the reflect formula to 1e-9 m.
#include "rube/physics/ray_cast.hpp"

#include "rube/physics/world.hpp"

#include <cmath>

namespace rube {

namespace {

// Keeps the nearer of `best` and a hit at `distance` (within `maxDistance`).
void keepNearer(std::optional<RayHit>& best, double distance, double maxDistance, RayHit hit) {
    if (distance < 0.0 || distance > maxDistance || (best && best->distance <= distance)) return;
    hit.distance = distance;
    best = hit;
}

} // namespace

std::optional<double> rayCircle(Vec2 origin, Vec2 direction, Vec2 centre, double radius) {
    const Vec2 m = origin - centre;
    const double c = m.lengthSquared() - radius * radius;
    if (c <= 0.0) return std::nullopt; // starts inside or on it: it does not enter
    const double b = direction.dot(m);
    if (b >= 0.0) return std::nullopt; // heading away from the centre
    const double discriminant = b * b - c;
    if (discriminant < 0.0) return std::nullopt; // passes by
    return -b - std::sqrt(discriminant);
}

std::optional<RayHit> rayCast(const World& world, Vec2 origin, Vec2 direction, double maxDistance) {
    std::optional<RayHit> best;
    const auto circles = world.circles();
    for (std::size_t i = 0; i < circles.size(); ++i) {
        const Circle& c = circles[i];
        if (const auto t = rayCircle(origin, direction, c.position, c.radius)) {
            const Vec2 at = origin + direction * *t;
            keepNearer(best, *t, maxDistance,
                       {RayHit::Shape::circle, static_cast<int>(i), 0.0, at, (at - c.position) / c.radius});
        }
    }
    const auto segments = world.segments();
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const Segment& s = segments[i];
        const int slot = static_cast<int>(i);
        // The end caps.
        for (const Vec2 end : {s.a, s.b}) {
            if (s.radius <= 0.0) break;
            if (const auto t = rayCircle(origin, direction, end, s.radius)) {
                const Vec2 at = origin + direction * *t;
                keepNearer(best, *t, maxDistance, {RayHit::Shape::segment, slot, 0.0, at, (at - end) / s.radius});
            }
        }
        // The side the ray approaches: its normal faces the ray (d . n < 0).
        const Vec2 along = s.b - s.a;
        const double length = along.length();
        if (length <= 0.0) continue;
        Vec2 n = along.perpendicular() / length;
        if (direction.dot(n) > 0.0) n = n * -1.0;
        const double approach = direction.dot(n);
        if (approach >= 0.0) continue;                          // parallel to the segment
        const double height = (origin - s.a).dot(n) - s.radius; // above the side's line, m
        if (height < 0.0) continue;                             // starts on or behind that side
        const double t = height / -approach;
        const Vec2 at = origin + direction * t;
        const double u = (at - s.a).dot(along) / (length * length); // where along a->b, 0..1 on the side
        if (u >= 0.0 && u <= 1.0) keepNearer(best, t, maxDistance, {RayHit::Shape::segment, slot, 0.0, at, n});
    }
    if (best) best->point = origin + direction * best->distance;
    return best;
}

} // namespace rube
