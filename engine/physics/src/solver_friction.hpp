#pragma once
// Internal: Coulomb friction for the soft-step solver, solved inside the contact sweeps (the same
// bodies are already loaded), and only in steps where some pair has friction or some circle spins:
// a frictionless scene never touches any of this.
//
// With n the unit normal from b to a and t = perp(n), the contact point is r_A = -n rA from a's
// centre and r_B = n rB from b's. Since omega x r = omega perp(r), t . (omega_A x r_A) = -rA omega_A
// and t . (omega_B x r_B) = rB omega_B, so the slip speed of the contact points is
//     vt = t . (vA - vB) - rA omega_A - rB omega_B,
// and an impulse lambda t on a (and -lambda t on b) changes it by lambda / tangentMass, turning each
// circle by -r lambda / I (r_A x t = -rA for a; r_B x (-t) = -rB for b).

#include "solver_soft_step.hpp"

#include <algorithm>
#include <span>
#include <vector>

namespace rube {

/// Friction at one contact, parallel to its ContactConstraint (same index). 24 bytes: the soft
/// sweep streams these beside the contacts every substep, and in a 20,000-ball pile neither fits in
/// cache, so what belongs to a body (arm, inertia, a belt's speed) is read from its FrictionBody.
struct FrictionTerms {
    double tangentMass = 0.0; ///< 1 / (1/mA + 1/mB + rA^2/IA + rB^2/IB): effective mass along t
    double friction = 0.0;    ///< mu of the pair; 0 skips the contact
    double impulse = 0.0;     ///< accumulated tangential impulse this step
};

/// A solver body as friction sees it: the arm from its centre to a contact point, how much a unit
/// tangential impulse there turns it, and how fast its surface moves (a conveyor's belt). Segments
/// never turn: arm and turn 0.
struct FrictionBody {
    double arm = 0.0;            ///< r: a circle's radius
    double turnPerImpulse = 0.0; ///< r / I, rad/s per N s
    Vec2 surfaceVelocity;        ///< a conveyor's belt velocity along the segment, m/s
};

/// What the contact sweeps need for friction: the terms per contact, and each solver body's arm and omega.
struct FrictionState {
    std::span<FrictionTerms> terms;       ///< parallel to the contacts
    std::span<const FrictionBody> bodies; ///< per solver body
    std::span<double> omega;              ///< per solver body, rad/s
};

/// Each solver body's friction side: circles 0..n-1, then segments (a belt's surface velocity).
inline void buildFrictionBodies(std::span<const Circle> circles, std::span<const Segment> segments,
                                std::size_t bodyCount, std::vector<FrictionBody>& out) {
    out.assign(bodyCount, FrictionBody{});
    for (std::size_t i = 0; i < circles.size(); ++i)
        out[i] = {circles[i].radius, circles[i].inverseInertia * circles[i].radius, {}};
    for (std::size_t s = 0; s < segments.size(); ++s)
        if (segments[s].surfaceSpeed != 0.0) out[circles.size() + s].surfaceVelocity = segments[s].beltVelocity();
}

/// The friction terms of `contacts` (mu from `friction(k)`; circles are solver bodies 0..n-1), each
/// warm started from its pair's impulse at the end of the last step (`records`): a pile's static
/// friction is held from one step to the next instead of rebuilt from zero, which lets it creep.
template <class FrictionOf>
void buildFriction(std::span<const ContactConstraint> contacts, std::span<const ContactRecord> records,
                   std::span<const Circle> circles, std::span<const double> inverseMass, FrictionOf friction,
                   std::vector<FrictionTerms>& out) {
    out.assign(contacts.size(), FrictionTerms{});
    const int circleCount = static_cast<int>(circles.size());
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const double mu = friction(k);
        if (mu <= 0.0) continue;
        const ContactConstraint& c = contacts[k];
        FrictionTerms& f = out[k];
        const Circle& ca = circles[static_cast<std::size_t>(c.a)];
        double kt = inverseMass[static_cast<std::size_t>(c.a)] + inverseMass[static_cast<std::size_t>(c.b)] +
                    ca.radius * ca.radius * ca.inverseInertia;
        if (c.b < circleCount) {
            const Circle& cb = circles[static_cast<std::size_t>(c.b)];
            kt += cb.radius * cb.radius * cb.inverseInertia;
        }
        f.tangentMass = kt > 0.0 ? 1.0 / kt : 0.0;
        f.friction = mu;
        f.impulse = records[k].tangentImpulse;
    }
}

/// Applies a tangential impulse lambda t at the contact: on a, and its opposite on b.
inline void applyFriction(const ContactConstraint& c, const FrictionBody& fa, const FrictionBody& fb, double lambda,
                          double invMassA, double invMassB, SolverBody& a, SolverBody& b, double& omegaA,
                          double& omegaB) {
    const Vec2 p = c.normal.perpendicular() * lambda;
    a.velocity += p * invMassA;
    b.velocity -= p * invMassB;
    omegaA -= fa.turnPerImpulse * lambda;
    omegaB -= fb.turnPerImpulse * lambda;
}

/// One friction update at a contact: drives the slip speed to zero within the Coulomb cone
/// |lambda_t| <= mu lambda_n, using the contact's normal impulse as it stands now.
inline void solveFriction(const ContactConstraint& c, FrictionTerms& f, const FrictionBody& fa, const FrictionBody& fb,
                          double invMassA, double invMassB, SolverBody& a, SolverBody& b, double& omegaA,
                          double& omegaB) {
    const double vt = c.normal.perpendicular().dot(a.velocity - b.velocity - fb.surfaceVelocity) - fa.arm * omegaA -
                      fb.arm * omegaB;
    const double limit = f.friction * c.impulse;
    const double total = std::clamp(f.impulse - f.tangentMass * vt, -limit, limit);
    const double delta = total - f.impulse;
    f.impulse = total;
    applyFriction(c, fa, fb, delta, invMassA, invMassB, a, b, omegaA, omegaB);
}

} // namespace rube
