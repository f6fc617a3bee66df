// Pivots: soft revolute point constraints to the world.
#include "pivot_joint.hpp"

#include <cmath>

namespace rube {

void preparePivots(std::span<const Pivot> pivots, std::span<const RigidBody> bodies,
                   std::vector<PivotConstraint>& out) {
    const bool same = out.size() == pivots.size();
    out.resize(pivots.size());
    for (std::size_t k = 0; k < pivots.size(); ++k) {
        const Pivot& pivot = pivots[k];
        PivotConstraint& c = out[k];
        if (!same || c.body != pivot.body) c.impulse = {};
        c.body = pivot.body;
        const RigidBody& body = bodies[static_cast<std::size_t>(pivot.body)];
        c.arm = rotate({std::cos(body.angle), std::sin(body.angle)}, pivot.localAnchor);
        c.startError = body.position + c.arm - pivot.worldAnchor;
    }
}

void warmStartPivots(std::span<const PivotConstraint> pivots, const RigidSolverView& view) {
    for (const PivotConstraint& c : pivots) {
        RigidState& s = view.rigid[static_cast<std::size_t>(c.body)];
        const Vec2 r = rotate(s.turnRotation, c.arm);
        s.velocity += c.impulse * s.inverseMass;
        s.omega += s.inverseInertia * r.cross(c.impulse);
    }
}

void solvePivots(std::span<PivotConstraint> pivots, const RigidSolverView& view, const Softness& softness,
                 bool useBias) {
    for (PivotConstraint& c : pivots) {
        RigidState& s = view.rigid[static_cast<std::size_t>(c.body)];
        const double m = s.inverseMass, i = s.inverseInertia;
        if (m == 0.0 && i == 0.0) continue;
        const Vec2 r = rotate(s.turnRotation, c.arm);
        const Vec2 cdot = s.velocity + r.perpendicular() * s.omega;
        Vec2 bias;
        double massScale = 1.0, impulseScale = 0.0;
        if (useBias) {
            // The error now: the start error plus how far the point moved (displacement, and the arm's turn).
            const Vec2 error = c.startError + s.displacement + (r - c.arm);
            bias = error * softness.biasRate;
            massScale = softness.massScale;
            impulseScale = softness.impulseScale;
        }
        const double k11 = m + i * r.y * r.y, k12 = -i * r.x * r.y, k22 = m + i * r.x * r.x;
        Vec2 solved;
        if (!solveSymmetric2x2(k11, k12, k22, cdot + bias, solved)) continue;
        const Vec2 impulse = solved * -massScale - c.impulse * impulseScale;
        c.impulse += impulse;
        s.velocity += impulse * m;
        s.omega += i * r.cross(impulse);
    }
}

} // namespace rube
