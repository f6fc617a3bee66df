// Speculative contacts aimed at their time of impact: the normal where the pair will touch.
#include "solver_impact_normal.hpp"

#include "solver_sweep.hpp"

#include <algorithm>
#include <cmath>

namespace rube {

namespace {

/// The closest point of segment ab to p, by clamped scalar projection (lecture 5), and where along it.
Vec2 closestOnSegment(Vec2 p, Vec2 a, Vec2 b, double& along) {
    const Vec2 ab = b - a;
    const double l2 = ab.lengthSquared();
    along = l2 > 0.0 ? (p - a).dot(ab) / l2 : 0.0;
    return l2 > 0.0 ? a + ab * std::clamp(along, 0.0, 1.0) : a;
}

/// The fraction in [0, 1] of the straight move q0 -> q0 + d at which q comes nearest to the origin
/// (seg null) or to the segment: distance to a convex shape is convex along a line, so its least is at
/// an end of the move or where the distance to a cap is least (the distance to the face is linear).
double nearestApproach(Vec2 q0, Vec2 d, const Segment* seg) {
    const double dd = d.lengthSquared();
    const auto nearestTo = [&](Vec2 c) { return dd > 0.0 ? std::clamp((c - q0).dot(d) / dd, 0.0, 1.0) : 0.0; };
    if (!seg) return nearestTo(Vec2{});
    double along = 0.0, best = 0.0, bestDistance = -1.0;
    for (const double f : {0.0, 1.0, nearestTo(seg->a), nearestTo(seg->b)}) {
        const Vec2 q = q0 + d * f;
        const double distance = (q - closestOnSegment(q, seg->a, seg->b, along)).lengthSquared();
        if (bestDistance < 0.0 || distance < bestDistance) best = f, bestDistance = distance;
    }
    return best;
}

/// Fixed-point passes for the time of impact along the substeps' path: each sweeps a straight line
/// with the mean velocity up to the last estimate, exact at that time (two suffice: the path bends
/// by |g| t^2 / 2, under 1.4 mm in a 60 Hz step).
constexpr int kPathPasses = 2;

} // namespace

void aimAtTimeOfImpact(std::span<ContactConstraint> contacts, std::span<ContactRecord> records,
                       std::span<const Circle> circles, std::span<const Segment> segments,
                       std::span<const double> inverseMass, Vec2 gravity, double dt, double h, double restingSpeed) {
    const int circleCount = static_cast<int>(circles.size());
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        ContactConstraint& c = contacts[k];
        if (c.baseSeparation <= 0.0) continue; // touching already: resting or pushing, its normal holds
        const Circle& a = circles[static_cast<std::size_t>(c.a)];
        const bool otherIsCircle = c.b < circleCount;
        const Segment* seg = otherIsCircle ? nullptr : &segments[static_cast<std::size_t>(c.b - circleCount)];
        if (seg && seg->angularVelocity != 0.0) continue; // a turning paddle's contacts are TurningContacts'
        const Vec2 otherVelocity = otherIsCircle ? circles[static_cast<std::size_t>(c.b)].velocity
                                                 : (seg->motion() == Motion::kinematic ? seg->velocity : Vec2{});
        const Vec2 w = a.velocity - otherVelocity;
        // Slow pairs rest rather than bounce, and their normal turns little within a step: left as found.
        if (-c.normal.dot(w) <= restingSpeed) continue;
        // Two dynamic circles fall alike; against infinite mass the circle alone falls, along the exact
        // parabola q0 + w t + g t^2 / 2 from the state as given (a lone bounce is flown on it,
        // carryPastImpact; the substeps run half a substep of gravity ahead of it, g t h / 2).
        const Vec2 fall = inverseMass[static_cast<std::size_t>(c.b)] > 0.0 ? Vec2{} : gravity;
        const Vec2 q0 = otherIsCircle ? a.position - circles[static_cast<std::size_t>(c.b)].position : a.position;
        const double reach = a.radius + (otherIsCircle ? circles[static_cast<std::size_t>(c.b)].radius : seg->radius);
        // The last substep's relax pass already holds a pair to what it may close in one substep more
        // (vn >= -s / h), so the look-ahead reaches h past the step.
        const double horizon = dt + h;
        double t = horizon;
        double fraction = -1.0;
        for (int pass = 0; pass < kPathPasses; ++pass) {
            const Vec2 move = (w + fall * (0.5 * t)) * horizon;
            fraction = otherIsCircle ? sweepPointCircle(q0, move, Vec2{}, reach)
                                     : sweepPointCapsule(q0, move, seg->a, seg->b, reach);
            if (fraction < 0.0) break;
            t = fraction * horizon;
        }
        // Touching within the look-ahead: aim at the time of impact. Not touching: at the time of nearest
        // approach within the look-ahead, so that the start normal's linear gap, shorter than the true one
        // off the line of centres, cannot catch a pair that passes by or touches only later.
        if (fraction < 0.0)
            t = nearestApproach(q0, (w + fall * (0.5 * horizon)) * horizon, otherIsCircle ? nullptr : seg) * horizon;
        const Vec2 atImpact = q0 + (w + fall * (0.5 * (fraction < 0.0 ? horizon : t))) * t;
        double along = 0.0;
        const Vec2 feature = otherIsCircle ? Vec2{} : closestOnSegment(atImpact, seg->a, seg->b, along);
        const Vec2 away = atImpact - feature;
        const double distance = away.length();
        if (!(distance > 0.0)) continue;
        // The gap along the new normal n changes by n . (relative displacement): it closes exactly at
        // the time of impact, or is least at the nearest approach, where it equals the true gap (the
        // shape lies behind the plane through its closest point, so it is never more than the true
        // gap). Its start value is n . (q0 - feature) - reach.
        c.normal = away / distance;
        c.baseSeparation = std::max(c.normal.dot(q0 - feature) - reach, 0.0);
        if (fraction >= 0.0) records[k].impactTime = t;
        if (!otherIsCircle) records[k].kind = along <= 0.0 || along >= 1.0 ? Other::segmentCap : Other::segment;
    }
}

} // namespace rube
