// Continuous detection (lecture 5): times of impact of a circle against a circle, a point (line cap)
// and a two-sided segment with line caps, at constant velocity and under constant acceleration.
#include "rube/physics/time_of_impact.hpp"

#include "polynomial.hpp"

#include <algorithm>
#include <cmath>

namespace rube {

namespace {

// The lecture's "a ~ 0": a relative speed below a picometre per second closes no gap within a step.
constexpr double kStillSpeedSquared = 1e-24;

// c = |u|^2 - R^2 written as (|u| - R)(|u| + R): when the circles just touch, |u|^2 and R^2 agree in
// almost every digit and their difference would be mostly rounding.
double gapTerm(Vec2 u, double radiusSum) {
    const double distance = u.length();
    return (distance - radiusSum) * (distance + radiusSum);
}

// Most pairs of an exact search are far apart, and the quartic's roots cost ten times a test that
// shows they cannot meet (issue 26): within the horizon a centre moves at most
// reach = |v| t + |acc| t^2 / 2 from where it starts, so a pair whose surfaces are farther apart than
// that has no root. The margin, a millionth of the distances (and a nanometre), keeps the test from
// ever dropping a root the exact test would find: where it applies the true gap stays at least the
// margin, and the quartic's value at least margin (2 R + margin), far above the rounding of its terms.
double reachWithin(Vec2 v, Vec2 acc, double horizon) {
    return std::sqrt(v.dot(v)) * horizon + 0.5 * std::sqrt(acc.dot(acc)) * horizon * horizon;
}
double farEnough(double touching, double reach) { return touching + reach + 1e-6 * (touching + reach) + 1e-9; }

// The smaller root (-b - sqrt(D)) / 2a of the abc formula. For b < 0 the numerator subtracts two
// nearly equal numbers when c is small, so use the equal form 2c / (-b + sqrt(D)) there.
double smallerRoot(double a, double b, double c, double discriminant) {
    const double s = std::sqrt(discriminant);
    return b < 0.0 ? 2.0 * c / (-b + s) : (-b - s) / (2.0 * a);
}

// The robust rules of attempt 3, for an overlap at the start: an impact now when approaching,
// nothing when separating (the bodies are already moving apart: let them).
std::optional<double> overlapAtStart(bool approaching, TimeOfImpactRule rule) {
    switch (rule) {
    case TimeOfImpactRule::attempt1: return std::nullopt; // its t < 0 is ignored
    case TimeOfImpactRule::attempt2: return 0.0;
    case TimeOfImpactRule::attempt3: break;
    }
    return approaching ? std::optional<double>{0.0} : std::nullopt;
}

// Overlapping at the start and separating, under acceleration: attempt 3 lets it go, but gravity may
// turn it back within the step (after a reset to the point of impact rounding leaves the normal speed
// at +-1e-17). The impact is then the earliest time it overlaps and approaches: where the gap stops
// growing (the first root of its derivative) if it still overlaps there, else where it meets again.
std::optional<double> separatingOverlap(const Polynomial& gap, double horizon, TimeOfImpactRule rule) {
    if (rule != TimeOfImpactRule::attempt3) return overlapAtStart(false, rule);
    const std::optional<double> turn = earliestRoot(gap.derivative(), 0.0, horizon, true);
    if (!turn) return std::nullopt;
    if (gap(*turn) < 0.0) return turn;
    return earliestRoot(gap, *turn, horizon);
}

// |u + v t + acc t^2 / 2| = radiusSum under constant relative acceleration: the quartic
// |A|^2 t^4 + 2 A.v t^3 + (|v|^2 + 2 A.u) t^2 + 2 u.v t + c = 0 with A = acc / 2.
std::optional<double> circleCircleTimeOfImpactAccelerated(Vec2 u, Vec2 v, Vec2 acc, double radiusSum, double horizon,
                                                          TimeOfImpactRule rule) {
    if (acc == Vec2{}) return circleCircleTimeOfImpact(u, v, radiusSum, horizon, rule);
    const double far = farEnough(radiusSum, reachWithin(v, acc, horizon));
    if (u.dot(u) > far * far) return std::nullopt; // |u| > far: out of reach (the quartic has no root)
    const double c = gapTerm(u, radiusSum);
    // Approaching by velocity, or by acceleration when the normal velocity is exactly zero
    // (a ball resting on another under gravity).
    const double uv = u.dot(v);
    const bool approaching = uv < 0.0 || (uv == 0.0 && u.dot(acc) < 0.0);
    const Vec2 half = acc * 0.5;
    const Polynomial gap{{c, 2.0 * uv, v.dot(v) + 2.0 * half.dot(u), 2.0 * half.dot(v), half.dot(half)}};
    if (c < 0.0) return approaching ? overlapAtStart(true, rule) : separatingOverlap(gap, horizon, rule);
    if (c == 0.0 && approaching) return 0.0;
    // Touching and moving apart: the root at 0 is the contact that is ending, not a new one.
    return earliestRoot(gap, 0.0, horizon, c == 0.0);
}

// The line test under constant acceleration: the gap a + vn t + an t^2 / 2 is quadratic in t.
// vn and an are the velocity and acceleration along the line's normal (negative towards it).
std::optional<double> lineTimeOfImpactAccelerated(double a, double vn, double an, double radius, double horizon,
                                                  TimeOfImpactRule rule) {
    if (an == 0.0) return lineTimeOfImpact(a, -vn, radius, horizon, rule);
    if (a < -radius) return std::nullopt; // the centre is already past the line: keep moving
    const bool approaching = vn < 0.0 || (vn == 0.0 && an < 0.0);
    const Polynomial gap{{a, vn, 0.5 * an, 0.0, 0.0}};
    if (a < 0.0) return approaching ? overlapAtStart(true, rule) : separatingOverlap(gap, horizon, rule);
    if (a == 0.0 && approaching) return 0.0;
    return earliestRoot(gap, 0.0, horizon, a == 0.0);
}

// The unit normal from `from` to `to`; when the two coincide, against the circle's motion (it is
// pushed back the way it came), and +y when it is not moving either.
Vec2 normalBetween(Vec2 to, Vec2 from, Vec2 velocity) {
    const Vec2 n = (to - from).normalized();
    if (n != Vec2{}) return n;
    const Vec2 back = (-velocity).normalized();
    return back != Vec2{} ? back : Vec2{0.0, 1.0};
}

} // namespace

std::optional<double> circleCircleTimeOfImpact(Vec2 u, Vec2 v, double radiusSum, double horizon,
                                               TimeOfImpactRule rule) {
    const double a = v.dot(v);
    const double b = 2.0 * u.dot(v);
    const double c = gapTerm(u, radiusSum);
    // Attempt 2: overlapping (c < 0) is an impact now; attempt 3 only when approaching (b < 0).
    if (c < 0.0 && rule != TimeOfImpactRule::attempt1) return overlapAtStart(b < 0.0, rule);
    if (a <= kStillSpeedSquared) return std::nullopt;
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return std::nullopt; // the paths never come within radiusSum
    const double t = smallerRoot(a, b, c, discriminant);
    if (t >= 0.0 && t <= horizon) return t;
    return std::nullopt; // in the past (attempt 1 overlapping, or separating) or after this step
}

std::optional<double> lineTimeOfImpact(double a, double b, double radius, double horizon, TimeOfImpactRule rule) {
    if (b <= 0.0) return std::nullopt; // moving away from the line, or along it
    double t = 0.0;
    if (a >= 0.0) t = a / b; // the triangle ratio: allowed movement over requested movement
    else if (a >= -radius) { // slightly inside, going deeper: rounding after a reset to the POI
        if (rule == TimeOfImpactRule::attempt1) return std::nullopt;
        t = 0.0;
    } else return std::nullopt; // the centre is already past the line: keep moving
    if (t <= horizon) return t;
    return std::nullopt;
}

std::optional<Collision> circleCircleCollision(const CircleMotion& circle, Vec2 otherCentre, double otherRadius,
                                               double horizon, TimeOfImpactRule rule) {
    const std::optional<double> t = circleCircleTimeOfImpactAccelerated(
        circle.centre - otherCentre, circle.velocity, circle.acceleration, circle.radius + otherRadius, horizon, rule);
    if (!t) return std::nullopt;
    Collision hit;
    hit.timeOfImpact = *t;
    hit.pointOfImpact = circle.at(*t);
    // The collision normal runs from centre to centre at the point of impact (lecture 5).
    hit.normal = normalBetween(hit.pointOfImpact, otherCentre, circle.velocity + circle.acceleration * *t);
    hit.contactPoint = otherCentre + hit.normal * otherRadius;
    return hit;
}

std::optional<Collision> circlePointCollision(const CircleMotion& circle, Vec2 point, double horizon,
                                              TimeOfImpactRule rule) {
    return circleCircleCollision(circle, point, 0.0, horizon, rule);
}

std::optional<Collision> circleSegmentCollision(const CircleMotion& circle, Vec2 a, Vec2 b, double segmentRadius,
                                                double horizon, TimeOfImpactRule rule) {
    // Out of reach of the box round the segment and its caps: no face and no cap within the horizon.
    // (The lecture's attempts 1 and 2 keep their own answers for what lies behind a face.)
    if (rule == TimeOfImpactRule::attempt3) {
        const double far = farEnough(circle.radius, reachWithin(circle.velocity, circle.acceleration, horizon));
        const double dx = std::max({std::min(a.x, b.x) - segmentRadius - circle.centre.x, 0.0,
                                    circle.centre.x - std::max(a.x, b.x) - segmentRadius});
        const double dy = std::max({std::min(a.y, b.y) - segmentRadius - circle.centre.y, 0.0,
                                    circle.centre.y - std::max(a.y, b.y) - segmentRadius});
        if (dx * dx + dy * dy > far * far) return std::nullopt;
    }
    const double radius = circle.radius + segmentRadius;
    const Vec2 line = b - a;
    const double length = line.length();
    // Only attempt 1 differs on a face: the line test rejects b <= 0 before it looks at a.
    const TimeOfImpactRule faceRule = rule == TimeOfImpactRule::attempt1 ? rule : TimeOfImpactRule::attempt3;
    if (length > 0.0) {
        const Vec2 lineNormal = line.normal();
        std::optional<Collision> face;
        // Two-sided: the lecture's two line segments with opposite normals, A to B and B to A.
        for (const Vec2 side : {lineNormal, -lineNormal}) {
            const double distance = (circle.centre - a).dot(side);
            const std::optional<double> t = lineTimeOfImpactAccelerated(
                distance - radius, circle.velocity.dot(side), circle.acceleration.dot(side), radius, horizon, faceRule);
            if (!t || (face && face->timeOfImpact <= *t)) continue;
            const Vec2 poi = circle.at(*t);
            // The distance along the line of the point of impact, by scalar projection (lecture 5):
            // outside [0, length] the circle passes the end, where the caps decide.
            const double along = (poi - a).dot(line) / length;
            if (along < 0.0 || along > length) continue;
            const Vec2 foot = poi - side * (poi - a).dot(side);
            face = Collision{*t, poi, side, foot + side * segmentRadius, false};
        }
        // A face hit comes first: a cap is never nearer than the line through it.
        if (face) return face;
    }
    // The line caps: circles of the segment's radius at both ends (zero for the lecture's line).
    std::optional<Collision> cap = circleCircleCollision(circle, a, segmentRadius, horizon, rule);
    if (length > 0.0) {
        const std::optional<Collision> capB = circleCircleCollision(circle, b, segmentRadius, horizon, rule);
        if (capB && (!cap || capB->timeOfImpact < cap->timeOfImpact)) cap = capB;
    }
    if (cap) cap->lineCap = true;
    return cap;
}

} // namespace rube
