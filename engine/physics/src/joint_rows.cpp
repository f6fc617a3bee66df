// The joints' shared pieces: loading an end, rows over up to four ends, and the soft equality,
// inequality, motor and point solves every kind is built from (see joint_solver.hpp).
#include "joint_solver.hpp"

#include <algorithm>
#include <cmath>

namespace rube {

JointBody loadSide(const JointView& view, JointSide side) {
    if (side.isWorld()) return {};
    const auto i = static_cast<std::size_t>(side.index);
    if (side.rigid) {
        const RigidState& s = view.bodies.rigid[i];
        return {s.velocity, s.omega, s.displacement, s.turn, s.inverseMass, s.inverseInertia};
    }
    // A circle: the circle solver's body, its spin (the solver turns every jointed circle) and its turn.
    const LoadedBody l = load(view.bodies, BodySide{side.index, false});
    return {l.velocity,    l.omega,         l.displacement, i < view.circleTurn.size() ? view.circleTurn[i] : 0.0,
            l.inverseMass, l.inverseInertia};
}

void storeSide(const JointView& view, JointSide side, const JointBody& b) {
    if (side.isWorld()) return;
    if (side.rigid) {
        RigidState& s = view.bodies.rigid[static_cast<std::size_t>(side.index)];
        s.velocity = b.velocity;
        s.omega = b.omega;
        return;
    }
    LoadedBody l;
    l.velocity = b.velocity;
    l.omega = b.omega;
    store(view.bodies, BodySide{side.index, false}, l);
}

Vec2 rotationOf(double angle) { return {std::cos(angle), std::sin(angle)}; }

Vec2 centreNow(Vec2 start, const JointBody& b) { return start + b.displacement; }

Vec2 armNow(double startAngle, const JointBody& b, Vec2 localAnchor) {
    return rotate(rotationOf(startAngle + b.turn), localAnchor);
}

void Row::add(JointSide side, Vec2 linear, double angular) {
    if (side.isWorld()) return;
    for (int k = 0; k < count; ++k)
        if (terms[k].side == side) {
            terms[k].linear += linear;
            terms[k].angular += angular;
            return;
        }
    terms[count++] = {side, linear, angular};
}

double Row::speed(const JointView& view) const {
    double s = 0.0;
    for (int k = 0; k < count; ++k) {
        const JointBody b = loadSide(view, terms[k].side);
        s += terms[k].linear.dot(b.velocity) + terms[k].angular * b.omega;
    }
    return s;
}

double Row::inverseMass(const JointView& view) const {
    double m = 0.0;
    for (int k = 0; k < count; ++k) {
        const JointBody b = loadSide(view, terms[k].side);
        m += b.inverseMass * terms[k].linear.lengthSquared() + b.inverseInertia * terms[k].angular * terms[k].angular;
    }
    return m;
}

void Row::apply(const JointView& view, double impulse) const {
    for (int k = 0; k < count; ++k) {
        JointBody b = loadSide(view, terms[k].side);
        b.velocity += terms[k].linear * (b.inverseMass * impulse);
        b.omega += b.inverseInertia * terms[k].angular * impulse;
        storeSide(view, terms[k].side, b);
    }
}

Row angleRow(JointSide a, JointSide b) {
    Row row;
    row.add(a, {}, -1.0);
    row.add(b, {}, 1.0);
    return row;
}

void solveEquality(const Row& row, const JointView& view, double error, double& accumulated, const Softness& soft,
                   bool useBias) {
    const double k = row.inverseMass(view);
    if (k <= 0.0) return;
    double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
    if (useBias) {
        bias = soft.biasRate * error;
        massScale = soft.massScale;
        impulseScale = soft.impulseScale;
    }
    const double impulse = -massScale * (row.speed(view) + bias) / k - impulseScale * accumulated;
    accumulated += impulse;
    row.apply(view, impulse);
}

void solveInequality(const Row& row, const JointView& view, double error, double& accumulated, const Softness& soft,
                     double h, bool useBias) {
    const double k = row.inverseMass(view);
    if (k <= 0.0) return;
    double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
    if (error > 0.0) {
        bias = error / h; // open: it may close up to the gap within this substep, no further
    } else if (useBias) {
        bias = soft.biasRate * error;
        massScale = soft.massScale;
        impulseScale = soft.impulseScale;
    }
    const double impulse = -massScale * (row.speed(view) + bias) / k - impulseScale * accumulated;
    const double total = std::max(accumulated + impulse, 0.0);
    const double applied = total - accumulated;
    accumulated = total;
    row.apply(view, applied);
}

void solveMotor(const Row& row, const JointView& view, double speed, double& accumulated, double maxImpulse) {
    const double k = row.inverseMass(view);
    if (k <= 0.0) return;
    const double impulse = -(row.speed(view) - speed) / k;
    const double total = std::clamp(accumulated + impulse, -maxImpulse, maxImpulse);
    const double applied = total - accumulated;
    accumulated = total;
    row.apply(view, applied);
}

void solvePoint(JointConstraint& c, const JointView& view, Vec2 rA, Vec2 rB, Vec2 error, const Softness& soft,
                bool useBias) {
    JointBody a = loadSide(view, c.a), b = loadSide(view, c.b);
    // Cdot = vB + omegaB x rB - vA - omegaA x rA.
    const Vec2 cdot = b.velocity + rB.perpendicular() * b.omega - a.velocity - rA.perpendicular() * a.omega;
    Vec2 bias;
    double massScale = 1.0, impulseScale = 0.0;
    if (useBias) {
        bias = error * soft.biasRate;
        massScale = soft.massScale;
        impulseScale = soft.impulseScale;
    }
    const double mA = a.inverseMass, mB = b.inverseMass, iA = a.inverseInertia, iB = b.inverseInertia;
    const double k11 = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
    const double k12 = -rA.y * rA.x * iA - rB.y * rB.x * iB;
    const double k22 = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;
    Vec2 solved;
    if (!solveSymmetric2x2(k11, k12, k22, cdot + bias, solved)) return;
    const Vec2 impulse = solved * -massScale - c.linearImpulse * impulseScale;
    c.linearImpulse += impulse;
    a.velocity -= impulse * mA;
    a.omega -= iA * rA.cross(impulse);
    b.velocity += impulse * mB;
    b.omega += iB * rB.cross(impulse);
    storeSide(view, c.a, a);
    storeSide(view, c.b, b);
}

const JointBehaviour& behaviourOf(JointKind kind) {
    switch (kind) {
    case JointKind::revolute: return revoluteBehaviour();
    case JointKind::prismatic: return prismaticBehaviour();
    case JointKind::weld: return weldBehaviour();
    case JointKind::spring: return springBehaviour();
    case JointKind::pulley: return pulleyBehaviour();
    case JointKind::gear: return gearBehaviour();
    }
    return revoluteBehaviour();
}

} // namespace rube
