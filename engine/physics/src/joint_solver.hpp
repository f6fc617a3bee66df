#pragma once
// Internal: joints in the solver's substeps, one kind a file (joint_revolute.cpp, joint_prismatic.cpp,
// joint_weld.cpp, joint_spring.cpp, joint_pulley.cpp, joint_gear.cpp), each reached through a small
// table of behaviour (as Chipmunk's cpConstraintClass): prepare at the step's start, warm start,
// solvePosition (velocity with soft position feedback: Box2D v3's solve with useBias) and
// solveVelocity (the rigid relax pass, no feedback). Nothing here knows the circle solver's or the
// rigid solver's own types beyond RigidSolverView, so the table can move onto a unified solver as
// it is. Not part of the public API.
//
// Soft constraints (Catto, "Soft Constraints", GDC 2011; Box2D v3's joints): an equality row with
// Jacobian J, effective mass m = 1 / (J M^-1 J^T), error C and speed Cdot = J v takes the impulse
//     lambda = -m massScale (Cdot + biasRate C) - impulseScale lambda_accumulated
// with feedback, and lambda = -m Cdot in a relax pass; an inequality (C >= 0) is speculative while
// open (bias C / h: it may close at most to 0 within the substep) and its accumulated impulse stays >= 0.

#include "rigid_solver_body.hpp"
#include "rube/physics/joint.hpp"

#include <span>
#include <vector>

namespace rube {

/// One end of a joint in the step: rigid body `index`, circle `index` of the circle solver's
/// bodies, or the world (index -1: infinite mass, at rest).
struct JointSide {
    int index = -1;
    bool rigid = false;
    bool isWorld() const { return index < 0; }
    friend bool operator==(JointSide, JointSide) = default;
};

/// What the joints read and write: the solver's bodies, and the circles' turns within the step.
struct JointView {
    RigidSolverView bodies;
    std::span<const double> circleTurn; ///< per circle: radians turned since the step began
};

/// A side's state loaded for a joint.
struct JointBody {
    Vec2 velocity;
    double omega = 0.0;
    Vec2 displacement;
    double turn = 0.0;
    double inverseMass = 0.0;
    double inverseInertia = 0.0;
};

JointBody loadSide(const JointView& view, JointSide side);
void storeSide(const JointView& view, JointSide side, const JointBody& body);

/// A joint during one step: its ends as they stood at the step's start, and its accumulated
/// impulses (which warm start the next substep, and the next step).
struct JointConstraint {
    const Joint* joint = nullptr;
    JointSide a, b;
    Vec2 centreA, centreB; ///< centres at the step's start, m
    double angleA = 0.0, angleB = 0.0;
    Vec2 linearImpulse;          ///< point constraint (revolute, weld), or (perpendicular, angle) of a prismatic
    double angularImpulse = 0.0; ///< weld's angle, gear's and pulley's row
    double motorImpulse = 0.0;
    double lowerImpulse = 0.0, upperImpulse = 0.0;
    bool kickDue = false;       ///< spring: its second half kick waits for the position update
    int gearA = -1, gearB = -1; ///< gear: the indices of the constraints it couples
};

/// Per step: the substep h and the joints' softness.
struct JointStep {
    double h = 0.0;
    Softness softness; ///< the joints' soft feedback (hinge points, welds, limits)
    /// Rigid feedback: the velocity row solved fully (mass scale 1) with the soft feedback's bias
    /// rate on the error. For the couplings that must hold to round-off while something drives them
    /// (gears, pulleys, a piston's axis): a soft row leaves part of each substep's drive in the
    /// velocity the positions move with, and the error settles at that part over the bias rate
    /// (5.6e-4 rad on a spinning gear, 3.5e-5 m on an Atwood rope).
    Softness rigid;
    std::span<const JointConstraint> all; ///< every joint of the step (a gear reads its joints' ends)
};

/// A joint kind's behaviour.
struct JointBehaviour {
    /// At the step's start, after the ends are set: what the kind keeps for the step.
    void (*prepare)(JointConstraint&, const JointView&, const JointStep&);
    /// Applies the accumulated impulses again.
    void (*warmStart)(JointConstraint&, const JointView&, const JointStep&);
    /// One sweep with soft position feedback (before the substep's positions move).
    void (*solvePosition)(JointConstraint&, const JointView&, const JointStep&);
    /// One relax sweep, velocities only (after the positions moved).
    void (*solveVelocity)(JointConstraint&, const JointView&, const JointStep&);
    /// A force (a spring), not a constraint: applied once a pass, never iterated.
    bool isForce = false;
};

/// The behaviour of a constraint kind (not a force) whose soft and relax passes are one
/// Solve(c, view, step, useBias), and which keeps nothing of its own at the step's start.
template <void (*Solve)(JointConstraint&, const JointView&, const JointStep&, bool)>
JointBehaviour constraintBehaviour(void (*warmStart)(JointConstraint&, const JointView&, const JointStep&)) {
    return {[](JointConstraint&, const JointView&, const JointStep&) {}, warmStart,
            [](JointConstraint& c, const JointView& view, const JointStep& step) { Solve(c, view, step, true); },
            [](JointConstraint& c, const JointView& view, const JointStep& step) { Solve(c, view, step, false); }};
}

const JointBehaviour& revoluteBehaviour();
const JointBehaviour& prismaticBehaviour();
const JointBehaviour& weldBehaviour();
const JointBehaviour& springBehaviour();
const JointBehaviour& pulleyBehaviour();
const JointBehaviour& gearBehaviour();
/// The behaviour of `kind`.
const JointBehaviour& behaviourOf(JointKind kind);

// ---- the kinds' shared pieces (joint_rows.cpp) ----

/// The end's centre now (start plus displacement) and its anchor's arm now (the local anchor
/// turned by the start angle plus the turn so far).
Vec2 centreNow(Vec2 start, const JointBody& b);
Vec2 armNow(double startAngle, const JointBody& b, Vec2 localAnchor);
/// The rotation (cos, sin) of an angle.
Vec2 rotationOf(double angle);

/// A scalar row J over up to four ends: per end a linear part and an angular part (the same end
/// twice is merged; the world is left out): Cdot = sum (linear . v + angular omega).
struct Row {
    struct Term {
        JointSide side;
        Vec2 linear;
        double angular = 0.0;
    };
    Term terms[4];
    int count = 0;
    void add(JointSide side, Vec2 linear, double angular);
    double speed(const JointView& view) const;
    /// J M^-1 J^T, 0 when nothing it touches can move.
    double inverseMass(const JointView& view) const;
    /// v += M^-1 J^T impulse.
    void apply(const JointView& view, double impulse) const;
};

/// The row of relative angular speed omegaB - omegaA.
Row angleRow(JointSide a, JointSide b);

/// An equality row: the soft impulse (feedback on error C when `useBias`) added to `accumulated`.
void solveEquality(const Row& row, const JointView& view, double error, double& accumulated, const Softness& soft,
                   bool useBias);
/// An inequality row, C >= 0: speculative while open, soft while violated, accumulated >= 0.
void solveInequality(const Row& row, const JointView& view, double error, double& accumulated, const Softness& soft,
                     double h, bool useBias);
/// A motor row: drives the row's speed to `speed` with |accumulated| <= maxImpulse.
void solveMotor(const Row& row, const JointView& view, double speed, double& accumulated, double maxImpulse);

/// A point constraint: a's point at arm rA and b's at arm rB held together, error = pB - pA
/// (Box2D v3's revolute point solve, K the 2 x 2 effective mass).
void solvePoint(JointConstraint& c, const JointView& view, Vec2 rA, Vec2 rB, Vec2 error, const Softness& soft,
                bool useBias);

} // namespace rube
