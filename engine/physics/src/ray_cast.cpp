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

namespace {

/// Where a ray enters a capsule (segment ab fattened by `radius`): its end caps, then the side it
/// approaches; the nearer entry within `maxDistance` goes into `best` as `shape` `slot`.
void rayCapsule(Vec2 origin, Vec2 direction, Vec2 a, Vec2 b, double radius, double maxDistance, RayHit::Shape shape,
                int slot, std::optional<RayHit>& best) {
    // The end caps.
    for (const Vec2 end : {a, b}) {
        if (radius <= 0.0) break;
        if (const auto t = rayCircle(origin, direction, end, radius)) {
            const Vec2 at = origin + direction * *t;
            keepNearer(best, *t, maxDistance, {shape, slot, 0.0, at, (at - end) / radius});
        }
    }
    // The side the ray approaches: its normal faces the ray (d . n < 0).
    const Vec2 along = b - a;
    const double length = along.length();
    if (length <= 0.0) return;
    Vec2 n = along.perpendicular() / length;
    if (direction.dot(n) > 0.0) n = n * -1.0;
    const double approach = direction.dot(n);
    if (approach >= 0.0) return;                        // parallel to the segment
    const double height = (origin - a).dot(n) - radius; // above the side's line, m
    if (height < 0.0) return;                           // starts on or behind that side
    const double t = height / -approach;
    const Vec2 at = origin + direction * t;
    const double u = (at - a).dot(along) / (length * length); // where along a->b, 0..1 on the side
    if (u >= 0.0 && u <= 1.0) keepNearer(best, t, maxDistance, {shape, slot, 0.0, at, n});
}

/// Where a ray enters a box (centre, half extents, turned by `rotation` = (cos, sin)): clipped
/// against its four faces' half-planes (Cyrus-Beck), entering through the last face it crosses
/// inwards, if it crosses them all before it leaves through any.
void rayBox(Vec2 origin, Vec2 direction, Vec2 centre, Vec2 halfExtents, Vec2 rotation, double maxDistance, int slot,
            std::optional<RayHit>& best) {
    const Vec2 axes[2] = {rotation, rotation.perpendicular()};
    const double half[2] = {halfExtents.x, halfExtents.y};
    double enter = -1.0, leave = maxDistance;
    Vec2 normal;
    bool outside = false;
    for (int k = 0; k < 2; ++k) {
        for (const double side : {1.0, -1.0}) {
            const Vec2 n = axes[k] * side;
            const double height = (origin - centre).dot(n) - half[k]; // above this face's line
            const double approach = direction.dot(n);
            outside = outside || height > 0.0;
            if (approach == 0.0) {
                if (height > 0.0) return; // parallel, outside this face
                continue;
            }
            const double t = -height / approach;
            if (approach < 0.0) {
                if (t > enter) {
                    enter = t;
                    normal = n;
                }
            } else if (t < leave) {
                leave = t;
            }
        }
    }
    // Starting on or inside the box, the ray does not enter it.
    if (!outside || enter < 0.0 || enter > leave) return;
    keepNearer(best, enter, maxDistance, {RayHit::Shape::body, slot, 0.0, origin + direction * enter, normal});
}

} // namespace

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
        rayCapsule(origin, direction, s.a, s.b, s.radius, maxDistance, RayHit::Shape::segment, static_cast<int>(i),
                   best);
    }
    // Boxes and capsules, whatever their motion: a crate or a plank stops a beam.
    const auto bodies = world.bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const RigidBody& b = bodies[i];
        const Vec2 rotation = Vec2::fromAngle(b.angle);
        const int slot = static_cast<int>(i);
        if (b.shape == BodyShape::box) {
            rayBox(origin, direction, b.position, b.halfExtents, rotation, maxDistance, slot, best);
        } else {
            const Vec2 core = rotation * b.halfExtents.x; // the capsule's core runs along its x axis
            rayCapsule(origin, direction, b.position - core, b.position + core, b.halfExtents.y, maxDistance,
                       RayHit::Shape::body, slot, best);
        }
    }
    if (best) best->point = origin + direction * best->distance;
    return best;
}

} // namespace rube
