#pragma once
// Internal: the world's guards against motion the solver cannot resolve (issue 27). Speeds are
// clamped per step as Box2D clamps them; a body whose state still goes non-finite is frozen where it
// last was finite, so one unstable body can never corrupt the others. Not part of the public API.

#include "rube/physics/world.hpp"

#include <span>
#include <vector>

namespace rube {

/// Where each body last was finite, so a body that goes non-finite can be frozen there.
struct FiniteSnapshot {
    std::vector<Vec2> circlePositions;
    std::vector<Vec2> bodyPositions;
    std::vector<double> bodyAngles;
};

/// Cuts |velocity| to speedLimit and |omega| to spinLimit, keeping their directions; true when it cut either.
bool clampRigidMotion(Vec2& velocity, double& omega, double speedLimit, double spinLimit);

/// solver and auto: cuts every dynamic rigid body's speed to def.maxTranslation / dt and every turning
/// one's spin to def.maxRotation / dt, counting each body cut in stats.speedClamps (circles, which the
/// solver sweeps, only past a runaway's speed). Call it after isolateNonFinite: it assumes finite states.
void limitSpeeds(std::span<Circle> circles, std::span<RigidBody> bodies, const WorldDef& def, StepStats& stats);

/// What isolateNonFinite records after a step, for a step that changed no state (World::stepQuietly).
void recordFinitePoses(std::span<const Circle> circles, std::span<const RigidBody> bodies, FiniteSnapshot& snapshot);

/// Freezes every body whose state is not finite: back where it was last finite, fixed (infinite
/// mass, so no contact or rope moves it and it moves nothing by its own velocity), velocity and spin
/// zero; counted in stats.isolatedBodies (the first one named) and stats.nonFinite set. With `record`
/// (after a step) it then records every body's pose into `snapshot`; before a step only what a caller
/// changed is checked. Returns true when it isolated something.
bool isolateNonFinite(std::span<Circle> circles, std::span<RigidBody> bodies, FiniteSnapshot& snapshot,
                      StepStats& stats, bool record);

} // namespace rube
