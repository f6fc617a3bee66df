// Rigid contact constraints: build, warm start, soft solve with friction, restitution.
#include "rigid_contacts.hpp"

#include "rigid_normal_pair.hpp"

#include <algorithm>
#include <cmath>

namespace rube {

namespace {

/// 1 / (1/mA + 1/mB + (rA x d)^2 / IA + (rB x d)^2 / IB): the pair's effective mass along d.
double effectiveMass(const LoadedBody& a, const LoadedBody& b, Vec2 rA, Vec2 rB, Vec2 d) {
    const double ra = rA.cross(d), rb = rB.cross(d);
    const double k = a.inverseMass + b.inverseMass + a.inverseInertia * ra * ra + b.inverseInertia * rb * rb;
    return k > 0.0 ? 1.0 / k : 0.0;
}

/// A solver body's velocities and what the constraints read of it, as the sweeps load it.
LoadedBody loadBody(const RigidState& s) {
    return {s.velocity, s.omega, s.displacement, s.turnRotation, s.inverseMass, s.inverseInertia};
}

/// Writes back what a constraint changes: the velocities.
void storeBody(RigidState& s, const LoadedBody& l) {
    s.velocity = l.velocity;
    s.omega = l.omega;
}

} // namespace

RigidContact makeRigidContact(const RigidSolverView& view, BodySide a, BodySide b, Vec2 centreA, Vec2 centreB,
                              const Manifold& manifold, double friction, double bounciness) {
    RigidContact c;
    c.a = a;
    c.b = b;
    c.normal = manifold.normal;
    c.tangent = c.normal.perpendicular();
    c.friction = friction;
    c.bounciness = bounciness;
    c.count = manifold.count;
    const LoadedBody la = load(view, a), lb = load(view, b);
    const Vec2 t = c.normal.perpendicular();
    for (int k = 0; k < manifold.count; ++k) {
        RigidContactPoint& p = c.points[k];
        p.anchorA = manifold.points[k].point - centreA;
        p.anchorB = manifold.points[k].point - centreB;
        p.baseSeparation = manifold.points[k].separation - c.normal.dot(p.anchorB - p.anchorA);
        p.normalMass = effectiveMass(la, lb, p.anchorA, p.anchorB, c.normal);
        p.tangentMass = effectiveMass(la, lb, p.anchorA, p.anchorB, t);
        p.feature = manifold.points[k].id;
    }
    return c;
}

void refreshArms(std::span<RigidContact> contacts, std::span<const RigidState> bodies) {
    for (RigidContact& c : contacts) {
        const Vec2 qA = bodies[static_cast<std::size_t>(c.bodyA)].turnRotation;
        const Vec2 qB = bodies[static_cast<std::size_t>(c.bodyB)].turnRotation;
        for (int k = 0; k < c.count; ++k) {
            RigidContactPoint& p = c.points[k];
            p.armA = rotate(qA, p.anchorA);
            p.armB = rotate(qB, p.anchorB);
        }
    }
}

void chooseSoftness(std::span<RigidContact> contacts, std::span<const RigidState> bodies) {
    for (RigidContact& c : contacts)
        c.againstFixed = bodies[static_cast<std::size_t>(c.bodyA)].inverseMass == 0.0 ||
                         bodies[static_cast<std::size_t>(c.bodyB)].inverseMass == 0.0;
}

void warmStartRigidContacts(std::span<RigidContact> contacts, std::span<RigidState> bodies, double h, double maxTurn) {
    for (RigidContact& c : contacts) {
        RigidState& sa = bodies[static_cast<std::size_t>(c.bodyA)];
        RigidState& sb = bodies[static_cast<std::size_t>(c.bodyB)];
        LoadedBody a = loadBody(sa), b = loadBody(sb);
        if (std::abs(a.omega) * h > maxTurn || std::abs(b.omega) * h > maxTurn) {
            for (int k = 0; k < c.count; ++k) c.points[k].normalImpulse = c.points[k].tangentImpulse = 0.0;
            continue;
        }
        const Vec2 t = c.tangent;
        for (int k = 0; k < c.count; ++k) {
            RigidContactPoint& p = c.points[k];
            const Vec2 impulse = c.normal * p.normalImpulse + t * p.tangentImpulse;
            p.deliveredNormal += p.normalImpulse;
            p.deliveredTangent += p.tangentImpulse;
            applyImpulse(a, p.armA, -impulse);
            applyImpulse(b, p.armB, impulse);
        }
        // As in the solve: a body that cannot move is never written, so a colour may be shared among workers.
        if (movableBody(sa)) storeBody(sa, a);
        if (movableBody(sb)) storeBody(sb, b);
    }
}

void measureApproach(std::span<RigidContact> contacts, std::span<const RigidState> bodies, int substep) {
    for (RigidContact& c : contacts) {
        const LoadedBody a = loadBody(bodies[static_cast<std::size_t>(c.bodyA)]);
        const LoadedBody b = loadBody(bodies[static_cast<std::size_t>(c.bodyB)]);
        const Vec2 n = c.normal, t = c.tangent;
        for (int k = 0; k < c.count; ++k) {
            RigidContactPoint& p = c.points[k];
            if (p.maxNormalImpulse > 0.0) continue;
            const Vec2 rA = p.armA, rB = p.armB;
            double vn = n.dot(pointVelocity(b, rB) - pointVelocity(a, rA));
            // Take back what this contact's own impulses did to vn: impulse P along d at point j changes
            // point k's vn by P [(n . d)(1/mA + 1/mB) + (rAk x n)(rAj x d) / IA + (rBk x n)(rBj x d) / IB].
            for (int j = 0; j < c.count; ++j) {
                const RigidContactPoint& q = c.points[j];
                if (q.deliveredNormal == 0.0 && q.deliveredTangent == 0.0) continue;
                const Vec2 qA = q.armA, qB = q.armB;
                const double ka = a.inverseInertia * rA.cross(n), kb = b.inverseInertia * rB.cross(n);
                vn -= q.deliveredNormal * (a.inverseMass + b.inverseMass + ka * qA.cross(n) + kb * qB.cross(n));
                vn -= q.deliveredTangent * (ka * qA.cross(t) + kb * qB.cross(t));
            }
            p.approachSpeed = -vn;
            p.touchSubstep = substep;
        }
    }
}

namespace {

/// K's entries for a two-point contact's points from their current arms.
PairMass<double> pairMass(const RigidContact& c, const LoadedBody& a, const LoadedBody& b) {
    const Vec2 n = c.normal;
    return PairMass<double>(a.inverseMass + b.inverseMass, a.inverseInertia, b.inverseInertia,
                            c.points[0].armA.cross(n), c.points[0].armB.cross(n), c.points[1].armA.cross(n),
                            c.points[1].armB.cross(n));
}

/// Both normal impulses of a two-point contact at once (solveNormalPair); false, changing nothing,
/// when no case of the problem holds.
/// `sweep`: a pass of the substeps, which also counts what each point delivered and its largest impulse.
bool solvePointsTogether(RigidContact& c, LoadedBody& a, LoadedBody& b, const double (&bias)[2],
                         const double (&massScale)[2], bool sweep) {
    RigidContactPoint& p1 = c.points[0];
    RigidContactPoint& p2 = c.points[1];
    const double vn1 = c.normal.dot(pointVelocity(b, p1.armB) - pointVelocity(a, p1.armA));
    const double vn2 = c.normal.dot(pointVelocity(b, p2.armB) - pointVelocity(a, p2.armA));
    const PairMass<double> k = pairMass(c, a, b);
    const NormalPair<double, bool> x = solveNormalPair<double, bool>(k.k11, k.k22, k.k12, massScale[0], massScale[1],
                                                                     vn1, vn2, bias[0], bias[1], p1.normalImpulse,
                                                                     p2.normalImpulse, 0.0, 1.0);
    if (!x.solved) return false;
    const double totals[2] = {x.x1, x.x2};
    for (int j = 0; j < 2; ++j) {
        RigidContactPoint& p = c.points[j];
        const double delta = totals[j] - p.normalImpulse;
        p.normalImpulse = totals[j];
        if (sweep) {
            p.deliveredNormal += delta;
            p.maxNormalImpulse = std::max(p.maxNormalImpulse, totals[j]);
        }
        applyImpulse(a, p.armA, c.normal * -delta);
        applyImpulse(b, p.armB, c.normal * delta);
    }
    return true;
}

} // namespace

void solveRigidContacts(std::span<RigidContact> contacts, std::span<RigidState> bodies,
                        const RigidContactSoftness& softness, double h, bool useBias) {
    const double invH = 1.0 / h;
    for (RigidContact& c : contacts) {
        RigidState& sa = bodies[static_cast<std::size_t>(c.bodyA)];
        RigidState& sb = bodies[static_cast<std::size_t>(c.bodyB)];
        LoadedBody a = loadBody(sa), b = loadBody(sb);
        const Softness& soft = softness.of(c.stacking, c.againstFixed);
        const Vec2 dp = b.displacement - a.displacement;
        double bias[2] = {0.0, 0.0}, massScale[2] = {1.0, 1.0}, impulseScale[2] = {0.0, 0.0};
        for (int k = 0; k < c.count; ++k) {
            const RigidContactPoint& p = c.points[k];
            // The current gap from the fixed anchors and how far each body moved and turned.
            const double s = c.normal.dot(dp + p.armB - p.armA) + p.baseSeparation;
            if (s > 0.0) {
                bias[k] = s * invH; // speculative: close at most the gap within this substep
            } else if (useBias) {
                bias[k] = std::max(soft.biasRate * s, -softness.maxPushSpeed);
                massScale[k] = soft.massScale;
                impulseScale[k] = soft.impulseScale;
            }
        }
        // Two points together (rigid_normal_pair.hpp), unless K is singular; else one after the other.
        if (!(c.count == 2 && solvePointsTogether(c, a, b, bias, massScale, true)))
            for (int k = 0; k < c.count; ++k) {
                RigidContactPoint& p = c.points[k];
                const Vec2 rA = p.armA, rB = p.armB;
                const double vn = c.normal.dot(pointVelocity(b, rB) - pointVelocity(a, rA));
                const double lambda = -p.normalMass * massScale[k] * (vn + bias[k]) - impulseScale[k] * p.normalImpulse;
                const double total = std::max(p.normalImpulse + lambda, 0.0);
                const double delta = total - p.normalImpulse;
                p.normalImpulse = total;
                p.deliveredNormal += delta;
                p.maxNormalImpulse = std::max(p.maxNormalImpulse, total);
                applyImpulse(a, rA, c.normal * -delta);
                applyImpulse(b, rB, c.normal * delta);
            }
        if (c.friction > 0.0) {
            const Vec2 t = c.tangent;
            for (int k = 0; k < c.count; ++k) {
                RigidContactPoint& p = c.points[k];
                const Vec2 rA = p.armA, rB = p.armB;
                const double vt = t.dot(pointVelocity(b, rB) - pointVelocity(a, rA)) + c.tangentSpeed;
                const double limit = c.friction * p.normalImpulse;
                // Spelled out as libstdc++'s std::clamp, so the lanes (rigid_contact_lanes.hpp) can match it.
                const double total = std::min(std::max(p.tangentImpulse - p.tangentMass * vt, -limit), limit);
                const double delta = total - p.tangentImpulse;
                p.tangentImpulse = total;
                p.deliveredTangent += delta;
                applyImpulse(a, rA, t * -delta);
                applyImpulse(b, rB, t * delta);
            }
        }
        // A body that cannot move is never written (its velocity plus 0 p could turn -0 into +0), so two
        // contacts of a colour that share only such a body may be solved at once (rigid_contact_lanes.hpp).
        if (movableBody(sa)) storeBody(sa, a);
        if (movableBody(sb)) storeBody(sb, b);
    }
}

namespace {

bool bounces(const RigidContactPoint& p, double threshold) {
    return p.maxNormalImpulse > 0.0 && p.approachSpeed >= threshold;
}

/// Both points of a two-point contact at once (solveNormalPair, rigid: mass scales 1): with the
/// points' normal speeds driven to C a_i together, the kinetic energy changes by (C^2 - 1) / 2 a^T
/// K^-1 a <= 0 for C <= 1. One point after the other would let the second undo the first and, for a
/// turning body, add energy. False, changing nothing, when no case of the problem holds.
bool blockRestitution(RigidContact& c, LoadedBody& a, LoadedBody& b) {
    // vn'_i - target_i = (K x)_i + c_i: restitution's bias is minus its target speed.
    const double bias[2] = {-(c.bounciness * c.points[0].approachSpeed), -(c.bounciness * c.points[1].approachSpeed)};
    const double rigid[2] = {1.0, 1.0};
    return solvePointsTogether(c, a, b, bias, rigid, false);
}

} // namespace

void applyRigidRestitution(std::span<RigidContact> contacts, std::span<RigidState> bodies, double threshold) {
    for (RigidContact& c : contacts) {
        if (c.bounciness == 0.0) continue;
        RigidState& sa = bodies[static_cast<std::size_t>(c.bodyA)];
        RigidState& sb = bodies[static_cast<std::size_t>(c.bodyB)];
        LoadedBody a = loadBody(sa), b = loadBody(sb);
        if (c.count == 2 && bounces(c.points[0], threshold) && bounces(c.points[1], threshold) &&
            blockRestitution(c, a, b)) {
            if (movableBody(sa)) storeBody(sa, a);
            if (movableBody(sb)) storeBody(sb, b);
            continue;
        }
        for (int k = 0; k < c.count; ++k) {
            RigidContactPoint& p = c.points[k];
            if (!bounces(p, threshold)) continue;
            const Vec2 rA = p.armA, rB = p.armB;
            const double vn = c.normal.dot(pointVelocity(b, rB) - pointVelocity(a, rA));
            // Drive vn to C times the approach speed, pushing only (lecture 3: v' = -C vn).
            const double lambda = -p.normalMass * (vn - c.bounciness * p.approachSpeed);
            const double total = std::max(p.normalImpulse + lambda, 0.0);
            const double delta = total - p.normalImpulse;
            p.normalImpulse = total;
            applyImpulse(a, rA, c.normal * -delta);
            applyImpulse(b, rB, c.normal * delta);
        }
        if (movableBody(sa)) storeBody(sa, a);
        if (movableBody(sb)) storeBody(sb, b);
    }
}

} // namespace rube
