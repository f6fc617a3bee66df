// Times of impact on trajectories that are not polynomials (see exact_spring_impacts.hpp).
//
// Conservative advancement with a second-order bound: with g(t) the gap (distance minus the radii),
// |g''| <= M = V^2 / R + A while the bodies do not overlap, V and A bounds on the relative speed
// and acceleration, R the radius sum (the distance's curvature term |v_perp|^2 / |d| with |d| >= R).
// So g(t + s) >= g + g' s - M s^2 / 2, whose first positive root
//     s = 2 g / (sqrt(g'^2 + 2 M g) - g')
// is a step that cannot pass the first root of g. Far from contact it is the first-order step
// g / |g'| or sqrt(2 g / M); near an approaching root (g' < 0) it is Newton's step less O(g^2), so
// the advancement converges on the root from before it, quadratically, to round-off.
#include "exact_spring_impacts.hpp"

#include "rube/physics/collision.hpp"

#include <algorithm>
#include <cmath>

namespace rube {

namespace {

/// Steps of the advancement before it gives up (never reached but by a pathological tangency).
constexpr int kMaxSteps = 10000;
/// The gap counted as touching, relative to the coordinates' size: well above the round-off of
/// |d| - R (a few 1e-16 of the coordinates), far below anything visible. At an approach of 0.1 m/s
/// it puts the time of impact 1e-11 s early.
constexpr double kTouchingGap = 1e-12;

struct GapSample {
    double gap = 0.0;  ///< distance minus the radii, m
    double rate = 0.0; ///< its derivative, m/s (negative approaching)
    Vec2 centre;       ///< the circle's centre
    Vec2 normal;       ///< from the other towards the circle
    Vec2 contact;      ///< on the other's surface
    bool cap = false;
};

template <class GapAt>
std::optional<Collision> firstContact(const GapAt& gapAt, double curvature, double touching, double horizon) {
    double t = 0.0;
    for (int k = 0; k < kMaxSteps; ++k) {
        const GapSample g = gapAt(t);
        if (g.gap <= touching && g.rate < 0.0) return Collision{t, g.centre, g.normal, g.contact, g.cap};
        double s = 0.0;
        if (g.gap > touching) {
            const double denominator = std::sqrt(g.rate * g.rate + 2.0 * curvature * g.gap) - g.rate;
            if (!(denominator > 0.0)) return std::nullopt; // no curvature and separating: never
            s = 2.0 * g.gap / denominator;
        } else {
            // Touching (or overlapping) and separating: the gap cannot come back below where it
            // is before g' s - M s^2 / 2 turns negative, at s = 2 g' / M.
            if (!(curvature > 0.0)) return std::nullopt;
            s = 2.0 * g.rate / curvature;
        }
        // Progress however small the step (a tangency): a nanometre's worth of the horizon.
        t += std::max(s, 1e-12 * horizon);
        if (!(t <= horizon)) return std::nullopt;
    }
    return std::nullopt;
}

double curvatureBound(double speed, double acceleration, double radiusSum) {
    return speed * speed / std::max(radiusSum, 1e-9) + acceleration;
}

} // namespace

void Trajectory::at(double t, Vec2& p, Vec2& v) const {
    p = position;
    v = velocity;
    if (spring) {
        springMove(*spring, p, v, t);
        return;
    }
    p += velocity * t + acceleration * (0.5 * t * t);
    v += acceleration * t;
}

Trajectory parabolaTrajectory(Vec2 position, Vec2 velocity, Vec2 acceleration, double horizon) {
    Trajectory path{position, velocity, acceleration};
    path.speedBound = velocity.length() + acceleration.length() * horizon;
    path.accelerationBound = acceleration.length();
    return path;
}

Trajectory springTrajectory(const SpringPath& spring, Vec2 position, Vec2 velocity) {
    Trajectory path{position, velocity, {}, &spring};
    path.speedBound = springSpeedBound(spring, position, velocity);
    path.accelerationBound = spring.omega * path.speedBound * (1.0 + 2.0 * spring.zeta);
    return path;
}

std::optional<Collision> trajectoryCircleCollision(const Trajectory& circle, double radius, const Trajectory& other,
                                                   double otherRadius, double horizon) {
    const double radiusSum = radius + otherRadius;
    const auto gapAt = [&](double t) {
        Vec2 p, v, q, w;
        circle.at(t, p, v);
        other.at(t, q, w);
        const Vec2 d = p - q;
        const double distance = d.length();
        GapSample g;
        g.normal = distance > 0.0 ? d * (1.0 / distance) : Vec2{0.0, 1.0};
        g.gap = distance - radiusSum;
        g.rate = g.normal.dot(v - w);
        g.centre = p;
        g.contact = q + g.normal * otherRadius;
        return g;
    };
    const double curvature = curvatureBound(circle.speedBound + other.speedBound,
                                            circle.accelerationBound + other.accelerationBound, radiusSum);
    const double touching = kTouchingGap * (1.0 + circle.position.length() + other.position.length());
    return firstContact(gapAt, curvature, touching, horizon);
}

std::optional<Collision> trajectorySegmentCollision(const Trajectory& circle, double radius, Vec2 a, Vec2 b,
                                                    Vec2 segmentVelocity, double segmentRadius, double horizon) {
    const double radiusSum = radius + segmentRadius;
    const Vec2 ab = b - a;
    const double lengthSquared = ab.lengthSquared();
    const auto gapAt = [&](double t) {
        Vec2 p, v;
        circle.at(t, p, v);
        const Vec2 shift = segmentVelocity * t;
        // The closest point of the segment, by the lecture's clamped scalar projection.
        const double along = lengthSquared > 0.0 ? (p - a - shift).dot(ab) / lengthSquared : 0.0;
        const double clamped = std::clamp(along, 0.0, 1.0);
        const Vec2 q = a + shift + ab * clamped;
        const Vec2 d = p - q;
        const double distance = d.length();
        GapSample g;
        g.normal = distance > 0.0 ? d * (1.0 / distance) : ab.normal();
        g.gap = distance - radiusSum;
        g.rate = g.normal.dot(v - segmentVelocity);
        g.centre = p;
        g.contact = q + g.normal * segmentRadius;
        g.cap = along <= 0.0 || along >= 1.0;
        return g;
    };
    const double curvature = curvatureBound(circle.speedBound + segmentVelocity.length(), circle.accelerationBound,
                                            radiusSum);
    const double touching = kTouchingGap * (1.0 + circle.position.length() + a.length() + b.length());
    return firstContact(gapAt, curvature, touching, horizon);
}

} // namespace rube
