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

#include "contact_solver.hpp"

#include <algorithm>
#include <span>
#include <vector>

namespace rube {

/// Friction at one contact, parallel to its ContactConstraint (same index).
struct FrictionTerms {
    double armA = 0.0;            ///< rA: centre of a to the contact point, m (its radius)
    double armB = 0.0;            ///< rB: the same for b; 0 for segments, which never turn
    double inverseInertiaA = 0.0; ///< 1 / I of a
    double inverseInertiaB = 0.0; ///< 1 / I of b; 0 for segments and infinite mass
    double tangentMass = 0.0;     ///< 1 / (1/mA + 1/mB + rA^2/IA + rB^2/IB): effective mass along t
    double friction = 0.0;        ///< mu of the pair; 0 skips the contact
    double impulse = 0.0;         ///< accumulated tangential impulse this step
    Vec2 surfaceVelocityB;        ///< a conveyor's moving surface: b's contact point moves this much faster
};

/// What the contact sweeps need for friction: the terms per contact and each solver body's omega.
struct FrictionState {
    std::span<FrictionTerms> terms; ///< parallel to the contacts
    std::span<double> omega;        ///< per solver body, rad/s
};

/// The friction terms of `contacts` (mu from `friction(k)`; circles are solver bodies 0..n-1), each
/// warm started from its pair's impulse at the end of the last step (`records`): a pile's static
/// friction is held from one step to the next instead of rebuilt from zero, which lets it creep.
template <class FrictionOf>
void buildFriction(std::span<const ContactConstraint> contacts, std::span<const ContactRecord> records, std::span<const Circle> circles,
                   std::span<const Segment> segments, std::span<const double> inverseMass, FrictionOf friction,
                   std::vector<FrictionTerms>& out) {
    out.assign(contacts.size(), FrictionTerms{});
    const int circleCount = static_cast<int>(circles.size());
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const double mu = friction(k);
        if (mu <= 0.0) continue;
        const ContactConstraint& c = contacts[k];
        FrictionTerms& f = out[k];
        const Circle& ca = circles[static_cast<std::size_t>(c.a)];
        f.armA = ca.radius;
        f.inverseInertiaA = ca.inverseInertia;
        if (c.b < circleCount) {
            const Circle& cb = circles[static_cast<std::size_t>(c.b)];
            f.armB = cb.radius;
            f.inverseInertiaB = cb.inverseInertia;
        } else if (const Segment& s = segments[static_cast<std::size_t>(c.b - circleCount)]; s.surfaceSpeed != 0.0) {
            f.surfaceVelocityB = (s.b - s.a).normalized() * s.surfaceSpeed;
        }
        const double kt = inverseMass[static_cast<std::size_t>(c.a)] + inverseMass[static_cast<std::size_t>(c.b)] + f.armA * f.armA * f.inverseInertiaA + f.armB * f.armB * f.inverseInertiaB;
        f.tangentMass = kt > 0.0 ? 1.0 / kt : 0.0;
        f.friction = mu;
        f.impulse = records[k].tangentImpulse;
    }
}

/// Applies a tangential impulse lambda t at the contact: on a, and its opposite on b.
inline void applyFriction(const ContactConstraint& c, const FrictionTerms& f, double lambda, double invMassA, double invMassB,
                          SolverBody& a, SolverBody& b, double& omegaA, double& omegaB) {
    const Vec2 p = c.normal.perpendicular() * lambda;
    a.velocity += p * invMassA;
    b.velocity -= p * invMassB;
    omegaA -= f.inverseInertiaA * f.armA * lambda;
    omegaB -= f.inverseInertiaB * f.armB * lambda;
}

/// One friction update at a contact: drives the slip speed to zero within the Coulomb cone
/// |lambda_t| <= mu lambda_n, using the contact's normal impulse as it stands now.
inline void solveFriction(const ContactConstraint& c, FrictionTerms& f, double invMassA, double invMassB, SolverBody& a,
                          SolverBody& b, double& omegaA, double& omegaB) {
    const double vt = c.normal.perpendicular().dot(a.velocity - b.velocity - f.surfaceVelocityB) - f.armA * omegaA - f.armB * omegaB;
    const double limit = f.friction * c.impulse;
    const double total = std::clamp(f.impulse - f.tangentMass * vt, -limit, limit);
    const double delta = total - f.impulse;
    f.impulse = total;
    applyFriction(c, f, delta, invMassA, invMassB, a, b, omegaA, omegaB);
}

} // namespace rube
