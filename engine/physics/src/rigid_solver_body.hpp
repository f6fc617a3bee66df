#pragma once
// Internal: how the rigid contacts and pivots see the bodies they act on during the solver's
// substeps. A rigid body carries its own state here; a circle or segment is the circle solver's
// SolverBody (the same velocities the circle contacts read and write, so balls and planks push
// each other), with the circle's omega when the step models rotation. Not part of the public API.

#include "solver_soft_step.hpp"

#include <cmath>
#include <span>

namespace rube {

/// A rigid body during one step of the solver (Box2D v3's body state: velocities, and the
/// displacement and turn since the step began, with the rotation of that turn).
struct RigidState {
    Vec2 velocity;
    double omega = 0.0;
    Vec2 displacement;           ///< m moved since the step began
    double turn = 0.0;           ///< radians turned since the step began
    Vec2 turnRotation{1.0, 0.0}; ///< (cos turn, sin turn)
    double inverseMass = 0.0;
    double inverseInertia = 0.0;
};

/// Whether a sweep may write a body: one that cannot move keeps its velocities bit for bit (its
/// velocity plus 0 p could turn -0 into +0), so contacts that share only such a body may be solved
/// at once (rigid_colours.hpp).
inline bool movableBody(const RigidState& s) { return s.inverseMass > 0.0 || s.inverseInertia > 0.0; }

/// One side of a rigid contact: rigid body `index`, or solver body `index` of the circle solver
/// (circles first, then segments).
struct BodySide {
    int index = 0;
    bool rigid = false;
};

/// Everything the substeps may touch: the rigid states and the circle solver's bodies.
struct RigidSolverView {
    std::span<RigidState> rigid;
    std::span<SolverBody> others;    ///< the circle solver's bodies: circles, then segments
    std::span<double> omega;         ///< per circle-solver body; empty when the step has no rotation
    std::span<const Circle> circles; ///< for the circles' inverse mass and inertia
};

/// A side's velocities and displacement, loaded for a constraint and stored back after it.
struct LoadedBody {
    Vec2 velocity;
    double omega = 0.0;
    Vec2 displacement;
    Vec2 turnRotation{1.0, 0.0};
    double inverseMass = 0.0;
    double inverseInertia = 0.0;
};

/// K^-1 rhs for the symmetric 2 x 2 K = [k11 k12; k12 k22] into `out`; false when K is singular.
inline bool solveSymmetric2x2(double k11, double k12, double k22, Vec2 rhs, Vec2& out) {
    const double det = k11 * k22 - k12 * k12;
    if (det == 0.0) return false;
    out = {(k22 * rhs.x - k12 * rhs.y) / det, (k11 * rhs.y - k12 * rhs.x) / det};
    return true;
}

/// Rotates r by the rotation (cos, sin) q.
inline Vec2 rotate(Vec2 q, Vec2 r) { return {q.x * r.x - q.y * r.y, q.y * r.x + q.x * r.y}; }

inline LoadedBody load(const RigidSolverView& view, BodySide side) {
    if (side.rigid) {
        const RigidState& s = view.rigid[static_cast<std::size_t>(side.index)];
        return {s.velocity, s.omega, s.displacement, s.turnRotation, s.inverseMass, s.inverseInertia};
    }
    const auto i = static_cast<std::size_t>(side.index);
    const SolverBody& b = view.others[i];
    LoadedBody l{b.velocity, 0.0, b.displacement, {1.0, 0.0}, 0.0, 0.0};
    if (i < view.circles.size()) {
        const Circle& c = view.circles[i];
        const bool movable = c.motion == Motion::dynamic && !c.sleep.asleep; // an asleep circle is fixed
        if (movable) l.inverseMass = c.inverseMass;
        // A circle's contact point stays where the normal meets its surface however it turns, so
        // its turn never moves an anchor; only its spin enters the point's velocity.
        if (!view.omega.empty()) {
            l.omega = view.omega[i];
            if (movable) l.inverseInertia = c.inverseInertia;
        }
    }
    return l;
}

inline void store(const RigidSolverView& view, BodySide side, const LoadedBody& l) {
    if (side.rigid) {
        RigidState& s = view.rigid[static_cast<std::size_t>(side.index)];
        s.velocity = l.velocity;
        s.omega = l.omega;
        return;
    }
    const auto i = static_cast<std::size_t>(side.index);
    view.others[i].velocity = l.velocity;
    if (!view.omega.empty() && i < view.circles.size()) view.omega[i] = l.omega;
}

/// The velocity of the body's point at arm r from its centre: v + omega x r.
inline Vec2 pointVelocity(const LoadedBody& b, Vec2 r) { return b.velocity + r.perpendicular() * b.omega; }

/// Applies impulse p at arm r: v += p / m, omega += (r x p) / I.
inline void applyImpulse(LoadedBody& b, Vec2 r, Vec2 p) {
    b.velocity += p * b.inverseMass;
    b.omega += b.inverseInertia * r.cross(p);
}

} // namespace rube
