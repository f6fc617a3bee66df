// Prismatic joints (pistons): b slides along an axis fixed in a, without turning against a; with
// an optional motor (speed, maximum force) and limits on the slide.
//
// With d = (cB + rB) - (cA + rA) and u the axis turned with a, the slide is s = d . u and its speed
// Cdot = J v with J = [ -u, -(d + rA) x u ; u, rB x u ] (a's part; b's part). Off the axis,
// e = d . p (p = u turned a quarter) and the angle theta = angleB - angleA - reference are held at
// 0 as one 2 x 2 block (Box2D v3's prismatic), after the motor and the limits.
#include "joint_solver.hpp"

#include <cmath>

namespace rube {

namespace {

struct Frame {
    JointBody a, b;
    Vec2 rA, rB, d, axis, perp;
};

Frame frameOf(const JointConstraint& c, const JointView& view) {
    const JointDef& d = c.joint->def;
    Frame f{loadSide(view, c.a), loadSide(view, c.b), {}, {}, {}, {}, {}};
    f.rA = armNow(c.angleA, f.a, d.localAnchorA);
    f.rB = armNow(c.angleB, f.b, d.localAnchorB);
    f.d = (centreNow(c.centreB, f.b) + f.rB) - (centreNow(c.centreA, f.a) + f.rA);
    f.axis = rotate(rotationOf(c.angleA + f.a.turn), d.localAxisA.normalized());
    f.perp = f.axis.perpendicular();
    return f;
}

/// The row of a direction fixed in a (u or p): its speed is the slide's (or the drift's) rate.
Row slideRow(const JointConstraint& c, const Frame& f, Vec2 direction) {
    Row row;
    row.add(c.a, -direction, -(f.d + f.rA).cross(direction));
    row.add(c.b, direction, f.rB.cross(direction));
    return row;
}

void warmStart(JointConstraint& c, const JointView& view, const JointStep&) {
    const Frame f = frameOf(c, view);
    const double axial = c.motorImpulse + c.lowerImpulse - c.upperImpulse;
    slideRow(c, f, f.axis).apply(view, axial);
    slideRow(c, f, f.perp).apply(view, c.linearImpulse.x);
    angleRow(c.a, c.b).apply(view, c.linearImpulse.y);
}

void solveBlock(JointConstraint& c, const JointView& view, const JointStep& step, bool useBias) {
    const JointDef& d = c.joint->def;
    const Frame f = frameOf(c, view);
    const double mA = f.a.inverseMass, mB = f.b.inverseMass, iA = f.a.inverseInertia, iB = f.b.inverseInertia;
    const double sA = (f.d + f.rA).cross(f.perp), sB = f.rB.cross(f.perp);
    const double k11 = mA + mB + iA * sA * sA + iB * sB * sB;
    const double k12 = iA * sA + iB * sB;
    double k22 = iA + iB;
    if (k22 == 0.0) k22 = 1.0; // neither turns: the angle row is idle
    const Vec2 cdot{f.perp.dot(f.b.velocity - f.a.velocity) + sB * f.b.omega - sA * f.a.omega, f.b.omega - f.a.omega};
    Vec2 bias;
    double massScale = 1.0, impulseScale = 0.0;
    if (useBias) {
        const Vec2 error{f.d.dot(f.perp), (c.angleB + f.b.turn) - (c.angleA + f.a.turn) - d.referenceAngle};
        bias = error * step.rigid.biasRate;
        massScale = step.rigid.massScale;
        impulseScale = step.rigid.impulseScale;
    }
    Vec2 solved;
    if (!solveSymmetric2x2(k11, k12, k22, cdot + bias, solved)) return;
    const Vec2 impulse = solved * -massScale - c.linearImpulse * impulseScale;
    c.linearImpulse += impulse;
    JointBody a = f.a, b = f.b;
    a.velocity -= f.perp * (mA * impulse.x);
    a.omega -= iA * (sA * impulse.x + impulse.y);
    b.velocity += f.perp * (mB * impulse.x);
    b.omega += iB * (sB * impulse.x + impulse.y);
    storeSide(view, c.a, a);
    storeSide(view, c.b, b);
}

void solve(JointConstraint& c, const JointView& view, const JointStep& step, bool useBias) {
    const JointDef& d = c.joint->def;
    if (d.motor.on()) {
        const Frame f = frameOf(c, view);
        solveMotor(slideRow(c, f, f.axis), view, d.motor.speed, c.motorImpulse, d.motor.maxForce * step.h);
    }
    if (d.limits.on) {
        const Frame f = frameOf(c, view);
        const Row row = slideRow(c, f, f.axis);
        const double s = f.d.dot(f.axis);
        solveInequality(row, view, s - d.limits.lower, c.lowerImpulse, step.softness, step.h, useBias);
        const Frame g = frameOf(c, view);
        solveInequality(slideRow(c, g, -g.axis), view, d.limits.upper - s, c.upperImpulse, step.softness, step.h,
                        useBias);
    }
    solveBlock(c, view, step, useBias);
}

} // namespace

const JointBehaviour& prismaticBehaviour() {
    static const JointBehaviour behaviour = constraintBehaviour<solve>(warmStart);
    return behaviour;
}

} // namespace rube
