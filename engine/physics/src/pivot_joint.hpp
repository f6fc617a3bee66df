#pragma once
// Internal: pivots (revolute joints to the world) solved softly in the solver's substeps.
// Not part of the public API.
//
// A pivot holds the body's point p + r (r its anchor turned with the body) on the world anchor:
// C = p + r - anchor = 0, so the point's velocity Cdot = v + omega x r must vanish. An impulse P at
// r changes it by K P with
//     K = [ 1/m + r.y^2 / I    -r.x r.y / I  ]
//         [ -r.x r.y / I       1/m + r.x^2 / I ],
// and the soft solve (Catto, "Soft Constraints") asks K P = -(Cdot + biasRate C) scaled by the
// spring's mass scale, less a part of the impulse so far (Box2D v3's revolute joint).

#include "rigid_solver_body.hpp"
#include "rube/physics/pivot.hpp"
#include "rube/physics/rigid_body.hpp"

#include <span>
#include <vector>

namespace rube {

/// A pivot during one step.
struct PivotConstraint {
    int body = 0;    ///< rigid body index
    Vec2 arm;        ///< anchor from the body's centre at the step's start, m
    Vec2 startError; ///< p + r - anchor at the step's start, m
    Vec2 impulse;    ///< of the current substep, warm starts the next (and the next step)
};

/// Fills `out` for `pivots` on `bodies` as they stand at the step's start; impulses carried over
/// from `out` when its pivots are the same.
void preparePivots(std::span<const Pivot> pivots, std::span<const RigidBody> bodies, std::vector<PivotConstraint>& out);

/// Applies every pivot's last impulse again (warm starting).
void warmStartPivots(std::span<const PivotConstraint> pivots, const RigidSolverView& view);

/// One Gauss-Seidel sweep over the pivots: soft position feedback when `useBias`.
void solvePivots(std::span<PivotConstraint> pivots, const RigidSolverView& view, const Softness& softness,
                 bool useBias);

} // namespace rube
