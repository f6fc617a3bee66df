// Aiming and shooting: closed forms where the course gives one (the ballistic equation, the lead
// quadratic), the quartic root finder of the times of impact where it does not (leading under gravity).
#include "rube/physics/aim.hpp"

#include "polynomial.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace rube {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// Real roots of a t^2 + b t + c = 0 in increasing order; returns how many. The abc formula without
// cancellation: q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2, roots q / a and c / q. a = 0 is the linear case.
int solveQuadratic(double a, double b, double c, std::array<double, 2>& roots) {
    if (a == 0.0) {
        if (b == 0.0) return 0;
        roots[0] = -c / b;
        return 1;
    }
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return 0;
    if (discriminant == 0.0) {
        roots[0] = -b / (2.0 * a);
        return 1;
    }
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    roots[0] = q / a;
    roots[1] = c / q;
    if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
    return 2;
}

// A shot along `velocity` at exactly the muzzle speed (the velocity found by a solver has it to round-off).
Shot shotAlong(Vec2 velocity, double muzzleSpeed) {
    Shot shot;
    shot.direction = velocity.normalized();
    shot.angle = shot.direction.angle();
    shot.velocity = shot.direction * muzzleSpeed;
    return shot;
}

// The launch velocity that puts the projectile at muzzle + d after t seconds: d = v t + g t^2 / 2.
Vec2 launchVelocity(Vec2 d, Vec2 gravity, double t) { return d / t - gravity * (0.5 * t); }

Arc arcOf(Vec2 d, Vec2 gravity, double muzzleSpeed, double t) {
    return Arc{shotAlong(launchVelocity(d, gravity, t), muzzleSpeed), t};
}

std::string outOfReach(double needed, double muzzleSpeed) {
    char text[128];
    std::snprintf(text, sizeof text, "target out of reach: needs at least %.3f m/s, muzzle speed is %.3f m/s", needed,
                  muzzleSpeed);
    return text;
}

} // namespace

Shot aimInDirection(double angle, double muzzleSpeed) {
    Shot shot;
    shot.direction = Vec2::fromAngle(angle);
    shot.angle = angle;
    shot.velocity = shot.direction * muzzleSpeed;
    return shot;
}

std::optional<Shot> aimAtTarget(Vec2 muzzle, Vec2 target, double muzzleSpeed) {
    const Vec2 d = target - muzzle;
    if (d == Vec2{}) return std::nullopt;
    return shotAlong(d, muzzleSpeed);
}

GravityShot aimGravityShot(Vec2 muzzle, Vec2 target, double muzzleSpeed, Vec2 gravity) {
    // The course's tan(theta) = (s^2 +- sqrt(s^4 - g (g x^2 + 2 y s^2))) / (g x) needs the frame where
    // gravity is -y. Eliminating the angle instead works in any frame: the projectile is at d after t
    // when |d - g t^2 / 2| = s t, so with T = t^2:
    //   (|g|^2 / 4) T^2 - (s^2 + d.g) T + |d|^2 = 0,  discriminant D = (s^2 + d.g)^2 - |g|^2 |d|^2,
    // which for g = (0, -g) is s^4 - g (g x^2 + 2 y s^2), the same square root as the course's formula;
    // its two roots are the low (earlier) and the high (later) arc.
    GravityShot out;
    const Vec2 d = target - muzzle;
    const double distance = d.length();
    const double g = gravity.length();
    const double dg = d.dot(gravity);
    // D = (s^2 + d.g - |g||d|)(s^2 + d.g + |g||d|) is zero at s_min^2 = |g||d| - d.g = g (y + sqrt(x^2 + y^2)).
    out.minimumSpeed = std::sqrt(std::max(0.0, g * distance - dg));
    if (distance == 0.0) {
        out.reason = "target is at the muzzle: there is no direction to aim in";
        return out;
    }
    if (!(muzzleSpeed > 0.0)) {
        out.reason = outOfReach(out.minimumSpeed, muzzleSpeed) + " (a shot needs a positive muzzle speed)";
        return out;
    }
    const double s2 = muzzleSpeed * muzzleSpeed;
    const double b = s2 + dg;
    const double aboveMinimum = b - g * distance; // s^2 - s_min^2, the factor that decides reachability
    // Round-off in s^2, d.g and |g||d|: within it the muzzle speed is the minimum one and D is 0.
    const double tolerance = 8.0 * kEpsilon * (s2 + std::fabs(dg) + g * distance);
    if (aboveMinimum < -tolerance) {
        out.reason = outOfReach(out.minimumSpeed, muzzleSpeed);
        return out;
    }
    const double discriminant = aboveMinimum <= tolerance ? 0.0 : aboveMinimum * (b + g * distance);
    const bool single = discriminant == 0.0 || g == 0.0; // one arc: the minimum speed, or a straight line
    // q > 0 because s^2 + d.g >= |g||d| >= 0 here. T_high = 2q / |g|^2 and T_low = 2 |d|^2 / q (the
    // product of the roots is 4 |d|^2 / |g|^2): both without cancellation, and T_low = |d|^2 / s^2 at g = 0.
    const double q = b + std::sqrt(discriminant);
    out.lowArc = arcOf(d, gravity, muzzleSpeed, distance * std::sqrt(2.0 / q));
    if (!single) out.highArc = arcOf(d, gravity, muzzleSpeed, std::sqrt(2.0 * q) / g);
    return out;
}

std::optional<Intercept> leadMovingTarget(Vec2 muzzle, Vec2 target, Vec2 targetVelocity, double muzzleSpeed,
                                          Vec2 gravity, double maxTime) {
    const Vec2 d = target - muzzle;
    const Vec2 v = targetVelocity;
    if (!(muzzleSpeed > 0.0) || d == Vec2{}) return std::nullopt;
    const double s2 = muzzleSpeed * muzzleSpeed;
    double time = 0.0;
    if (gravity == Vec2{}) {
        // |d + v t| = s t squared: (|v|^2 - s^2) t^2 + 2 (d.v) t + |d|^2 = 0; the smallest positive root.
        std::array<double, 2> roots{};
        const int count = solveQuadratic(v.dot(v) - s2, 2.0 * d.dot(v), d.dot(d), roots);
        const auto first = std::find_if(roots.begin(), roots.begin() + count, [](double t) { return t > 0.0; });
        if (first == roots.begin() + count || *first > maxTime) return std::nullopt;
        time = *first;
    } else {
        // |d + v t + w t^2|^2 - s^2 t^2 = 0 with w = -g / 2: a quartic, positive at t = 0 (|d|^2) and at
        // infinity (|w|^2 t^4). Its roots lie below Cauchy's bound 1 + max |c_i / c_4|, so the bracketed
        // search of the times of impact (isolate by the derivative's roots, refine the first sign change)
        // finds the earliest one on (0, min(maxTime, bound)]. A root where the quartic only touches zero
        // (the target grazing the edge of reach) has no sign change and is not found.
        const Vec2 w = gravity * -0.5;
        const Polynomial p{{d.dot(d), 2.0 * d.dot(v), v.dot(v) + 2.0 * d.dot(w) - s2, 2.0 * v.dot(w), w.dot(w)}};
        double bound = 0.0;
        for (int i = 0; i < 4; ++i) bound = std::max(bound, std::fabs(p.c[i] / p.c[4]));
        const std::optional<double> root = earliestRoot(p, 0.0, std::min(maxTime, 1.0 + bound), true);
        if (!root || !(*root > 0.0)) return std::nullopt;
        time = *root;
    }
    Intercept out;
    out.time = time;
    out.pointOfImpact = target + v * time;
    out.shot = shotAlong(launchVelocity(d + v * time, gravity, time), muzzleSpeed);
    return out;
}

ShotTiming timeFixedAngleShot(Vec2 muzzle, Vec2 direction, double muzzleSpeed, Vec2 target, Vec2 targetVelocity,
                              Vec2 gravity) {
    // Fired after `delay`, the projectile meets the target after a flight of `sigma` when
    //   u sigma + g sigma^2 / 2 = d + v (delay + sigma),   u = s * direction, d = target - muzzle.
    // Two equations, two unknowns. The part across v has no delay in it:
    //   n.(g / 2) sigma^2 + n.u sigma - n.d = 0,   n = v rotated a quarter turn,
    // and the part along v then gives delay = v.(u sigma + g sigma^2 / 2 - v sigma - d) / |v|^2.
    ShotTiming out;
    const Vec2 u = direction.normalized() * muzzleSpeed;
    const Vec2 d = target - muzzle;
    const Vec2 v = targetVelocity;
    if (u == Vec2{}) {
        out.reason = "the shot needs a direction and a positive muzzle speed";
        return out;
    }
    auto relativeMiss = [&](double sigma, double delay) { // where the projectile is, seen from the target
        return u * sigma + gravity * (0.5 * sigma * sigma) - d - v * (delay + sigma);
    };
    // A root counts only if the full 2-D miss vanishes to round-off: this rejects the spurious roots of the
    // one-dimensional equations used below (for a target standing still, the part along the shot).
    const double scale = std::max({1.0, d.length(), u.length(), v.length(), gravity.length()});
    auto accept = [&](double sigma, double delay) {
        if (!(sigma >= 0.0 && delay >= 0.0) || (out.possible && delay >= out.delay)) return;
        if (relativeMiss(sigma, delay).length() > 1e-9 * scale * std::max(1.0, sigma * sigma + delay)) return;
        out.possible = true;
        out.delay = delay;
        out.flightTime = sigma;
        out.pointOfImpact = target + v * (delay + sigma);
    };

    std::array<double, 2> roots{};
    if (v == Vec2{}) {
        // A target standing still: the fixed shot either passes through it (any delay; 0 is returned) or never.
        const Vec2 n = u.perpendicular();
        int count = solveQuadratic(0.5 * n.dot(gravity), 0.0, -n.dot(d), roots);
        if (count == 0 && n.dot(d) == 0.0) // gravity along the shot: the motion is one-dimensional, along u
            count = solveQuadratic(0.5 * u.dot(gravity), u.dot(u), -u.dot(d), roots);
        for (int i = 0; i < count; ++i) accept(roots[i], 0.0);
        if (!out.possible) out.reason = "the target stands still and the fixed-angle shot never passes through it";
        return out;
    }
    const Vec2 n = v.perpendicular();
    const double a = 0.5 * n.dot(gravity), b = n.dot(u), c = -n.dot(d);
    const double delayPerMiss = 1.0 / v.dot(v);
    auto delayFor = [&](double sigma) {
        return v.dot(u * sigma + gravity * (0.5 * sigma * sigma) - v * sigma - d) * delayPerMiss;
    };
    if (a == 0.0 && b == 0.0) {
        // The shot flies along the target's line (no gravity across it): h(sigma) = |v| delay is one
        // equation in two unknowns. The smallest delay: fire now if that ever hits, else the least
        // delay over sigma > 0 (at the vertex of h, or sigma -> 0 where the target reaches the muzzle).
        if (c != 0.0) {
            out.reason = "the shot flies parallel to the target's path and never crosses it";
            return out;
        }
        const Vec2 along = v * std::sqrt(delayPerMiss);
        const int count = solveQuadratic(0.5 * along.dot(gravity), along.dot(u - v), -along.dot(d), roots);
        for (int i = 0; i < count; ++i) accept(roots[i], 0.0);
        if (!out.possible) {
            const double vertex = along.dot(gravity) > 0.0 ? -along.dot(u - v) / along.dot(gravity) : 0.0;
            const double sigma = std::max(0.0, vertex);
            accept(sigma, delayFor(sigma));
        }
    } else {
        const int count = solveQuadratic(a, b, c, roots);
        for (int i = 0; i < count; ++i) accept(roots[i], delayFor(roots[i]));
    }
    if (!out.possible)
        out.reason = "the fixed-angle shot cannot meet the target: its path never crosses the target's at a "
                     "time the target is there later than now";
    return out;
}

std::vector<Vec2> predictedArc(Vec2 position, Vec2 velocity, Vec2 gravity, double duration, int pointCount,
                               std::optional<Aabb> box) {
    std::vector<Vec2> points;
    if (pointCount < 1 || (box && !box->contains(position))) return points;
    auto at = [&](double t) { return position + velocity * t + gravity * (0.5 * t * t); }; // p + v t + g t^2 / 2
    points.reserve(static_cast<std::size_t>(pointCount));
    points.push_back(position);
    double previous = 0.0;
    for (int i = 1; i < pointCount; ++i) {
        const double t = duration * static_cast<double>(i) / static_cast<double>(pointCount - 1);
        if (box && !box->contains(at(t))) {
            // Bisect between the last point inside and the first outside: the arc's exit, to round-off.
            double inside = previous, outside = t;
            for (int k = 0; k < 200; ++k) {
                const double mid = inside + 0.5 * (outside - inside);
                if (!(mid > inside && mid < outside)) break;
                (box->contains(at(mid)) ? inside : outside) = mid;
            }
            points.push_back(at(inside));
            break;
        }
        points.push_back(at(t));
        previous = t;
    }
    return points;
}

} // namespace rube
