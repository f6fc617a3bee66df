// A lone bounce resolved at its time of impact, and the circle flown on for the rest of the step.
#include "solver_bounce_flight.hpp"

#include <vector>

namespace rube {

namespace {

/// A bounce to carry: its contact, and the circle's change of velocity and displacement.
struct Carry {
    std::size_t contact = 0;
    Vec2 velocityChange;
    Vec2 displacementChange;
    bool deferred = false; ///< touching early next step: left in flight, no impact this step
};

} // namespace

int carryPastImpact(std::span<ContactConstraint> contacts, std::span<ContactRecord> records,
                    std::span<SolverBody> bodies, std::span<const Circle> circles, std::span<const double> inverseMass,
                    std::span<const std::uint8_t> isBullet, int circleCount, double threshold, Vec2 gravity, double dt,
                    double h) {
    bool any = false;
    for (const ContactRecord& r : records) any = any || (r.impactTime >= 0.0 && r.firstTouch >= 0);
    if (!any) return 0; // most steps: nothing to carry, nothing counted
    std::vector<Carry> carries;
    std::vector<int> carryOf(static_cast<std::size_t>(circleCount), -1); // per circle: its entry in carries
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const ContactConstraint& c = contacts[k];
        const ContactRecord& r = records[k];
        const double t0 = r.impactTime;
        if (t0 < 0.0 || t0 > dt + h || r.firstTouch < 0 || r.bounciness == 0.0 || r.approachSpeed <= threshold)
            continue;
        const std::size_t a = static_cast<std::size_t>(c.a), b = static_cast<std::size_t>(c.b);
        if (inverseMass[b] > 0.0 || isBullet[a]) continue;
        // The other body (fixed, or kinematic at a constant velocity) keeps its velocity all step.
        const Vec2 relative = circles[a].velocity - bodies[b].velocity;
        const double gn = gravity.dot(c.normal);
        const double vn = c.normal.dot(bodies[a].velocity - bodies[b].velocity);
        const double s = c.baseSeparation + c.normal.dot(bodies[a].displacement - bodies[b].displacement);
        // The substeps (semi-implicit Euler, v += g h then x += v h) put the circle at x0 + v0 t +
        // g t (t + h) / 2, half a substep of gravity ahead of the exact parabola x0 + v0 t + g t^2 / 2
        // the exact method flies from the same state. A carried circle is put back on the exact
        // parabola along the surface (its tangential displacement less g_t dt h / 2; its velocity
        // v0 + g dt is exact) and given the normal state of the exact flight and bounce.
        const Vec2 tangentialLead = (gravity - c.normal * gn) * (0.5 * dt * h);
        if (t0 > dt) {
            // Touching early in the next step: the last substep's speculative constraint (vn >= -s / h)
            // caught it up to h early, at the end of this step. Left in free flight instead, it is
            // bounced at its time of impact next step: v.n = n.(v0 + g dt), gap = s0 + n.(v0 dt + g dt^2 / 2).
            const double normalVelocity = c.normal.dot(relative) + gn * dt;
            const double gap = c.baseSeparation + c.normal.dot(relative) * dt + 0.5 * gn * dt * dt;
            if (gap < 0.0) continue;
            carryOf[a] = static_cast<int>(carries.size());
            carries.push_back({k, c.normal * (normalVelocity - vn), c.normal * (gap - s) - tangentialLead, true});
            continue;
        }
        // Reflected at t0 on the exact parabola from the state as given: u = -n.(v0 + g t0) (lecture 3,
        // v.n -> C u), then free flight for tau = dt - t0 along n: v.n = C u + g.n tau, gap = C u tau + g.n tau^2 / 2.
        const double approach = -(c.normal.dot(relative) + gn * t0);
        if (approach <= threshold) continue;
        const double tau = dt - t0;
        const double gap = r.bounciness * approach * tau + 0.5 * gn * tau * tau;
        if (gap <= 0.0) continue; // back on the surface within the step: the end-of-step rule rests it
        const double normalVelocity = r.bounciness * approach + gn * tau;
        carryOf[a] = static_cast<int>(carries.size());
        carries.push_back({k, c.normal * (normalVelocity - vn), c.normal * (gap - s) - tangentialLead, false});
    }
    // A circle with any other contact (a speculative one: it pushed on nothing else) is near some
    // shape it could be carried into, or is one of a crowd (a pile's balls landing on its floor):
    // it keeps the end-of-step restitution.
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const ContactConstraint& c = contacts[k];
        for (const int body : {c.a, c.b}) {
            if (body >= circleCount) continue;
            const int i = carryOf[static_cast<std::size_t>(body)];
            if (i >= 0 && carries[static_cast<std::size_t>(i)].contact != k)
                carryOf[static_cast<std::size_t>(body)] = -2;
        }
    }
    int carried = 0;
    for (std::size_t i = 0; i < carries.size(); ++i) {
        const Carry& carry = carries[i];
        const ContactConstraint& c = contacts[carry.contact];
        const std::size_t a = static_cast<std::size_t>(c.a);
        if (carryOf[a] != static_cast<int>(i)) continue;
        SolverBody& circle = bodies[a];
        ContactRecord& r = records[carry.contact];
        circle.velocity += carry.velocityChange;
        circle.displacement += carry.displacementChange;
        r.carried = true;
        if (carry.deferred) {
            // Not touched yet: no impulse to warm start next step's contact with, no impact to record.
            contacts[carry.contact].impulse = 0.0;
            r.firstTouch = -1;
            continue;
        }
        // Flying away from the surface: no impulse to warm start next step's contact with (a warm
        // contact would hold the circle on the substeps rather than the exact flight).
        contacts[carry.contact].impulse = 0.0;
        // Where and when it touched: on the exact parabola p0 + v0 t + g t^2 / 2.
        const double t0 = r.impactTime;
        const Vec2 atImpact = circles[a].position + circles[a].velocity * t0 + gravity * (0.5 * t0 * t0);
        r.pointOfImpact = atImpact - c.normal * circles[a].radius;
        r.touchTime = t0;
        ++carried;
    }
    return carried;
}

} // namespace rube
