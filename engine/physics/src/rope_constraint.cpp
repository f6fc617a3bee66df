// Ropes as a one-sided distance constraint |p_a - p_b| <= L, enforced after each method's step.
//
// Why after the step: every method (discrete, turn-based, exact, solver) moves a roped ball as if
// free, under gravity, fields and impacts, and the rope is then honoured the same way for all of
// them; a world without ropes never enters this file. For a rope that ends the step longer than L:
//
// A rope taut all step, its ball hitting nothing: the ball went round the circle. Its tension is
// central and does no work, so the pass integrates the rope's angle itself, as semi-implicit Euler
// (lecture 3: velocity first, then position with the new velocity) in polar form:
//     omega' = (t0 . v_rel') / L,   theta' = theta + omega' dt,
// with v_rel' the relative velocity the method ended with (gravity and fields included) and t0 the
// tangent at the start. The ends are put L apart at theta', and v_rel' is turned by theta' - theta,
// which keeps its length (the centripetal part of the tension), then loses its radial part (the
// part of gravity the rope holds). For a pendulum this is theta'' = -(g / L) sin(theta), symplectic:
// its energy error stays bounded, and its period is short by (omega dt)^2 / 24. The method's own
// position is not used: the exact method's p + v t + g t^2 / 2 with the velocity at its end is not
// symplectic, and made a swing gain energy every period.
//
// A rope that was slack, or whose ball hit something this step: the method's positions stand, and
// the ends are pulled back along the rope, n = d / |d|. A rope jerking taut is a perfectly inelastic
// impact along it (lecture 3 with C = 0): the stretching speed v_rel . n > 0 is removed.
//
// Corrections are shared by inverse mass, w_i / (w_a + w_b), so between two dynamic circles momentum
// and the centre of mass are kept; an anchor, a kinematic or a static circle has w = 0 and does not move.
#include "rope_constraint.hpp"

#include <cmath>

namespace rube {

namespace {

// A rope counts as taut when its ends are apart by at least this share of its length less than L:
// after the pass they are L apart to rounding, a few parts in 1e16.
constexpr double kTautTolerance = 1e-9;
// Extra passes over the ropes when some rope joins two circles: each pass shrinks what the last
// one left stretched in a chain; 8 hold a double pendulum's ropes to 0.02 mm at 60 Hz (pendulum.toml).
constexpr int kChainPasses = 8;

double inverseMassOf(const Circle& c) { return c.motion == Motion::dynamic ? c.inverseMass : 0.0; }

Vec2 farEnd(std::span<const Circle> circles, const Rope& rope) {
    return rope.other >= 0 ? circles[static_cast<std::size_t>(rope.other)].position : rope.anchor;
}

bool hitSomething(std::span<const Impact> impacts, int circle) {
    for (const Impact& impact : impacts)
        if (impact.circle == circle || (impact.otherKind == Other::circle && impact.other == circle)) return true;
    return false;
}

// v turned counter-clockwise by the angle whose cosine and sine are c and s.
Vec2 turn(Vec2 v, double c, double s) { return {c * v.x - s * v.y, s * v.x + c * v.y}; }

// Puts the rope's ends exactly L apart along the unit n (from the far end to a), then removes any
// relative velocity that still stretches it: v_rel . n <= 0, an inelastic jerk along the rope.
// Against an anchor or an immovable circle only the other end moves; between two dynamic circles
// each moves by its share w_i / (w_a + w_b), so their centre of mass and momentum stay.
void pullTaut(Circle& a, Circle* b, const Rope& rope, Vec2 n, Vec2 relative) {
    const double wa = inverseMassOf(a), wb = b ? inverseMassOf(*b) : 0.0;
    const double w = wa + wb;
    if (!(w > 0.0)) return;
    const double shareA = wa / w, shareB = wb / w;
    const Vec2 target = n * rope.length;
    if (!b || wb == 0.0) {
        a.position = (b ? b->position : rope.anchor) + target;
    } else if (wa == 0.0) {
        b->position = a.position - target;
    } else {
        const Vec2 centre = a.position * shareB + b->position * shareA; // (m_a p_a + m_b p_b) / M
        a.position = centre + target * shareA;
        b->position = centre - target * shareB;
    }
    const double stretching = relative.dot(n);
    if (stretching > 0.0) {
        a.velocity -= n * (stretching * shareA);
        if (b) b->velocity += n * (stretching * shareB);
    }
}

} // namespace

void recordRopeStarts(std::span<const Circle> circles, std::span<const Rope> ropes, std::vector<RopeStart>& starts) {
    starts.resize(ropes.size());
    for (std::size_t k = 0; k < ropes.size(); ++k) {
        const Rope& rope = ropes[k];
        if (rope.cut) continue;
        const Circle& a = circles[static_cast<std::size_t>(rope.circle)];
        const Vec2 offset = a.position - farEnd(circles, rope);
        const double taut = rope.length * (1.0 - kTautTolerance);
        // An asleep rope (its ends asleep or immovable) is compared squared: no square root for a
        // rope that sleeps (the same answer but within rounding at the tolerance's edge).
        const bool asleep = a.sleep.asleep &&
                            (rope.other < 0 || circles[static_cast<std::size_t>(rope.other)].sleep.asleep ||
                             inverseMassOf(circles[static_cast<std::size_t>(rope.other)]) == 0.0);
        starts[k] = {offset, asleep ? offset.lengthSquared() >= taut * taut : offset.length() >= taut};
    }
}

void enforceRopes(std::span<Circle> circles, std::span<const Rope> ropes, std::span<const RopeStart> starts,
                  std::span<const Impact> impacts, double dt) {
    for (std::size_t k = 0; k < ropes.size(); ++k) {
        const Rope& rope = ropes[k];
        if (rope.cut) continue;
        Circle& a = circles[static_cast<std::size_t>(rope.circle)];
        Circle* b = rope.other >= 0 ? &circles[static_cast<std::size_t>(rope.other)] : nullptr;
        const double wa = inverseMassOf(a), wb = b ? inverseMassOf(*b) : 0.0;
        // Asleep (solver_sleep.hpp: zero velocity, put to sleep within this step's method, after it
        // moved them g dt^2 past the rope): the ends are only put back L apart where they lie, once,
        // the step it fell asleep; no square root otherwise.
        const bool asleep = a.sleep.asleep && (!b || b->sleep.asleep || wb == 0.0);
        if (asleep && (a.position - (b ? b->position : rope.anchor)).lengthSquared() <= rope.length * rope.length)
            continue;
        const double w = wa + wb;
        if (!(w > 0.0)) continue; // both ends immovable: nothing the rope could do
        const double shareA = wa / w, shareB = wb / w;
        const Vec2 vb = b ? b->velocity : Vec2{};
        Vec2 relative = a.velocity - vb;
        const RopeStart& start = starts[k];
        const bool freeSwing = start.taut && !asleep && !hitSomething(impacts, rope.circle) &&
                               (!b || !hitSomething(impacts, rope.other));
        // Where the ends would be apart by now: the method's word, or semi-implicit Euler's for a free swing.
        const Vec2 offset = freeSwing ? start.offset + relative * dt : a.position - (b ? b->position : rope.anchor);
        const double distance = offset.length();
        if (distance <= rope.length || distance == 0.0) continue; // slack: a rope never pushes
        Vec2 n = offset / distance;
        if (start.taut) {
            double c = 0.0, s = 0.0;
            if (freeSwing) {
                // theta' - theta = omega' dt, the arc length the tangential velocity covers over L.
                const Vec2 n0 = start.offset.normalized();
                const double turned = n0.perpendicular().dot(relative) * dt / rope.length;
                c = std::cos(turned);
                s = std::sin(turned);
                n = turn(n0, c, s);
            } else {
                // The angle from the start direction to the end one: cos = n0 . n, sin = n0 x n.
                const Vec2 n0 = start.offset.normalized();
                c = n0.dot(n);
                s = n0.cross(n);
            }
            // The centripetal part of the tension only turns v_rel: no work, |v_rel| unchanged.
            const Vec2 turnedVelocity = turn(relative, c, s);
            const Vec2 change = turnedVelocity - relative;
            a.velocity += change * shareA;
            if (b) b->velocity -= change * shareB;
            relative = turnedVelocity;
        }
        pullTaut(a, b, rope, n, relative);
    }
    // Ropes that share a ball (a chain, a double pendulum) were pulled taut one after another, so
    // each may have stretched the one before it: a few more passes along the ropes as they now lie
    // (Gauss-Seidel, as the solver's contacts are), only in worlds with a rope between two circles.
    bool chained = false;
    for (const Rope& rope : ropes) chained = chained || (!rope.cut && rope.other >= 0);
    for (int pass = 0; chained && pass < kChainPasses; ++pass) {
        for (const Rope& rope : ropes) {
            if (rope.cut) continue;
            Circle& a = circles[static_cast<std::size_t>(rope.circle)];
            Circle* b = rope.other >= 0 ? &circles[static_cast<std::size_t>(rope.other)] : nullptr;
            const Vec2 d = a.position - (b ? b->position : rope.anchor);
            const double distance = d.length();
            if (distance <= rope.length || distance == 0.0) continue;
            pullTaut(a, b, rope, d / distance, a.velocity - (b ? b->velocity : Vec2{}));
        }
    }
}

} // namespace rube
