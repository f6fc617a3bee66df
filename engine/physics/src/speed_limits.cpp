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

// x - x is 0 for every finite x and NaN for an infinity or a NaN, so one sum tests six numbers with
// one compare and no branch per number (this runs twice a step over every body; exact in IEEE, and
// -ffast-math, which could fold x - x to 0, is refused by the build).
bool allFinite(Vec2 p, Vec2 v, double angle, double omega) {
    const double zero = (p.x - p.x) + (p.y - p.y) + (v.x - v.x) + (v.y - v.y) + (angle - angle) + (omega - omega);
    return zero == 0.0;
}

void recordPoses(std::span<const Circle> circles, std::span<const RigidBody> bodies, FiniteSnapshot& snapshot) {
    for (std::size_t i = 0; i < circles.size(); ++i) snapshot.circlePositions[i] = circles[i].position;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        snapshot.bodyPositions[i] = bodies[i].position;
        snapshot.bodyAngles[i] = bodies[i].angle;
    }
}

bool finiteCircle(const Circle& c) { return allFinite(c.position, c.velocity, c.angle, c.angularVelocity); }

bool finiteBody(const RigidBody& b) { return allFinite(b.position, b.velocity, b.angle, b.angularVelocity); }

// Every body finite, as one sum of x - x over all of them: NaN if any number is not finite.
bool allBodiesFinite(std::span<const Circle> circles, std::span<const RigidBody> bodies) {
    double zero = 0.0;
    for (const Circle& c : circles)
        zero += (c.position.x - c.position.x) + (c.position.y - c.position.y) + (c.velocity.x - c.velocity.x) +
                (c.velocity.y - c.velocity.y) + (c.angle - c.angle) + (c.angularVelocity - c.angularVelocity);
    for (const RigidBody& b : bodies)
        zero += (b.position.x - b.position.x) + (b.position.y - b.position.y) + (b.velocity.x - b.velocity.x) +
                (b.velocity.y - b.velocity.y) + (b.angle - b.angle) + (b.angularVelocity - b.angularVelocity);
    return zero == 0.0;
}

void noteIsolated(StepStats& stats, Other kind, std::size_t index) {
    stats.nonFinite = true;
    if (stats.isolatedBodies++ == 0) {
        stats.firstIsolatedKind = kind;
        stats.firstIsolatedSlot = static_cast<int>(index);
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

void limitSpeeds(std::span<Circle> circles, std::span<RigidBody> bodies, const WorldDef& def, StepStats& stats) {
    const double dt = def.timeStep;
    const double speedLimit = def.maxTranslation / dt, spinLimit = def.maxRotation / dt;
    // Circles are clamped only far past what the solver resolves: it sweeps a fast circle (no
    // tunnelling up to 10,000 radii a step, failure_boundaries_test), and a circle's contact never
    // depends on its angle. What is left is a runaway, e.g. a 3 mg ball kicked by a pool's buoyancy:
    // kCircleRadiiPerStep radii a step, ten times the fastest the tests sweep.
    for (Circle& c : circles)
        if (c.motion == Motion::dynamic)
            stats.speedClamps += clampLength(c.velocity, std::max(speedLimit, kCircleRadiiPerStep * c.radius / dt));
    for (RigidBody& b : bodies)
        if (b.motion == Motion::dynamic)
            stats.speedClamps += clampRigidMotion(b.velocity, b.angularVelocity, speedLimit,
                                                  b.inverseInertia > 0.0 ? spinLimit : 1e300);
}

void recordFinitePoses(std::span<const Circle> circles, std::span<const RigidBody> bodies, FiniteSnapshot& snapshot) {
    snapshot.circlePositions.resize(circles.size());
    snapshot.bodyPositions.resize(bodies.size());
    snapshot.bodyAngles.resize(bodies.size());
    recordPoses(circles, bodies, snapshot);
}

bool isolateNonFinite(std::span<Circle> circles, std::span<RigidBody> bodies, FiniteSnapshot& snapshot,
                      StepStats& stats, bool record) {
    const std::int64_t before = stats.isolatedBodies;
    // A world that gained bodies since the last record has no last pose for them yet: record now.
    record = record || snapshot.circlePositions.size() != circles.size() ||
             snapshot.bodyPositions.size() != bodies.size();
    snapshot.circlePositions.resize(circles.size());
    snapshot.bodyPositions.resize(bodies.size());
    snapshot.bodyAngles.resize(bodies.size());
    if (allBodiesFinite(circles, bodies)) { // the common case: one branch-free pass, then the copy
        if (record) recordPoses(circles, bodies, snapshot);
        return false;
    }
    for (std::size_t i = 0; i < circles.size(); ++i) {
        Circle& c = circles[i];
        if (!finiteCircle(c)) {
            noteIsolated(stats, Other::circle, i);
            freezeCircle(c, snapshot.circlePositions[i]);
        }
        if (record) snapshot.circlePositions[i] = c.position;
    }
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        RigidBody& b = bodies[i];
        if (!finiteBody(b)) {
            noteIsolated(stats, Other::body, i);
            freezeBody(b, snapshot.bodyPositions[i], snapshot.bodyAngles[i]);
        }
        if (record) {
            snapshot.bodyPositions[i] = b.position;
            snapshot.bodyAngles[i] = b.angle;
        }
    }
    return stats.isolatedBodies != before;
}

} // namespace rube
