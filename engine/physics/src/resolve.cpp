// Collision resolve: Newton's collision formula along the normal, and the position reset.
#include "resolve.hpp"

#include "step_method.hpp"

#include <algorithm>

namespace rube {

double pairBounciness(const Material& first, const Material& second) { return first.bounciness * second.bounciness; }

double approachSpeed(Vec2 v1, Vec2 v2, Vec2 normal) { return -(v1 - v2).dot(normal); }

double resolveImpact(Vec2& v1, double inverseMass1, Vec2& v2, double inverseMass2, Vec2 normal, double bounciness) {
    const double approach = approachSpeed(v1, v2, normal);
    // Separating bodies are left alone: reflecting them would pull them back together (lecture 3 tip).
    if (!(approach > 0.0)) return approach;
    if (inverseMass1 == 0.0 && inverseMass2 == 0.0) return approach; // two walls: nothing can give
    const double v1n = v1.dot(normal);
    const double v2n = v2.dot(normal);
    // u: the normal velocity of the centre of mass, (m1 v1 + m2 v2) / (m1 + m2) (lecture 3), written with
    // inverse masses; against infinite mass it is exactly the wall's velocity.
    double u = 0.0;
    if (inverseMass2 == 0.0) u = v2n;
    else if (inverseMass1 == 0.0) u = v1n;
    else u = (inverseMass2 * v1n + inverseMass1 * v2n) / (inverseMass1 + inverseMass2);
    // v' = u - C (v - u) along the normal, the tangential part kept (lecture 3).
    v1 += normal * ((u - bounciness * (v1n - u)) - v1n);
    v2 += normal * ((u - bounciness * (v2n - u)) - v2n);
    return approach;
}

void pushApart(Vec2& p1, double inverseMass1, Vec2& p2, double inverseMass2, Vec2 normal, double depth) {
    const double total = inverseMass1 + inverseMass2;
    if (total == 0.0) return;
    // Each body moves in proportion to its inverse mass: the heavier one moves less.
    p1 += normal * (depth * (inverseMass1 / total));
    p2 -= normal * (depth * (inverseMass2 / total));
}

Vec2 segmentSide(const Segment& s, Vec2 point) {
    const Vec2 n = (s.b - s.a).normal();
    return (point - s.a).dot(n) < 0.0 ? -n : n;
}

std::optional<SegmentOverlap> circleSegmentOverlapOnSide(Vec2 centre, double radius, const Segment& s, Vec2 side) {
    const Vec2 line = s.b - s.a;
    const double l2 = line.lengthSquared();
    // The distance along the line by scalar projection: outside the segment the caps decide (lecture 5).
    const double along = l2 > 0.0 ? (centre - s.a).dot(line) / l2 : 0.0;
    if (along <= 0.0 || along >= 1.0) {
        const std::optional<Overlap> cap = circleCircleOverlap(centre, radius, along <= 0.0 ? s.a : s.b, s.radius);
        if (!cap) return std::nullopt;
        return SegmentOverlap{*cap, true};
    }
    const double reach = radius + s.radius;
    const double distance = (centre - s.a).dot(side);
    if (distance <= -reach || distance >= reach) return std::nullopt;
    return SegmentOverlap{Overlap{side, reach - distance, centre - side * (distance - s.radius)}, false};
}

int separateOverlaps(StepContext& ctx, std::span<const Vec2> sideCentres, double sideDelay, double time, bool record) {
    int count = 0;
    const auto note = [&](int circle, Other kind, int other, const Overlap& o, double approach) {
        ++count;
        if (!record) return;
        ctx.impacts.push_back(Impact{circle, kind, other, time, o.point, o.normal, std::max(approach, 0.0)});
        ++ctx.stats.impacts;
    };
    const int circleCount = static_cast<int>(ctx.circles.size());
    for (int i = 0; i < circleCount; ++i) {
        Circle& c = ctx.circles[i];
        if (c.motion != Motion::dynamic) continue;
        for (int k = 0; k < static_cast<int>(ctx.segments.size()); ++k) {
            const Segment& s = ctx.segments[k];
            // The side the centre was on at the start of the step: pushing out towards it never sends a
            // ball through a line it touched, so discrete tunnels only when speed x dt > 2 (r + radius).
            Segment before = s;
            before.a -= s.velocity * sideDelay;
            before.b -= s.velocity * sideDelay;
            const auto hit = circleSegmentOverlapOnSide(c.position, c.radius, s, segmentSide(before, sideCentres[i]));
            if (!hit) continue;
            c.position += hit->overlap.normal * hit->overlap.depth; // a segment has infinite mass
            Vec2 wallVelocity = s.velocityAt(hit->overlap.point);   // v + omega x r on a turning segment
            const double approach = resolveImpact(c.velocity, c.inverseMass, wallVelocity, 0.0, hit->overlap.normal,
                                                  pairBounciness(c.material, s.material));
            note(i, hit->lineCap ? Other::segmentCap : Other::segment, k, hit->overlap, approach);
        }
        for (int j = 0; j < circleCount; ++j) {
            Circle& o = ctx.circles[j];
            const bool dynamicOther = o.motion == Motion::dynamic;
            if (j == i || (dynamicOther && j < i)) continue; // each dynamic pair once
            const std::optional<Overlap> hit = circleCircleOverlap(c.position, c.radius, o.position, o.radius);
            if (!hit) continue;
            // Kinematic circles have infinite mass: work on copies so they are never nudged.
            Vec2 otherPosition = o.position;
            Vec2 otherVelocity = o.velocity;
            pushApart(c.position, c.inverseMass, otherPosition, o.inverseMass, hit->normal, hit->depth);
            const double approach = resolveImpact(c.velocity, c.inverseMass, otherVelocity, o.inverseMass, hit->normal,
                                                  pairBounciness(c.material, o.material));
            if (dynamicOther) {
                o.position = otherPosition;
                o.velocity = otherVelocity;
            }
            note(i, Other::circle, j, *hit, approach);
        }
    }
    return count;
}

} // namespace rube
