#pragma once
// Internal: the circle solver's soft step: its contacts' data and per-substep stages (the rigid contacts
// share its SolverBody and Softness). Not part of the public API.
//
// One step (Catto, "Solver2D" / Box2D v3's soft step): contacts are found once; then every substep
// integrates velocities, warm starts, solves with soft position feedback, integrates positions and
// relaxes without it; restitution is applied once at the end. Bodies carry their displacement since
// the step began, so a contact's current gap is its start gap plus the relative displacement along
// its fixed normal: s = s0 + n . (dpA - dpB), with no narrowphase inside the substeps.

#include "rube/physics/world.hpp"

#include <span>

namespace rube {

/// A body as the substeps see it: its velocity and how far it has moved since the step began.
struct alignas(32) SolverBody {
    Vec2 velocity;     ///< m/s, updated by gravity and contact impulses
    Vec2 displacement; ///< m moved since the start of the step
};

/// Coefficients of a soft constraint: a spring-damper of given frequency and damping ratio,
/// integrated implicitly over one substep (Catto, "Soft Constraints", GDC 2011).
struct Softness {
    double biasRate = 0.0;     ///< omega / (2 zeta + h omega): position error to velocity bias
    double massScale = 1.0;    ///< h omega a1 / (1 + h omega a1), a1 = 2 zeta + h omega
    double impulseScale = 0.0; ///< 1 / (1 + h omega a1): how much of the old impulse to forget
};

/// The softness of a spring of `hertz` and `dampingRatio`, integrated over substeps of `h` seconds.
Softness makeSoftness(double hertz, double dampingRatio, double h);

/// One contact between dynamic circle `a` and body `b` (circle or segment), the hot data the
/// substeps touch, in the order the solver sweeps them. 48 bytes: the sweeps stream every contact
/// 32 times a step, so a 20,000-ball pile's contacts must stay small (the bodies' inverse masses are
/// read from a per-body array instead, which stays in cache).
struct alignas(16) ContactConstraint {
    int a = 0;                   ///< solver body index of the dynamic circle
    int b = 0;                   ///< solver body index of the other body (circles first, then segments)
    Vec2 normal;                 ///< unit, from b towards a, fixed for the step
    double baseSeparation = 0.0; ///< surface gap at the start of the step (negative: overlap)
    double normalMass =
        0.0;              ///< 1 / (1/mA + 1/mB), the pair's effective mass along n (1/m = 0: infinite mass, lecture 3)
    double impulse = 0.0; ///< accumulated normal impulse of the current substep (>= 0)
};

/// The cold side of a contact: what restitution and the impact record need. A contact that starts
/// the step pushing (warm started) is resting; one that starts at zero impulse and pushes has touched.
struct ContactRecord {
    Other kind = Other::circle;  ///< what the circle touches: a circle, a segment's side or its cap
    double bounciness = 0.0;     ///< product of both materials' bounciness
    double approachSpeed = 0.0;  ///< -vn when the contact first pushed: the speed restitution reverses
    double touchTime = 0.0;      ///< seconds into the step at which it first touched
    int firstTouch = -1;         ///< substep in which a contact that started at rest first pushed, or -1
    double tangentImpulse = 0.0; ///< the pair's friction impulse at the end of the last step: friction's warm start
    double impactTime = -1.0;    ///< seconds into the step at which the swept pair touches (aimAtTimeOfImpact), or -1
    bool carried = false; ///< bounced at its time of impact and flown on (carryPastImpact): restitution leaves it
    Vec2 pointOfImpact;   ///< where a carried bounce touched (the circle has flown on since)
};

struct FrictionState;

/// Applies last substep's impulses again as the starting guess: v += M^-1 n lambda (warm starting),
/// and the friction impulses too when `friction` is given.
void warmStartContacts(std::span<const ContactConstraint> contacts, std::span<SolverBody> bodies,
                       std::span<const double> inverseMass, const FrictionState* friction = nullptr);

/// `inverseMass` is per solver body: 1/m of dynamic circles, 0 for every body of infinite mass.
/// One Gauss-Seidel sweep with soft position feedback: overlap is pushed out softly, speculative
/// contacts (gap s > 0) only forbid closing more than the gap within this substep, vn >= -s / h.
/// softness[0] applies between two dynamic circles, softness[1] against infinite mass. Marks contacts
/// that start pushing for the first time this step with `substep` and their approach speed.
/// With `friction`, each contact's Coulomb friction is solved right after its normal impulse.
void solveContacts(std::span<ContactConstraint> contacts, std::span<ContactRecord> records,
                   std::span<SolverBody> bodies, std::span<const double> inverseMass, const Softness (&softness)[2],
                   double h, int substep, double maxPushSpeed, const FrictionState* friction = nullptr);

/// One rigid Gauss-Seidel sweep without position feedback (relax): removes the push-out velocity
/// the soft solve added, so overlap is corrected in position without gaining energy.
/// Positions do not move between the relax passes of a substep: the first pass (`gaps` to fill)
/// measures every contact's gap into `gaps`, the later ones read it back.
void relaxContacts(std::span<ContactConstraint> contacts, std::span<ContactRecord> records,
                   std::span<SolverBody> bodies, std::span<const double> inverseMass, std::span<double> gaps,
                   bool measureGaps, double h, int substep);

/// Restitution once per step for contacts that touched faster than `threshold`: the normal velocity
/// becomes C times the approach speed (v' = u - C (v - u), lecture 3), the approach taken one substep
/// of gravity later (`gravityStep` = g h) against infinite mass, so bounces keep their height.
void applyRestitution(std::span<const ContactConstraint> contacts, std::span<const ContactRecord> records,
                      std::span<SolverBody> bodies, std::span<const double> inverseMass, double threshold,
                      Vec2 gravityStep);

} // namespace rube
