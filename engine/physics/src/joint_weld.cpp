// Weld joints: a's anchor held on b's and their angle held at the reference angle (a hammer's head
// on its handle). Rigid (the joints' own stiff softness) unless given `hertz`: then both the point
// and the angle are springs of that frequency and damping ratio (Catto's soft constraints).
// Order as Box2D v3's weld: the angle, then the point.
#include "joint_solver.hpp"

namespace rube {

namespace {

Softness softnessOf(const JointConstraint& c, const JointStep& step) {
    const JointDef& d = c.joint->def;
    return d.hertz > 0.0 ? makeSoftness(d.hertz, d.dampingRatio, step.h) : step.softness;
}

void warmStart(JointConstraint& c, const JointView& view, const JointStep&) {
    const JointDef& d = c.joint->def;
    JointBody a = loadSide(view, c.a), b = loadSide(view, c.b);
    const Vec2 rA = armNow(c.angleA, a, d.localAnchorA), rB = armNow(c.angleB, b, d.localAnchorB);
    a.velocity -= c.linearImpulse * a.inverseMass;
    a.omega -= a.inverseInertia * (rA.cross(c.linearImpulse) + c.angularImpulse);
    b.velocity += c.linearImpulse * b.inverseMass;
    b.omega += b.inverseInertia * (rB.cross(c.linearImpulse) + c.angularImpulse);
    storeSide(view, c.a, a);
    storeSide(view, c.b, b);
}

void solve(JointConstraint& c, const JointView& view, const JointStep& step, bool useBias) {
    const JointDef& d = c.joint->def;
    const Softness soft = softnessOf(c, step);
    {
        const JointBody a = loadSide(view, c.a), b = loadSide(view, c.b);
        const double theta = (c.angleB + b.turn) - (c.angleA + a.turn) - d.referenceAngle;
        solveEquality(angleRow(c.a, c.b), view, theta, c.angularImpulse, soft, useBias);
    }
    const JointBody a = loadSide(view, c.a), b = loadSide(view, c.b);
    const Vec2 rA = armNow(c.angleA, a, d.localAnchorA), rB = armNow(c.angleB, b, d.localAnchorB);
    const Vec2 error = (centreNow(c.centreB, b) + rB) - (centreNow(c.centreA, a) + rA);
    solvePoint(c, view, rA, rB, error, soft, useBias);
}

} // namespace

const JointBehaviour& weldBehaviour() {
    static const JointBehaviour behaviour = constraintBehaviour<solve>(warmStart);
    return behaviour;
}

} // namespace rube
