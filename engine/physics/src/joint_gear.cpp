// Gears: coordA + ratio coordB = constant, coordA the angle of a revolute (angleB - angleA), coordB
// that of a second revolute or the slide of a prismatic (rack and pinion). A belt is a gear whose
// ratio is minus the ratio of its wheels' radii: both turn the same way, rim speeds equal.
//
// The row runs over the four ends of the two joints (some may be one body, or the world): a
// revolute's angle has J = [ -1 on its a's omega, +1 on its b's ]; a prismatic's slide has
// J = [ -u, -(d + rA) x u ; u, rB x u ] (see joint_prismatic.cpp), scaled by the ratio. The error
// coordA + ratio coordB - constant is fed back softly, as every joint's.
#include "joint_solver.hpp"

namespace rube {

namespace {

/// Adds `scale` times the coordinate's row of joint `j` to `row`; returns the coordinate.
double addCoordinate(Row& row, const JointConstraint& j, const JointView& view, double scale) {
    const JointDef& d = j.joint->def;
    const JointBody a = loadSide(view, j.a), b = loadSide(view, j.b);
    if (d.kind == JointKind::revolute) {
        row.add(j.a, {}, -scale);
        row.add(j.b, {}, scale);
        return (j.angleB + b.turn) - (j.angleA + a.turn) - d.referenceAngle;
    }
    const Vec2 rA = armNow(j.angleA, a, d.localAnchorA), rB = armNow(j.angleB, b, d.localAnchorB);
    const Vec2 between = (centreNow(j.centreB, b) + rB) - (centreNow(j.centreA, a) + rA);
    const Vec2 u = rotate(rotationOf(j.angleA + a.turn), d.localAxisA.normalized());
    row.add(j.a, u * -scale, -scale * (between + rA).cross(u));
    row.add(j.b, u * scale, scale * rB.cross(u));
    return between.dot(u);
}

struct Coupling {
    Row row;
    double error = 0.0;
};

Coupling couplingOf(const JointConstraint& c, const JointView& view, const JointStep& step) {
    const Joint& gear = *c.joint;
    const JointConstraint& first = step.all[static_cast<std::size_t>(c.gearA)];
    const JointConstraint& second = step.all[static_cast<std::size_t>(c.gearB)];
    Coupling k;
    const double coordA = addCoordinate(k.row, first, view, 1.0);
    const double coordB = addCoordinate(k.row, second, view, gear.def.ratio);
    k.error = coordA + gear.def.ratio * coordB - gear.gearConstant;
    return k;
}

void warmStart(JointConstraint& c, const JointView& view, const JointStep& step) {
    couplingOf(c, view, step).row.apply(view, c.angularImpulse);
}

void solve(JointConstraint& c, const JointView& view, const JointStep& step, bool useBias) {
    const Coupling k = couplingOf(c, view, step);
    solveEquality(k.row, view, k.error, c.angularImpulse, step.rigid, useBias);
}

} // namespace

const JointBehaviour& gearBehaviour() {
    static const JointBehaviour behaviour = constraintBehaviour<solve>(warmStart);
    return behaviour;
}

} // namespace rube
