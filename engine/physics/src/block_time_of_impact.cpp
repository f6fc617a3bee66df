// Continuous detection for lecture 3's blocks: the time and point of impact of a moving block against
// a block (Assignment 3.3: per-axis distances before and after the move, t = a / b), a circle (the
// block grown by r: faces offset by r, corners rounded with r) and a segment with rounded line caps.
#include "rube/physics/block_collision.hpp"

#include "polynomial.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace rube {

namespace {

double signOrZero(double x) { return x < 0.0 ? -1.0 : (x > 0.0 ? 1.0 : 0.0); }

// The earliest t in [0, horizon] at which a gap of `gap` now, closing at -speed and -accel, reaches 0:
// gap + speed t + accel t^2 / 2 = 0. The caller has checked gap >= 0 (the block is on this side).
// At constant velocity this is the lecture's triangle ratio t = a / b.
std::optional<double> gapTime(double gap, double speed, double accel, double horizon) {
    const bool approaching = speed < 0.0 || (speed == 0.0 && accel < 0.0);
    if (gap == 0.0 && approaching) return 0.0;
    if (accel == 0.0) {
        if (!(speed < 0.0)) return std::nullopt; // moving away or along: never closes
        const double t = gap / -speed;           // t = a / b (lecture 3)
        return t <= horizon ? std::optional<double>{t} : std::nullopt;
    }
    // Touching and moving apart: the root at 0 is the contact that is ending, not a new one.
    return earliestRoot(Polynomial{{gap, speed, 0.5 * accel, 0.0, 0.0}}, 0.0, horizon, gap == 0.0);
}

// Approaching along the normal n (from the other towards the block) when overlapping at the start:
// by velocity, or by acceleration when the normal velocity is exactly zero (resting under gravity).
bool approachingAlong(const BlockMotion& block, Vec2 n) {
    const double vn = block.velocity.dot(n);
    return vn < 0.0 || (vn == 0.0 && block.acceleration.dot(n) < 0.0);
}

// Component k (0: x, 1: y) of v.
double axis(Vec2 v, int k) { return k == 0 ? v.x : v.y; }

// Keeps the earlier of two collisions.
void keepEarlier(std::optional<Collision>& best, const std::optional<Collision>& candidate) {
    if (candidate && (!best || candidate->timeOfImpact < best->timeOfImpact)) best = candidate;
}

} // namespace

std::optional<Collision> blockBlockCollision(const BlockMotion& block, Vec2 otherCentre, Vec2 otherHalfExtents,
                                             double horizon) {
    const Vec2 reach = block.halfExtents + otherHalfExtents;
    if (const auto overlap = blockBlockOverlap(block.centre, block.halfExtents, otherCentre, otherHalfExtents)) {
        if (!approachingAlong(block, overlap->normal)) return std::nullopt; // attempt 3: let them separate
        return Collision{0.0, block.centre, overlap->normal, overlap->point, false};
    }
    std::optional<Collision> best;
    // Four faces of the other block: per axis k and side s, the distance between the facing sides is
    // s (p_k - q_k) - (h1_k + h2_k) before the move; the block must start on that side (a >= 0).
    for (int k = 0; k < 2; ++k) {
        const int other = 1 - k;
        for (const double s : {1.0, -1.0}) {
            const double gap = s * (axis(block.centre, k) - axis(otherCentre, k)) - axis(reach, k);
            if (gap < 0.0) continue;
            const auto t = gapTime(gap, s * axis(block.velocity, k), s * axis(block.acceleration, k), horizon);
            if (!t || (best && best->timeOfImpact <= *t)) continue;
            const Vec2 poi = block.at(*t);
            // The other axis must overlap then; touching corner to corner (equality) is no impact,
            // so a block sliding along a row of blocks does not catch on their seams.
            const double across = axis(poi, other) - axis(otherCentre, other);
            if (!(std::fabs(across) < axis(reach, other))) continue;
            const Vec2 normal = k == 0 ? Vec2{s, 0.0} : Vec2{0.0, s};
            // The contact point: on the other's face, in the middle of the span both faces share.
            const double lo = std::max(axis(poi, other) - axis(block.halfExtents, other),
                                       axis(otherCentre, other) - axis(otherHalfExtents, other));
            const double hi = std::min(axis(poi, other) + axis(block.halfExtents, other),
                                       axis(otherCentre, other) + axis(otherHalfExtents, other));
            const double face = axis(otherCentre, k) + s * axis(otherHalfExtents, k);
            const Vec2 contact = k == 0 ? Vec2{face, 0.5 * (lo + hi)} : Vec2{0.5 * (lo + hi), face};
            best = Collision{*t, poi, normal, contact, false};
        }
    }
    return best;
}

std::optional<Collision> blockCircleCollision(const BlockMotion& block, Vec2 circleCentre, double radius,
                                              double horizon) {
    const Vec2 half = block.halfExtents;
    if (const auto overlap = blockCircleOverlap(block.centre, half, circleCentre, radius)) {
        if (!approachingAlong(block, overlap->normal)) return std::nullopt;
        return Collision{0.0, block.centre, overlap->normal, overlap->point, false};
    }
    std::optional<Collision> best;
    // The faces offset by r: the circle's centre q (from the block's centre) reaches s q_k = h_k + r
    // while |q_other| <= h_other. The normal, from the circle towards the block, is -s along k.
    for (int k = 0; k < 2; ++k) {
        const int other = 1 - k;
        for (const double s : {1.0, -1.0}) {
            const double gap = s * (axis(circleCentre, k) - axis(block.centre, k)) - (axis(half, k) + radius);
            if (gap < 0.0) continue;
            const auto t = gapTime(gap, -s * axis(block.velocity, k), -s * axis(block.acceleration, k), horizon);
            if (!t || (best && best->timeOfImpact <= *t)) continue;
            const Vec2 poi = block.at(*t);
            if (!(std::fabs(axis(circleCentre, other) - axis(poi, other)) <= axis(half, other))) continue;
            const Vec2 normal = k == 0 ? Vec2{-s, 0.0} : Vec2{0.0, -s};
            best = Collision{*t, poi, normal, circleCentre + normal * radius, false};
        }
    }
    // The corners: each is a point moving with the block against the circle of radius r (lecture 5's
    // abc formula), valid where the circle's centre lies beyond both faces that meet there.
    for (const double sx : {1.0, -1.0}) {
        for (const double sy : {1.0, -1.0}) {
            const Vec2 offset{sx * half.x, sy * half.y};
            const CircleMotion corner{block.centre + offset, block.velocity, 0.0, block.acceleration};
            const auto hit = circleCircleCollision(corner, circleCentre, radius, horizon);
            if (!hit || (best && best->timeOfImpact <= hit->timeOfImpact)) continue;
            const Vec2 q = circleCentre - (hit->pointOfImpact - offset);
            if (!(sx * q.x >= half.x && sy * q.y >= half.y)) continue;
            // circleCircleCollision's normal runs from the circle to the corner: from the circle to the block.
            best = Collision{hit->timeOfImpact, hit->pointOfImpact - offset, hit->normal, hit->pointOfImpact, true};
        }
    }
    return best;
}

std::optional<Collision> blockSegmentCollision(const BlockMotion& block, Vec2 a, Vec2 b, double segmentRadius,
                                               double horizon) {
    const Vec2 line = b - a;
    const double length = line.length();
    if (length > 0.0) {
        const Vec2 lineNormal = line.normal();
        const Vec2 side = (block.centre - a).dot(lineNormal) < 0.0 ? -lineNormal : lineNormal;
        if (const auto overlap = blockSegmentOverlapOnSide(block.centre, block.halfExtents, a, b, segmentRadius,
                                                           side)) {
            if (!approachingAlong(block, overlap->normal)) return std::nullopt;
            return Collision{0.0, block.centre, overlap->normal, overlap->point, false};
        }
        std::optional<Collision> face;
        // Two-sided, as for circles: the line with either normal. The block's nearest corner (or side)
        // reaches blockReach + radius from its centre along the normal: the gap is the lecture's
        // distance to the line minus that reach.
        for (const Vec2 n : {lineNormal, -lineNormal}) {
            const double reach = blockReach(block.halfExtents, n) + segmentRadius;
            const double gap = (block.centre - a).dot(n) - reach;
            if (gap < 0.0) continue;
            const auto t = gapTime(gap, block.velocity.dot(n), block.acceleration.dot(n), horizon);
            if (!t || (face && face->timeOfImpact <= *t)) continue;
            const Vec2 poi = block.at(*t);
            const Vec2 corner = poi +
                                Vec2{-block.halfExtents.x * signOrZero(n.x), -block.halfExtents.y * signOrZero(n.y)};
            // The corner's distance along the line, by scalar projection: past the ends the caps decide.
            const double along = (corner - a).dot(line) / length;
            if (along < 0.0 || along > length) continue;
            face = Collision{*t, poi, n, a + line * (along / length) + n * segmentRadius, false};
        }
        // A face hit comes first: the caps, grown by the block, lie within the face's slab.
        if (face) return face;
    }
    std::optional<Collision> cap = blockCircleCollision(block, a, segmentRadius, horizon);
    if (length > 0.0) keepEarlier(cap, blockCircleCollision(block, b, segmentRadius, horizon));
    if (cap) cap->lineCap = true;
    return cap;
}

} // namespace rube
