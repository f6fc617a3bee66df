#pragma once
// Internal: contact constraints between a rigid body (box, capsule) and anything else (another
// rigid body, a circle, a segment), with Coulomb friction and restitution, solved in the circle
// solver's substeps (the soft step of Box2D v3). Not part of the public API.
//
// A contact point keeps its anchors rA, rB (from each body's centre, at the step's start) for the
// whole step; its gap in a substep follows from how far the bodies moved and turned since:
//     s = n . ((dpB + R(turnB) rB) - (dpA + R(turnA) rA)) + s0 - n . (rB - rA),
// so no narrowphase runs inside the substeps. With the point velocities v + omega x r,
// an impulse P = lambda n on B (and -P on A) changes vn by lambda / normalMass with
//     1 / normalMass = 1/mA + 1/mB + (rA x n)^2 / IA + (rB x n)^2 / IB.

#include "rigid_manifold.hpp"
#include "rigid_solver_body.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace rube {

/// One point of a rigid contact.
struct RigidContactPoint {
    Vec2 anchorA, anchorB;       ///< from each body's centre at the step's start, m
    Vec2 armA, armB;             ///< the anchors turned with their bodies as they stand this substep (refreshArms)
    double baseSeparation = 0.0; ///< s0 - n . (rB - rA): the gap formula's constant term
    double normalMass = 0.0;
    double tangentMass = 0.0;
    double normalImpulse = 0.0; ///< of the current substep (warm starts the next), >= 0
    double tangentImpulse = 0.0;
    double deliveredNormal = 0.0; ///< normal impulse this point applied over the step so far (all substeps), N s
    double deliveredTangent =
        0.0; ///< tangent impulse likewise: with the normal one, what measureApproach takes back out
    double maxNormalImpulse = 0.0; ///< largest normal impulse of the step: 0 means it never touched
    double approachSpeed = 0.0;    ///< -vn before the substep in which it first pushed: what restitution reverses
    int touchSubstep = 0;          ///< the substep in which it first pushed (once maxNormalImpulse > 0)
    std::uint32_t feature = 0;     ///< which faces and vertices made it (the manifold's id): the warm-start key
    bool carried = false;          ///< warm started from the last step: resting contact, never a new impact
};

/// A manifold turned into a constraint: one normal, up to two points.
struct RigidContact {
    BodySide a, b;
    int bodyA = 0, bodyB = 0;  ///< the sides in the rigid stage's solver bodies (RigidStage::states_)
    Vec2 normal;               ///< unit, from A towards B
    Vec2 tangent;              ///< the normal turned a quarter anticlockwise: friction's direction
    bool againstFixed = false; ///< a side cannot be moved: the contact takes the stiffer softness
    /// Between two shapes (boxes, capsules, planks, lines) of which no pivot or joint holds either:
    /// a contact of a stack or a heap, stiffer and relaxed once (RigidContactSoftness; method_solver.cpp,
    /// kRigidContactRelaxPasses). Not: a ball's contacts and a mechanism's.
    bool stacking = false;
    double friction = 0.0;   ///< mu of the pair: the product of both materials' (as circle pairs)
    double bounciness = 0.0; ///< C of the pair: the product of both materials'
    /// How fast B's surface runs along the tangent on its own (a conveyor's belt: t . its surface
    /// velocity): friction drives the points' slip vt + tangentSpeed to zero. 0 for anything else.
    double tangentSpeed = 0.0;
    int count = 0;
    RigidContactPoint points[2];
};

/// The constraint for `manifold` between sides a and b whose centres were `centreA` and `centreB`
/// at the step's start.
RigidContact makeRigidContact(const RigidSolverView& view, BodySide a, BodySide b, Vec2 centreA, Vec2 centreB,
                              const Manifold& manifold, double friction, double bounciness);

/// The contact stiffness: a soft spring against a movable body, and one twice as stiff against
/// infinite mass (it moves one body only), as the circle contacts are.
struct RigidContactSoftness {
    Softness movable;          ///< between two movable bodies
    Softness fixed;            ///< against infinite mass
    Softness stackMovable;     ///< a stacking contact (RigidContact::stacking) between two movable bodies
    Softness stackFixed;       ///< a stacking contact against infinite mass
    double maxPushSpeed = 3.0; ///< m/s: deep overlaps are pushed out no faster
    /// The softness of a contact, stacking or not, against infinite mass or not.
    const Softness& of(bool stacking, bool againstFixed) const {
        return stacking ? (againstFixed ? stackFixed : stackMovable) : (againstFixed ? fixed : movable);
    }
};

/// The functions below act on the rigid stage's solver bodies, indexed by bodyA and bodyB. The stage
/// runs restitution as it is; warm starting, the approach measure, the arms and the sweep it runs in
/// their block forms (rigid_contact_blocks.hpp), and these one-contact-at-a-time forms are what those
/// must equal bit for bit (tests/rigid_lanes_test.cpp) and where their formulas are written out.

/// Applies every point's last impulses again as the starting guess (warm starting). A contact whose
/// body turns more than `maxTurn` radians in the substep of length h starts from zero instead: its
/// anchors have swung so far that the old impulse, applied at the new arms, pumps energy in (a box
/// struck on a corner at 500 m/s spins at 10^4 rad/s, and warm starting then diverged within one step).
void warmStartRigidContacts(std::span<RigidContact> contacts, std::span<RigidState> bodies, double h, double maxTurn);

/// Before a substep's impulses: each point that has not pushed yet notes its approach speed -vn.
/// Measured before any impulse, as Box2D measures it before the step: a point measured inside the sweep
/// would count the spin its neighbour's impulse just gave the body (the far end of a plank landing
/// flat dips faster), and bouncing that back would add energy. For the same reason the impulses its
/// own contact's points delivered in earlier substeps are taken back out of vn: a box landing on one
/// corner while spinning swings its other corner down within the step, and that corner's approach is
/// then the one it had without the first corner's push (restitution's targets C a with a = -J u_free
/// leave the energy at most the free motion's: KE' = KE_free - (1 - C^2) / 2 a^T K^-1 a).
/// `substep` is the substep about to run: a point that has not pushed yet notes it as its touch substep.
void measureApproach(std::span<RigidContact> contacts, std::span<const RigidState> bodies, int substep);

/// One Gauss-Seidel sweep: normal impulses (soft push-out when `useBias`, speculative gaps always
/// kept), then friction within the Coulomb cone |lambda_t| <= mu lambda_n.
void solveRigidContacts(std::span<RigidContact> contacts, std::span<RigidState> bodies,
                        const RigidContactSoftness& softness, double h, bool useBias);

/// Restitution once per step for points that touched faster than `threshold`: the normal velocity
/// becomes -C times the approach speed (v' = -C vn, lecture 3).
void applyRigidRestitution(std::span<RigidContact> contacts, std::span<RigidState> bodies, double threshold);

/// Turns every point's anchors with their bodies as they stand now (armA, armB): the sweeps of a
/// substep all read the same arms, so they are computed once after each change of the bodies' turns.
void refreshArms(std::span<RigidContact> contacts, std::span<const RigidState> bodies);

/// Which softness the contact takes, from its sides' masses in `bodies` (constant over the step).
void chooseSoftness(std::span<RigidContact> contacts, std::span<const RigidState> bodies);

} // namespace rube
