// A bounce never adds energy: restitution against fixed things is scaled back to the energy the body
// began the step with.
//
// Restitution drives each point's normal speed to C times its approach (v' = -C vn, lecture 3), from
// the velocities the substeps left. Those already hold what friction and the soft push-out did in
// the step, and a body turning fast turns a corner's push into spin and the spin into speed along
// the floor (a capsule landing almost flat skids off faster than it came). Against fixed things no
// force but gravity does work, so E_end = KE' + PE_end <= KE_0 + PE_0 must hold for C <= 1: when
// restitution's change du would break it, only the fraction s of du that keeps it is applied.
#include "rigid_stage.hpp"

#include <algorithm>
#include <cmath>

namespace rube {

namespace {

/// Kinetic energy m v^2 / 2 + I omega^2 / 2 of a rigid state (its masses are inverses; 0 is infinite).
double kineticEnergy(const RigidState& s, Vec2 v, double omega) {
    double e = 0.5 * v.lengthSquared() / s.inverseMass;
    if (s.inverseInertia > 0.0) e += 0.5 * omega * omega / s.inverseInertia;
    return e;
}

/// True when the side neither moves nor can be moved: a fixed segment, circle or body.
bool isFixed(const RigidSolverView& view, BodySide side) {
    const LoadedBody l = load(view, side);
    return l.inverseMass == 0.0 && l.inverseInertia == 0.0 && l.velocity.x == 0.0 && l.velocity.y == 0.0 && l.omega == 0.0;
}

} // namespace

void RigidStage::capBounceEnergy() {
    const std::size_t n = states_.size();
    onlyFixed_.assign(n, 1);
    bool bounced = false;
    for (const RigidContact& c : contacts_) {
        if (c.bounciness > 0.0) bounced = true;
        if (isFixed(view_, c.b)) continue;
        onlyFixed_[static_cast<std::size_t>(c.a.index)] = 0;
        if (c.b.rigid) onlyFixed_[static_cast<std::size_t>(c.b.index)] = 0;
    }
    if (!bounced) return;
    for (std::size_t i = 0; i < n; ++i) {
        RigidState& s = states_[i];
        const RigidState& before = beforeBounce_[i];
        if (!onlyFixed_[i] || s.inverseMass == 0.0) continue;
        const Vec2 dv = s.velocity - before.velocity;
        const double dw = s.omega - before.omega;
        if (dv.x == 0.0 && dv.y == 0.0 && dw == 0.0) continue;
        // E = KE + m (-g) . x: the energy it began with, less the potential energy where it ends.
        const double m = 1.0 / s.inverseMass;
        const Vec2 end = startPosition_[i] + s.displacement;
        const double budget = kineticEnergy(s, startVelocity_[i], startOmega_[i]) - m * gravity_.dot(startPosition_[i]) +
                               m * gravity_.dot(end);
        if (kineticEnergy(s, s.velocity, s.omega) <= budget) continue;
        // KE(s) = KE0 + B s + A s^2 along before + s du: the largest s in [0, 1] within the budget,
        // or (already over it before the bounce) the s that adds least.
        const double inertia = s.inverseInertia > 0.0 ? 1.0 / s.inverseInertia : 0.0;
        const double a = 0.5 * (m * dv.lengthSquared() + inertia * dw * dw);
        const double b = m * before.velocity.dot(dv) + inertia * before.omega * dw;
        const double ke0 = kineticEnergy(s, before.velocity, before.omega);
        double scale = std::clamp(-b / (2.0 * a), 0.0, 1.0);
        if (ke0 <= budget) {
            // The larger root of A s^2 + B s + (KE0 - budget) = 0; KE0 - budget <= 0 keeps it real.
            const double c = ke0 - budget;
            scale = std::clamp((-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a), 0.0, 1.0);
        }
        s.velocity = before.velocity + dv * scale;
        s.omega = before.omega + dw * scale;
    }
}

} // namespace rube
