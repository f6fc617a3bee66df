// Springs: a damped spring between a's anchor and b's, of rest length L0, stiffness k and damping c,
// optionally one-sided. Its force on b along n = (pB - pA) / |pB - pA| is
//     f = -k (|pB - pA| - L0) - c Cdot,   Cdot = n . (vB + omegaB x rB - vA - omegaA x rA)
// (pushOnly keeps f >= 0, pullOnly f <= 0).
//
// A spring is a force, not a constraint: it is integrated by velocity Verlet within the substep, a
// half kick f h / 2 before the positions move (solvePosition) and a half kick at the new positions
// after (the first solveVelocity). Velocity Verlet is symplectic: an undamped spring's energy stays
// within O((omega h)^2) of its start forever (no drift), and its period is off by (omega h)^2 / 24.
// It is stable while omega h < 2, omega = sqrt(k / m), m the spring's effective mass; past
// kExplicitTurn the spring is solved as Catto's soft constraint instead (implicit, stable at any
// stiffness, and it loses energy: see the failure table's spring stiffness axis).
#include "joint_solver.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rube {

namespace {

/// omega h past which the explicit spring gives way to the implicit one: velocity Verlet's energy
/// error (omega h)^2 / 4 is 6 % there, and stability ends at 2.
constexpr double kExplicitTurn = 0.5;

struct Axis {
    Row row;
    double length = 0.0;
};

Axis axisOf(const JointConstraint& c, const JointView& view) {
    const JointDef& d = c.joint->def;
    const JointBody a = loadSide(view, c.a), b = loadSide(view, c.b);
    const Vec2 rA = armNow(c.angleA, a, d.localAnchorA), rB = armNow(c.angleB, b, d.localAnchorB);
    const Vec2 between = (centreNow(c.centreB, b) + rB) - (centreNow(c.centreA, a) + rA);
    Axis axis;
    axis.length = between.length();
    // Coincident anchors have no direction: the spring then pushes along the world's y.
    const Vec2 n = axis.length > 0.0 ? between * (1.0 / axis.length) : Vec2{0.0, 1.0};
    axis.row.add(c.a, -n, -rA.cross(n));
    axis.row.add(c.b, n, rB.cross(n));
    return axis;
}

double oneSided(SpringSide side, double f) {
    if (side == SpringSide::pushOnly) return std::max(f, 0.0);
    if (side == SpringSide::pullOnly) return std::min(f, 0.0);
    return f;
}

/// The half kick f h / 2. The first half takes the damping at the speed it starts from; the second
/// (`closing`) at the speed it ends with, u1 = u + lambda / m, so that lambda = h/2 (-k x - c u1):
///     lambda = h/2 (-k x - c u) / (1 + h/2 c / m)
/// (the trapezoidal rule in the damping: second order, as velocity Verlet is in the spring).
void kick(const JointConstraint& c, const JointView& view, const JointStep& step, bool closing) {
    const JointDef& d = c.joint->def;
    const Axis axis = axisOf(c, view);
    const double half = 0.5 * step.h;
    double impulse = half * (-d.stiffness * (axis.length - d.restLength) - d.damping * axis.row.speed(view));
    if (closing) impulse /= 1.0 + half * d.damping * axis.row.inverseMass(view);
    axis.row.apply(view, oneSided(d.springSide, impulse));
}

bool explicitSpring(const JointConstraint& c, const JointView& view, const JointStep& step) {
    const double inverseMass = axisOf(c, view).row.inverseMass(view);
    return step.h * std::sqrt(c.joint->def.stiffness * inverseMass) <= kExplicitTurn;
}

void prepare(JointConstraint&, const JointView&, const JointStep&) {}
void warmStart(JointConstraint&, const JointView&, const JointStep&) {}

void solvePosition(JointConstraint& c, const JointView& view, const JointStep& step) {
    if (explicitSpring(c, view, step)) {
        kick(c, view, step, false);
        c.kickDue = true;
        return;
    }
    // Too stiff for the explicit kick: the spring as a soft constraint (Box2D's spring), one implicit
    // solve a substep, its frequency and damping ratio from k, c and the effective mass.
    const JointDef& d = c.joint->def;
    const Axis axis = axisOf(c, view);
    const double inverseMass = axis.row.inverseMass(view);
    const double mass = 1.0 / inverseMass;
    const double omega = std::sqrt(d.stiffness * inverseMass);
    const double zeta = d.damping / (2.0 * std::sqrt(d.stiffness * mass));
    const Softness soft = makeSoftness(omega / (2.0 * std::numbers::pi), zeta, step.h);
    const double impulse = -soft.massScale * mass *
                           (axis.row.speed(view) + soft.biasRate * (axis.length - d.restLength));
    axis.row.apply(view, oneSided(d.springSide, impulse));
}

void solveVelocity(JointConstraint& c, const JointView& view, const JointStep& step) {
    if (!c.kickDue) return;
    c.kickDue = false;
    kick(c, view, step, true);
}

} // namespace

const JointBehaviour& springBehaviour() {
    static const JointBehaviour behaviour{prepare, warmStart, solvePosition, solveVelocity, true};
    return behaviour;
}

} // namespace rube
