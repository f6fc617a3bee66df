// The circle solver's soft-step stages: warm start, soft solve, relax, restitution.
#include "solver_soft_step.hpp"

#include "solver_friction.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rube {

namespace {

/// First push of a contact this step: the speed it arrived with (what restitution reverses), and when
/// within the substep the gap s closed at normal speed vn.
void markFirstTouch(ContactRecord& r, int substep, double h, double s, double vn) {
    if (r.firstTouch >= 0) return;
    r.firstTouch = substep;
    r.approachSpeed = -vn;
    r.touchTime = substep * h + (s > 0.0 && vn < 0.0 ? std::min(s / -vn, h) : 0.0);
}

} // namespace

Softness makeSoftness(double hertz, double dampingRatio, double h) {
    if (hertz <= 0.0) return Softness{0.0, 1.0, 0.0};
    // Implicit Euler on a spring k = m omega^2 with damper c = 2 m zeta omega gives, per unit mass,
    // lambda = -m (a2/(1+a2)) (vn + (omega/a1) s) - (1/(1+a2)) lambda_old, a1 = 2 zeta + h omega, a2 = h omega a1.
    const double omega = 2.0 * std::numbers::pi * hertz;
    const double a1 = 2.0 * dampingRatio + h * omega;
    const double a2 = h * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    return Softness{omega / a1, a2 * a3, a3};
}

namespace {

template <bool Friction>
void warmStartSweep(std::span<const ContactConstraint> contacts, std::span<SolverBody> bodies,
                    const double* inverseMass, const FrictionState* friction) {
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const ContactConstraint& c = contacts[k];
        const double invMassA = inverseMass[c.a], invMassB = inverseMass[c.b];
        const Vec2 p = c.normal * c.impulse;
        bodies[c.a].velocity += p * invMassA;
        bodies[c.b].velocity -= p * invMassB;
        if constexpr (Friction) {
            const FrictionTerms& f = friction->terms[k];
            if (f.impulse != 0.0) // a contact without friction (mu = 0) never holds an impulse
                applyFriction(c, friction->bodies[c.a], friction->bodies[c.b], f.impulse, invMassA, invMassB,
                              bodies[c.a], bodies[c.b], friction->omega[c.a], friction->omega[c.b]);
        }
    }
}

} // namespace

void warmStartContacts(std::span<const ContactConstraint> contacts, std::span<SolverBody> bodies,
                       std::span<const double> inverseMass, const FrictionState* friction) {
    if (friction) warmStartSweep<true>(contacts, bodies, inverseMass.data(), friction);
    else warmStartSweep<false>(contacts, bodies, inverseMass.data(), nullptr);
}

namespace {

/// The soft sweep, with or without friction: one template so the frictionless loop carries no test.
template <bool Friction>
void solveSweep(std::span<ContactConstraint> contacts, std::span<ContactRecord> records, std::span<SolverBody> bodies,
                const double* inverseMass, const Softness (&softness)[2], double h, int substep, double maxPushSpeed,
                const FrictionState* friction) {
    const double invH = 1.0 / h;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        ContactConstraint& c = contacts[k];
        SolverBody& a = bodies[c.a];
        SolverBody& b = bodies[c.b];
        const double invMassA = inverseMass[c.a], invMassB = inverseMass[c.b];
        // The current gap from the start gap and the relative displacement along the fixed normal.
        const double s = c.baseSeparation + c.normal.dot(a.displacement - b.displacement);
        const double vn = c.normal.dot(a.velocity - b.velocity);
        // Speculative (s > 0): closing by at most the gap this substep is allowed, vn >= -s / h, rigidly.
        // Overlapping: a soft push-out at the spring's bias rate, capped at maxPushSpeed.
        // A branch on the gap, not a select (see relaxSweep): most contacts keep their side of it.
        double bias, massScale, impulseScale;
        if (s > 0.0) {
            bias = s * invH;
            massScale = 1.0;
            impulseScale = 0.0;
        } else {
            const Softness& soft = softness[invMassB == 0.0 ? 1 : 0];
            bias = std::max(soft.biasRate * s, -maxPushSpeed);
            massScale = soft.massScale;
            impulseScale = soft.impulseScale;
        }
        // Sequential impulses with an accumulated, clamped impulse: lambda_total >= 0 (no pulling).
        const double delta = -c.normalMass * massScale * (vn + bias) - impulseScale * c.impulse;
        const double total = std::max(c.impulse + delta, 0.0);
        const double previous = c.impulse;
        const Vec2 p = c.normal * (total - previous);
        c.impulse = total;
        a.velocity += p * invMassA;
        b.velocity -= p * invMassB;
        // Starting to push from zero: the cold record is only touched on this rare transition.
        if (total > 0.0 && previous == 0.0) markFirstTouch(records[k], substep, h, s, vn);
        if constexpr (Friction) {
            FrictionTerms& f = friction->terms[k];
            // Friction is bounded by mu times the normal impulse: a contact that does not push and
            // holds no friction impulse (a speculative one, most of a pile's) has none to solve.
            if (f.friction > 0.0 && (c.impulse > 0.0 || f.impulse != 0.0))
                solveFriction(c, f, friction->bodies[c.a], friction->bodies[c.b], invMassA, invMassB, a, b,
                              friction->omega[c.a], friction->omega[c.b]);
        }
    }
}

} // namespace

void solveContacts(std::span<ContactConstraint> contacts, std::span<ContactRecord> records,
                   std::span<SolverBody> bodies, std::span<const double> inverseMass, const Softness (&softness)[2],
                   double h, int substep, double maxPushSpeed, const FrictionState* friction) {
    if (friction)
        solveSweep<true>(contacts, records, bodies, inverseMass.data(), softness, h, substep, maxPushSpeed, friction);
    else solveSweep<false>(contacts, records, bodies, inverseMass.data(), softness, h, substep, maxPushSpeed, nullptr);
}

namespace {

/// One relax sweep; `Measure` selects whether the gaps are computed from the displacements (and
/// stored) or read back from the first pass of this substep. Same arithmetic either way.
template <bool Measure>
void relaxSweep(std::span<ContactConstraint> contacts, std::span<ContactRecord> records, std::span<SolverBody> bodies,
                const double* inverseMass, double* gaps, double h, int substep) {
    const double invH = 1.0 / h;
    const std::size_t n = contacts.size();
    for (std::size_t k = 0; k < n; ++k) {
        ContactConstraint& c = contacts[k];
        SolverBody& a = bodies[c.a];
        SolverBody& b = bodies[c.b];
        const double invMassA = inverseMass[c.a], invMassB = inverseMass[c.b];
        double s;
        if constexpr (Measure) {
            s = c.baseSeparation + c.normal.dot(a.displacement - b.displacement);
            gaps[k] = s;
        } else {
            s = gaps[k];
        }
        const double vn = c.normal.dot(a.velocity - b.velocity);
        // Rigid, no push-out: vn >= 0 when touching, vn >= -s / h when still apart.
        // max(s, 0) / h, written as a branch: as a select (what std::max compiles to here) every
        // impulse waits for its gap, which the first pass computes from both bodies' displacements;
        // predicted, the sweep runs ahead on the velocities alone. The same value for every s (-0 and
        // NaN included); one step's relax pass replayed: 7.0 -> 4.8 ns a contact (20,000-ball pile).
        double bias;
        if (s < 0.0) bias = 0.0;
        else bias = s * invH;
        const double delta = -c.normalMass * (vn + bias);
        const double total = std::max(c.impulse + delta, 0.0);
        const double previous = c.impulse;
        const Vec2 p = c.normal * (total - previous);
        c.impulse = total;
        a.velocity += p * invMassA;
        b.velocity -= p * invMassB;
        // A speculative contact may first catch its circle here, after the substep's move.
        if (total > 0.0 && previous == 0.0) markFirstTouch(records[k], substep, h, s, vn);
    }
}

} // namespace

void relaxContacts(std::span<ContactConstraint> contacts, std::span<ContactRecord> records,
                   std::span<SolverBody> bodies, std::span<const double> inverseMass, std::span<double> gaps,
                   bool measureGaps, double h, int substep) {
    if (measureGaps) relaxSweep<true>(contacts, records, bodies, inverseMass.data(), gaps.data(), h, substep);
    else relaxSweep<false>(contacts, records, bodies, inverseMass.data(), gaps.data(), h, substep);
}

void applyRestitution(std::span<const ContactConstraint> contacts, std::span<const ContactRecord> records,
                      std::span<SolverBody> bodies, std::span<const double> inverseMass, double threshold,
                      Vec2 gravityStep) {
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const ContactConstraint& c = contacts[k];
        const ContactRecord& r = records[k];
        // Slow contacts rest: bouncing them would make a resting pile jitter forever.
        if (r.carried || r.firstTouch < 0 || r.bounciness == 0.0 || r.approachSpeed <= threshold) continue;
        SolverBody& a = bodies[c.a];
        SolverBody& b = bodies[c.b];
        const double vn = c.normal.dot(a.velocity - b.velocity);
        // Semi-implicit Euler conserves H = v^2/2 + g.x - (h/2) g.v in flight, not the energy; a bounce
        // flips v and so would lose h |v| of apex height each time. Reflecting u + |g.n| h instead of
        // u restores H exactly for C = 1. Two dynamic circles fall alike: no correction between them.
        const double invMassA = inverseMass[static_cast<std::size_t>(c.a)],
                     invMassB = inverseMass[static_cast<std::size_t>(c.b)];
        const double gravityInto = invMassB > 0.0 ? 0.0 : std::max(-gravityStep.dot(c.normal), 0.0);
        const double target = r.bounciness * (r.approachSpeed + gravityInto);
        // lambda = -m (vn - target), clamped so the accumulated impulse stays >= 0.
        const double delta = -c.normalMass * (vn - target);
        const double applied = std::max(c.impulse + delta, 0.0) - c.impulse;
        const Vec2 p = c.normal * applied;
        a.velocity += p * invMassA;
        b.velocity -= p * invMassB;
    }
}

} // namespace rube
