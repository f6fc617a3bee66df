// Speed limits and isolation of non-finite bodies (issue 27).
//
// Why clamp: the solver integrates each substep from the contact manifold of the step's start.
// A body that turns by more than a fraction of a turn in one step, or crosses metres, has left
// the configuration those contacts describe; wedged in a corner, the position correction then feeds
// spin back in every step (a capsule climbed from 173 to 241,206 rad/s before its neighbours went
// NaN). Box2D bounds the same two things per step (b2_maxTranslation = 2 m, b2_maxRotation =
// 0.25 pi in v3): |v| dt <= maxTranslation, |omega| dt <= maxRotation. A clamp scales the vector
// and keeps its direction, so momentum's direction is kept and only its size is lost.
//
// Why isolate: the clamps bound what can be bounded, but a state may still overflow (a field's
// kick on a body of tiny mass, a caller's NaN). Such a body is frozen at its last finite pose with
// infinite mass: impulses against an infinite mass give it no velocity and share nothing back
// through its own (zero) velocity, so no NaN reaches its neighbours.
#include "speed_limits.hpp"

#include <algorithm>
#include <cmath>

namespace rube {

namespace {

/// The most radii a circle may cross in one step under the solver: ten times the sweep's tested range.
constexpr double kCircleRadiiPerStep = 1e5;

bool finiteCircle(const Circle& c) {
    return isFinite(c.position) && isFinite(c.velocity) && std::isfinite(c.angle) && std::isfinite(c.angularVelocity);
}

bool finiteBody(const RigidBody& b) {
    return isFinite(b.position) && isFinite(b.velocity) && std::isfinite(b.angle) && std::isfinite(b.angularVelocity);
}

void noteIsolated(StepStats& stats, Other kind, std::size_t index) {
    stats.nonFinite = true;
    if (stats.isolatedBodies++ == 0) {
        stats.firstIsolatedKind = kind;
        stats.firstIsolated = static_cast<int>(index);
    }
}

void freezeCircle(Circle& c, Vec2 lastFinite) {
    c.position = isFinite(c.position) ? c.position : lastFinite;
    if (!std::isfinite(c.angle)) c.angle = 0.0;
    c.velocity = {};
    c.angularVelocity = 0.0;
    c.inverseMass = 0.0;
    c.inverseInertia = 0.0;
    c.motion = Motion::fixed;
    c.path = -1;
    c.sleep = SleepState{};
}

void freezeBody(RigidBody& b, Vec2 lastPosition, double lastAngle) {
    if (!isFinite(b.position) || !std::isfinite(b.angle)) {
        b.position = lastPosition;
        b.angle = lastAngle;
    }
    b.velocity = {};
    b.angularVelocity = 0.0;
    b.inverseMass = 0.0;
    b.inverseInertia = 0.0;
    b.motion = Motion::fixed;
}

/// Scales v down to `limit` in length; true when it had to.
bool clampLength(Vec2& v, double limit) {
    const double speedSquared = v.lengthSquared();
    if (!(speedSquared > limit * limit)) return false;
    v = v * (limit / std::sqrt(speedSquared));
    return true;
}

bool clampMagnitude(double& x, double limit) {
    if (!(std::abs(x) > limit)) return false;
    x = std::copysign(limit, x);
    return true;
}

} // namespace

bool clampRigidMotion(Vec2& velocity, double& omega, double speedLimit, double spinLimit) {
    const bool linear = clampLength(velocity, speedLimit);
    return clampMagnitude(omega, spinLimit) || linear;
}

void limitSpeeds(std::span<Circle> circles, std::span<RigidBody> bodies, const WorldDef& def, const FiniteSnapshot& snapshot,
                 StepStats& stats) {
    const double dt = def.timeStep;
    const double speedLimit = def.maxTranslation / dt, spinLimit = def.maxRotation / dt;
    // Circles are clamped only far past what the solver resolves: it sweeps a fast circle (no
    // tunnelling up to 10,000 radii a step, failure_boundaries_test), and a circle's contact never
    // depends on its angle. What is left is a runaway, e.g. a 3 mg ball kicked by a pool's buoyancy.
    for (std::size_t i = 0; i < circles.size(); ++i) {
        Circle& c = circles[i];
        if (c.motion != Motion::dynamic) continue;
        if (!finiteCircle(c)) {
            noteIsolated(stats, Other::circle, i);
            freezeCircle(c, i < snapshot.circlePositions.size() ? snapshot.circlePositions[i] : Vec2{});
            continue;
        }
        // Only a runaway: kCircleStepsPerRadius radii a step, ten times the fastest the tests sweep.
        stats.speedClamps += clampLength(c.velocity, std::max(speedLimit, kCircleRadiiPerStep * c.radius / dt));
    }
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        RigidBody& b = bodies[i];
        if (b.motion != Motion::dynamic) continue;
        if (!finiteBody(b)) {
            noteIsolated(stats, Other::body, i);
            freezeBody(b, i < snapshot.bodyPositions.size() ? snapshot.bodyPositions[i] : Vec2{},
                       i < snapshot.bodyAngles.size() ? snapshot.bodyAngles[i] : 0.0);
            continue;
        }
        stats.speedClamps += clampRigidMotion(b.velocity, b.angularVelocity, speedLimit, b.inverseInertia > 0.0 ? spinLimit : 1e300);
    }
}

bool isolateNonFinite(std::span<Circle> circles, std::span<RigidBody> bodies, FiniteSnapshot& snapshot, StepStats& stats) {
    const std::int64_t before = stats.isolatedBodies;
    snapshot.circlePositions.resize(circles.size());
    for (std::size_t i = 0; i < circles.size(); ++i) {
        Circle& c = circles[i];
        if (!finiteCircle(c)) {
            noteIsolated(stats, Other::circle, i);
            freezeCircle(c, snapshot.circlePositions[i]);
        }
        snapshot.circlePositions[i] = c.position;
    }
    snapshot.bodyPositions.resize(bodies.size());
    snapshot.bodyAngles.resize(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        RigidBody& b = bodies[i];
        if (!finiteBody(b)) {
            noteIsolated(stats, Other::body, i);
            freezeBody(b, snapshot.bodyPositions[i], snapshot.bodyAngles[i]);
        }
        snapshot.bodyPositions[i] = b.position;
        snapshot.bodyAngles[i] = b.angle;
    }
    return stats.isolatedBodies != before;
}

} // namespace rube
