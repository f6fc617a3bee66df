// Pulleys: a rope from a's anchor over fixed point groundA and from b's anchor over groundB, of
// length L: |pA - groundA| + ratio |pB - groundB| <= L. A rope pulls, never pushes: the constraint
// is an inequality, slack = L - length >= 0, whose impulse only pulls both sides towards their
// ground points; a slack rope does nothing. With uA, uB the unit directions from the ground points,
// the length's rate is J v, J = [ uA, rA x uA ; ratio uB, ratio rB x uB ].
#include "joint_solver.hpp"

namespace rube {

namespace {

struct Rope {
    Row slackRow; ///< -J: the rate of the slack
    double slack = 0.0;
};

Rope ropeOf(const JointConstraint& c, const JointView& view) {
    const JointDef& d = c.joint->def;
    const JointBody a = loadSide(view, c.a), b = loadSide(view, c.b);
    const Vec2 rA = armNow(c.angleA, a, d.localAnchorA), rB = armNow(c.angleB, b, d.localAnchorB);
    const Vec2 toA = centreNow(c.centreA, a) + rA - d.groundA, toB = centreNow(c.centreB, b) + rB - d.groundB;
    const double lengthA = toA.length(), lengthB = toB.length();
    // A body at its ground point has no direction to be pulled in: that side does not pull.
    const Vec2 uA = lengthA > 0.0 ? toA * (1.0 / lengthA) : Vec2{};
    const Vec2 uB = lengthB > 0.0 ? toB * (1.0 / lengthB) : Vec2{};
    Rope rope;
    rope.slack = d.length - (lengthA + d.ratio * lengthB);
    rope.slackRow.add(c.a, -uA, -rA.cross(uA));
    rope.slackRow.add(c.b, uB * -d.ratio, -d.ratio * rB.cross(uB));
    return rope;
}

void warmStart(JointConstraint& c, const JointView& view, const JointStep&) {
    ropeOf(c, view).slackRow.apply(view, c.angularImpulse);
}

void solve(JointConstraint& c, const JointView& view, const JointStep& step, bool useBias) {
    const Rope rope = ropeOf(c, view);
    solveInequality(rope.slackRow, view, rope.slack, c.angularImpulse, step.rigid, step.h, useBias);
}

} // namespace

const JointBehaviour& pulleyBehaviour() {
    static const JointBehaviour behaviour = constraintBehaviour<solve>(warmStart);
    return behaviour;
}

} // namespace rube
