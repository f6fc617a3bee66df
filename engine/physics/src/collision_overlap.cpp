// Discrete overlap tests (lecture 5: circle-circle, circle-point, circle-segment with caps).
#include "rube/physics/collision.hpp"

#include <algorithm>

namespace rube {

std::optional<Overlap> circleCircleOverlap(Vec2 c1, double r1, Vec2 c2, double r2) {
    const Vec2 d = c1 - c2;
    const double radiusSum = r1 + r2;
    const double distSq = d.lengthSquared();
    // Compare squared lengths first: no square root for the common no-contact case.
    if (distSq >= radiusSum * radiusSum) return std::nullopt;
    const double dist = std::sqrt(distSq);
    // Coincident centres have no direction between them; pick +y so the push-back is defined.
    const Vec2 normal = dist > 0.0 ? d / dist : Vec2{0.0, 1.0};
    return Overlap{normal, radiusSum - dist, c2 + normal * r2};
}

std::optional<Overlap> circlePointOverlap(Vec2 c, double r, Vec2 p) { return circleCircleOverlap(c, r, p, 0.0); }

Vec2 closestPointOnSegment(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 ab = b - a;
    const double l2 = ab.lengthSquared();
    if (l2 == 0.0) return a;
    // The distance along the line by scalar projection, clamped to the segment (lecture 5).
    const double t = std::clamp((p - a).dot(ab) / l2, 0.0, 1.0);
    return a + ab * t;
}

std::optional<Overlap> circleSegmentOverlap(Vec2 c, double r, Vec2 a, Vec2 b, double segmentRadius) {
    const Vec2 ab = b - a;
    const double l2 = ab.lengthSquared();
    const double along = l2 > 0.0 ? (c - a).dot(ab) / l2 : 0.0;
    if (along <= 0.0) return circleCircleOverlap(c, r, a, segmentRadius);
    if (along >= 1.0) return circleCircleOverlap(c, r, b, segmentRadius);
    // Inside the span: the distance is the projection on the line's normal, taken on the
    // circle's side so the segment is two-sided (lecture 5, "two segments with opposite normals").
    Vec2 n = ab.normal();
    double dist = (c - a).dot(n);
    if (dist < 0.0) {
        n = -n;
        dist = -dist;
    }
    const double reach = r + segmentRadius;
    if (dist >= reach) return std::nullopt;
    return Overlap{n, reach - dist, c - n * (dist - segmentRadius)};
}

} // namespace rube
