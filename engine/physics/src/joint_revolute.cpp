// Revolute joints (hinges): a's anchor held on b's, with an optional motor and angle limits.
//
// The point: C = (cB + rB) - (cA + rA) = 0, solved as one 2 x 2 block (solvePoint). The angle
// theta = (angleB - angleA) - referenceAngle, its speed omegaB - omegaA: the motor drives it to the
// motor's speed with at most maxTorque h a substep (so alpha <= maxTorque / I), the limits keep
// lower <= theta <= upper as two inequalities. Order as Box2D v3's: motor, limits, point last (the
// hinge holds whatever the motor and limits did).
#include "joint_solver.hpp"

namespace rube {

namespace {

struct Ends {
    JointBody a, b;
    Vec2 rA, rB;
};

Ends endsOf(const JointConstraint& c, const JointView& view) {
    const JointDef& d = c.joint->def;
    Ends e{loadSide(view, c.a), loadSide(view, c.b), {}, {}};
    e.rA = armNow(c.angleA, e.a, d.localAnchorA);
    e.rB = armNow(c.angleB, e.b, d.localAnchorB);
    return e;
}

void warmStart(JointConstraint& c, const JointView& view, const JointStep&) {
    const Ends e = endsOf(c, view);
    JointBody a = e.a, b = e.b;
    const double axial = c.motorImpulse + c.lowerImpulse - c.upperImpulse;
    a.velocity -= c.linearImpulse * a.inverseMass;
    a.omega -= a.inverseInertia * (e.rA.cross(c.linearImpulse) + axial);
    b.velocity += c.linearImpulse * b.inverseMass;
    b.omega += b.inverseInertia * (e.rB.cross(c.linearImpulse) + axial);
    storeSide(view, c.a, a);
    storeSide(view, c.b, b);
}

void solve(JointConstraint& c, const JointView& view, const JointStep& step, bool useBias) {
    const JointDef& d = c.joint->def;
    const Row angle = angleRow(c.a, c.b);
    if (d.motor.on()) solveMotor(angle, view, d.motor.speed, c.motorImpulse, d.motor.maxForce * step.h);
    if (d.limits.on) {
        const Ends e = endsOf(c, view);
        const double theta = (c.angleB + e.b.turn) - (c.angleA + e.a.turn) - d.referenceAngle;
        solveInequality(angle, view, theta - d.limits.lower, c.lowerImpulse, step.softness, step.h, useBias);
        Row reversed = angleRow(c.b, c.a); // upper - theta >= 0: its speed is omegaA - omegaB
        solveInequality(reversed, view, d.limits.upper - theta, c.upperImpulse, step.softness, step.h, useBias);
    }
    const Ends e = endsOf(c, view);
    const Vec2 error = (centreNow(c.centreB, e.b) + e.rB) - (centreNow(c.centreA, e.a) + e.rA);
    solvePoint(c, view, e.rA, e.rB, error, step.rigid, useBias);
}

} // namespace

const JointBehaviour& revoluteBehaviour() {
    static const JointBehaviour behaviour = constraintBehaviour<solve>(warmStart);
    return behaviour;
}

} // namespace rube
