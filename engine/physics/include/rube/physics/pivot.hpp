#pragma once
/// Pivots: a rigid body pinned at one of its points to a fixed point of the world, free to turn
/// about it (a revolute joint to the world: a seesaw on its fulcrum, a pendulum bar, a swing door).
/// Only the solver (and auto, which gives such steps to the solver) models pivots.

#include "rube/physics/handles.hpp"
#include "rube/physics/vec2.hpp"

namespace rube {

/// What a caller fills in to add a pivot: which body, pinned where.
struct PivotDef {
    BodyId body;      ///< the rigid body
    Vec2 localAnchor; ///< the pinned point in the body's own frame (relative to its centre, angle 0), m
    Vec2 worldAnchor; ///< the fixed point of the world it is pinned to, m
};

/// A pivot in the world.
struct Pivot {
    int body = -1;    ///< slot (World::bodies()) of the rigid body, -1 while the pivot waits
    BodyId bodyId;    ///< the rigid body
    Vec2 localAnchor; ///< in the body's frame, m
    Vec2 worldAnchor; ///< in the world, m
};

} // namespace rube
