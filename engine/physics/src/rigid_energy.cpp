// A bounce never adds energy: restitution against fixed things is scaled back to the energy the body
// began the step with.
//
// Restitution drives each point's normal speed to C times its approach (v' = -C vn, lecture 3), from
// the velocities the substeps left. Those already hold what friction and the soft push-out did in
// the step, and a body turning fast turns a corner's push into spin and the spin into speed along
// the floor (a capsule landing almost flat skids off faster than it came). Against fixed things no
// force but gravity does work, so E_end = KE' + PE_end <= KE_0 + PE_0 must hold for C <= 1: when
// restitution's change du would break it, only the fraction s of du that keeps it is applied.
#include "rigid_stage.hpp"

#include <algorithm>
#include <cmath>

namespace rube {

namespace {

/// Kinetic energy m v^2 / 2 + I omega^2 / 2 of a rigid state (its masses are inverses; 0 is infinite).
double kineticEnergy(const RigidState& s, Vec2 v, double omega) {
    double e = 0.5 * v.lengthSquared() / s.inverseMass;
    if (s.inverseInertia > 0.0) e += 0.5 * omega * omega / s.inverseInertia;
    return e;
}

/// The velocity of a side that cannot be moved and does not turn (a fixed or translating segment,
/// circle or body); false for anything movable or turning.
bool unmovableVelocity(const RigidSolverView& view, BodySide side, Vec2& velocity) {
    const LoadedBody l = load(view, side);
    velocity = l.velocity;
    return l.inverseMass == 0.0 && l.inverseInertia == 0.0 && l.omega == 0.0;
}

/// A bounce that leaves this much more energy than the budget (as a fraction of the body's kinetic
/// energy plus m |g| times its half thickness) was not a bounce but the substeps running away: a body
/// struck on a corner at hundreds of m/s spins so fast that its contacts' fixed anchors mean nothing.
constexpr double kRunawayFraction = 0.05;
/// Bodies in a worker's share of the energy check (a body costs tens of nanoseconds).
constexpr std::size_t kEnergyChunk = 256;

} // namespace

void RigidStage::capBounceEnergy() {
    const std::size_t n = rigidCount_;
    onlyFixed_.assign(n, 1);
    frame_.assign(n, Vec2{});
    seenFrame_.assign(n, 0);
    // Each body's unmovable partners must share one velocity u: energy is counted in their frame.
    const auto meet = [&](std::size_t i, bool unmovable, Vec2 u) {
        if (!unmovable) {
            onlyFixed_[i] = 0;
        } else if (!seenFrame_[i]) {
            seenFrame_[i] = 1;
            frame_[i] = u;
        } else if (frame_[i].x != u.x || frame_[i].y != u.y) {
            onlyFixed_[i] = 0;
        }
    };
    // Colour by colour, shared among the workers: no two contacts of a colour share a movable body, and
    // only movable bodies are met (the others are left alone below). The outcome for a body does not
    // depend on the order its contacts are met in: it keeps the frame only if all of them agree on it.
    sweepColours(pool_, colours_, [&](std::size_t first, std::size_t last) {
        for (std::size_t k = first; k < last; ++k) {
            const RigidContact& c = contacts_[k];
            Vec2 u;
            // A conveyor's belt does work on what it carries: not a fixed partner.
            const bool unmovable = unmovableVelocity(view_, c.b, u) && c.tangentSpeed == 0.0;
            const auto a = static_cast<std::size_t>(c.a.index);
            if (states_[a].inverseMass != 0.0) meet(a, unmovable, u);
            if (c.b.rigid && states_[static_cast<std::size_t>(c.b.index)].inverseMass != 0.0)
                meet(static_cast<std::size_t>(c.b.index), false, u);
        }
    });
    // A pinned body is held by its pivot, which does no work but is not a contact: left alone.
    for (const PivotConstraint& p : pivots_) onlyFixed_[static_cast<std::size_t>(p.body)] = 0;
    // Likewise a body a joint holds (a motor or a spring may do work on it).
    if (!joints_.empty())
        for (std::size_t i = 0; i < n; ++i)
            if (joints_.holdsBody(static_cast<int>(i))) onlyFixed_[i] = 0;
    const double g = gravity_.length();
    // Each body on its own from here: any split among the workers, the same bits.
    forShares(pool_, n, kEnergyChunk, [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) {
            RigidState& s = states_[i];
            const RigidState& before = beforeBounce_[i];
            if (!onlyFixed_[i] || s.inverseMass == 0.0) continue;
            const Vec2 u = frame_[i];
            // E = KE + m (-g) . x in the partners' frame: the energy it began with, less the potential
            // energy where it ends (the frame has moved u dt by then).
            const double m = 1.0 / s.inverseMass;
            const Vec2 end = startPosition_[i] + s.displacement - u * stepTime_;
            const double startEnergy = kineticEnergy(s, startVelocity_[i] - u, startOmega_[i]);
            const double budget = startEnergy - m * gravity_.dot(startPosition_[i]) + m * gravity_.dot(end);
            const Vec2 dv = s.velocity - before.velocity;
            const double dw = s.omega - before.omega;
            if (kineticEnergy(s, s.velocity - u, s.omega) > budget && (dv.x != 0.0 || dv.y != 0.0 || dw != 0.0)) {
                // KE(s) = KE0 + B s + A s^2 along before + s du: the largest s in [0, 1] within the budget,
                // or (already over it before the bounce) the s that adds least.
                const double inertia = s.inverseInertia > 0.0 ? 1.0 / s.inverseInertia : 0.0;
                const double a = 0.5 * (m * dv.lengthSquared() + inertia * dw * dw);
                const double b = m * (before.velocity - u).dot(dv) + inertia * before.omega * dw;
                const double ke0 = kineticEnergy(s, before.velocity - u, before.omega);
                double scale = std::clamp(-b / (2.0 * a), 0.0, 1.0);
                if (ke0 <= budget) {
                    // The larger root of A s^2 + B s + (KE0 - budget) = 0; KE0 - budget <= 0 keeps it real.
                    const double c = ke0 - budget;
                    scale = std::clamp((-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a), 0.0, 1.0);
                }
                s.velocity = before.velocity + dv * scale;
                s.omega = before.omega + dw * scale;
            }
            // Still far over: the substeps ran away. The body takes its free flight for the step instead
            // (semi-implicit Euler, as the substeps integrate it) and the continuous pass finds where that
            // meets a segment and bounces it there.
            const double excess = kineticEnergy(s, s.velocity - u, s.omega) - budget;
            if (!(excess <= kRunawayFraction * (startEnergy + m * g * thickness_[i]))) runFree(i);
        }
    });
}

void RigidStage::runFree(std::size_t i) {
    RigidState& s = states_[i];
    s.velocity = startVelocity_[i];
    s.displacement = {};
    for (int k = 0; k < substeps_; ++k) {
        s.velocity += gravity_ * substepTime_;
        s.displacement += s.velocity * substepTime_;
    }
    s.omega = startOmega_[i];
    s.turn = s.omega * stepTime_;
    s.turnRotation = {std::cos(s.turn), std::sin(s.turn)};
}

} // namespace rube
