// Discrete overlap tests for lecture 3's blocks: block against block (the AABB test), block against
// circle (the rounded rectangle) and block against a segment with rounded line caps.
#include "rube/physics/block_collision.hpp"

#include <algorithm>
#include <cmath>

namespace rube {

namespace {

// +1 or -1 by the sign of x; +1 for zero, so a push-back from a coincident centre is still defined.
double sideOf(double x) { return x < 0.0 ? -1.0 : 1.0; }

// The sign of x, 0 for zero: picks the block's corner (or, for an axis-aligned line, the middle of its side) nearest a
// line.
double signOrZero(double x) { return x < 0.0 ? -1.0 : (x > 0.0 ? 1.0 : 0.0); }

} // namespace

double blockReach(Vec2 half, Vec2 n) { return half.x * std::fabs(n.x) + half.y * std::fabs(n.y); }

std::optional<Overlap> blockBlockOverlap(Vec2 centre1, Vec2 half1, Vec2 centre2, Vec2 half2) {
    const Vec2 d = centre1 - centre2;
    // P.right > Q.left and P.left < Q.right is |dx| < hx1 + hx2 (lecture 3, AABB), and the same on y.
    const double overlapX = half1.x + half2.x - std::fabs(d.x);
    const double overlapY = half1.y + half2.y - std::fabs(d.y);
    if (!(overlapX > 0.0) || !(overlapY > 0.0)) return std::nullopt;
    // Reset along the axis of least overlap: the smallest move that separates them.
    const bool alongX = overlapX < overlapY;
    const Vec2 normal = alongX ? Vec2{sideOf(d.x), 0.0} : Vec2{0.0, sideOf(d.y)};
    // The middle of the two faces' shared span, on block 2's face.
    const auto middle = [](double c1, double h1, double c2, double h2) {
        return 0.5 * (std::max(c1 - h1, c2 - h2) + std::min(c1 + h1, c2 + h2));
    };
    const Vec2 point = alongX ? Vec2{centre2.x + normal.x * half2.x, middle(centre1.y, half1.y, centre2.y, half2.y)}
                              : Vec2{middle(centre1.x, half1.x, centre2.x, half2.x), centre2.y + normal.y * half2.y};
    return Overlap{normal, alongX ? overlapX : overlapY, point};
}

std::optional<Overlap> blockCircleOverlap(Vec2 centre, Vec2 half, Vec2 circleCentre, double radius) {
    const Vec2 q = circleCentre - centre;
    const Vec2 nearest{std::clamp(q.x, -half.x, half.x), std::clamp(q.y, -half.y, half.y)};
    if (nearest == q) {
        // The circle's centre is inside the block: out through the nearest face.
        const double outX = half.x - std::fabs(q.x) + radius;
        const double outY = half.y - std::fabs(q.y) + radius;
        const Vec2 normal = outX < outY ? Vec2{-sideOf(q.x), 0.0} : Vec2{0.0, -sideOf(q.y)};
        return Overlap{normal, std::min(outX, outY), circleCentre + normal * radius};
    }
    // Outside: the distance to the nearest point of the block, a face or a corner, against r.
    const Vec2 d = q - nearest;
    const double distSq = d.lengthSquared();
    if (distSq >= radius * radius) return std::nullopt;
    const double dist = std::sqrt(distSq);
    const Vec2 normal = -(d / dist); // from the circle towards the block
    return Overlap{normal, radius - dist, circleCentre + normal * radius};
}

std::optional<Overlap> blockSegmentOverlapOnSide(Vec2 centre, Vec2 half, Vec2 a, Vec2 b, double segmentRadius,
                                                 Vec2 side) {
    const Vec2 line = b - a;
    const double l2 = line.lengthSquared();
    if (l2 > 0.0) {
        // The block's corner nearest the line on `side` (the middle of a side for an axis-aligned line):
        // while it projects inside the segment, the face decides.
        const Vec2 corner = centre + Vec2{-half.x * signOrZero(side.x), -half.y * signOrZero(side.y)};
        const double along = (corner - a).dot(line) / l2;
        if (along > 0.0 && along < 1.0) {
            const double reach = blockReach(half, side) + segmentRadius;
            const double distance = (centre - a).dot(side);
            if (distance <= -reach || distance >= reach) return std::nullopt;
            return Overlap{side, reach - distance, a + line * along + side * segmentRadius};
        }
    }
    // Past the ends: the line caps, circles of the segment's radius; the deeper one decides.
    std::optional<Overlap> cap = blockCircleOverlap(centre, half, a, segmentRadius);
    if (l2 > 0.0) {
        const std::optional<Overlap> capB = blockCircleOverlap(centre, half, b, segmentRadius);
        if (capB && (!cap || capB->depth > cap->depth)) cap = capB;
    }
    return cap;
}

} // namespace rube
