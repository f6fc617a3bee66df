#pragma once
// Internal: the rigid bodies' part of the solver's step. The solver calls it at the same points of
// its substep loop as its own circle contacts (integrate velocities, warm start, solve, integrate
// positions, relax; restitution at the end), so pivots, rigid contacts and circle contacts are one
// Gauss-Seidel system over the same velocities. A world without rigid bodies never enters it.
// Not part of the public API.

#include "joint_stage.hpp"
#include "pivot_joint.hpp"
#include "rigid_colours.hpp"
#include "rigid_contact_blocks.hpp"
#include "rigid_pairs.hpp"
#include "rigid_contacts.hpp"
#include "rigid_warm_start.hpp"
#include "step_method.hpp"

#include <bit>
#include <cstdint>
#include <vector>

namespace rube {

struct SweptShape;

/// The rigid bodies, their contacts and pivots during the solver's step.
class RigidStage {
public:
    /// Sets up the step: body states, every contact of a rigid body (found once, with speculative
    /// margins for how far things may move in `dt`) and the pivots, all as they stand at the step's start.
    void prepare(const StepContext& ctx, double dt);
    /// Bodies changed slots between steps: the warm starts follow them (RigidContactCache::remap).
    void remapSlots(const SlotRemap& remap) { cache_.remap(remap); }
    /// Calls `list(i)` for each circle that meets a rigid body with friction (it must turn this step).
    template <class List>
    void listFrictionCircles(List list) const {
        for (std::size_t k = 0; k < listed_.size(); ++k) {
            const RigidContact& c = listedContact(k);
            if (c.friction > 0.0 && !c.b.rigid && c.b.index < circleCount_) list(c.b.index);
        }
    }
    /// Binds the circle solver's bodies and omegas (empty when the step has no rotation) for the substeps.
    void bind(std::span<SolverBody> others, std::span<double> omega, std::span<const Circle> circles);
    /// Substep stage: gravity on the dynamic rigid bodies.
    void integrateVelocities(Vec2 gravityStep);
    /// Substep stage: contacts note their approach speeds, then pivots and contacts apply last substep's impulses.
    void warmStart();
    /// Substep stage: pivots then contacts, with soft position feedback when `useBias` (else a relax
    /// pass); with `everyRelaxOnly`, of the contacts only the blocks that take every relax pass
    /// (RigidBlock::everyRelax: any but the stacking contacts).
    void solve(double h, bool useBias, bool everyRelaxOnly = false);
    /// Substep stage: displacement and turn of every rigid body.
    void integratePositions(double h);
    /// Restitution once per step.
    void applyRestitution(double threshold);
    /// Writes the rigid bodies' new state back into the world.
    void finish(StepContext& ctx) const;
    /// Reports every rigid contact that first touched this step faster than the resting speed as an
    /// Impact (counted in the stats, as the circle contacts' are) and returns how many (rigid_impacts.cpp).
    int recordImpacts(StepContext& ctx);
    /// The continuous pass, after finish() and before kinematic segments move: a body that moved or
    /// turned further than its half thickness and ends through a segment it met on the way is put back
    /// at its time of impact and bounced there; returns the impacts recorded (rigid_sweep.cpp).
    int sweep(StepContext& ctx, double dt);

    /// The step's rigid contacts in colour order (for the sleeping islands, after the step): made at
    /// bind(), so between prepare() and bind() they are still the last step's.
    std::span<const RigidContact> contacts() const { return contacts_; }
    /// Sleepers that an awake dynamic body's contacts, or a moving kinematic body's box, reach this
    /// step: circle c as c, rigid body i as -1 - i (SleepIslands::wakeReached wakes their islands).
    std::span<const int> reached() const { return reached_; }
    /// Per joint (the step's ctx.joints), after the step: 1 where its motor is stalled at a limit
    /// (JointStage::motorsStalled), which lets its island sleep as a braked one may.
    std::span<const std::uint8_t> stalledMotors() const { return stalledMotors_; }

    /// An axis-aligned bounding box, for the pair test.
    using Box = BoundingBox;

private:
    /// Bodies in a worker's chunk of a per-body loop (fewer than two chunks run on the calling thread):
    /// a body's update costs a few nanoseconds, a hand-over about a microsecond.
    static constexpr std::size_t kBodyChunk = 256;
    /// Candidate pairs in a chunk of the narrowphase (a manifold costs about 0.1 us).
    static constexpr std::size_t kPairChunk = 64;
    /// Speculative distance every pair gets on top of its motion (Box2D's four linear slops): a plank
    /// resting on a ball keeps its contact while either moves a little.
    static constexpr double kSpeculativeDistance = 0.02;
    /// The box around `p` grown by its radius and `extra` (rigid_find_contacts.cpp).
    static BoundingBox boundsOf(const RoundedPolygon& p, double extra);
    /// The step's contacts, listed, and the sleepers reached (rigid_find_contacts.cpp).
    void findContacts(const StepContext& ctx, double dt);
    /// contactSoftness_ and pivotSoftness_ for substeps of h (rigid_softness.cpp).
    void chooseSoftnesses(double h);
    /// The solver body of a contact's side: a rigid body's own slot, or the circle solver's body's
    /// place in the compact list after the rigid ones (added on first use).
    int solverBodyOf(BodySide side);
    /// held_ from the step's pivots and joints, once the contacts have given the circles their solver
    /// bodies (rigid_softness.cpp).
    void markHeld(const StepContext& ctx);
    /// Whether contact c (its solver bodies set) is a stacking one: RigidContact::stacking.
    bool stacking(const RigidContact& c) const;
    /// Copies the listed circle-solver bodies' velocities, displacements and spins into their solver
    /// bodies (before a sweep over the contacts), and their velocities and spins back (after it), so
    /// rigid and circle contacts act on the same velocities in the same Gauss-Seidel order.
    void loadOthers();
    void storeOthers();
    void reachBySegments(const StepContext& ctx, double dt);
    /// After restitution: a body whose every contact is with something fixed keeps at most the energy
    /// it began the step with; restitution's extra velocity is scaled back to that (rigid_energy.cpp).
    void capBounceEnergy();
    /// Replaces rigid body i's step with its free flight under gravity (rigid_energy.cpp).
    void runFree(std::size_t i);
    bool resolveSweptHit(StepContext& ctx, std::size_t body, int segment, const SweptShape& shape, double t, double dt);

    WorkerPool* pool_ = nullptr; // the world's workers (StepContext::workers), or null
    int circleCount_ = 0;
    double speedLimit_ = 0.0, spinLimit_ = 0.0; // WorldDef::maxTranslation and maxRotation over the step, per second
    std::int64_t clamps_ = 0;                   // substep clamps this step, added to the stats in finish()
    int substep_ = 0;                           // the substep the next warm start begins
    double substepTime_ = 0.0;                  // h, s
    // The step's solver bodies, one contiguous array the contacts index: the rigid bodies first
    // (slot i is rigid body i: pivots, joints, the sweep and the energy cap read them there), then
    // only those circles and segments that some rigid contact touches (otherBody_ says which).
    std::vector<RigidState> states_;
    std::size_t rigidCount_ = 0;
    std::vector<int> otherBody_; // per solver body past the rigid ones: its index in the circle solver's bodies
    std::vector<int> otherSlot_; // per circle-solver body: its solver body, or -1
    std::vector<Vec2> startPosition_;
    std::vector<double> startAngle_;
    std::vector<Vec2> startVelocity_; // per rigid body, for the energy it began the step with
    std::vector<double> startOmega_;
    std::vector<RigidState> beforeBounce_; // the states restitution began from
    std::vector<std::uint8_t>
        onlyFixed_; // per rigid body: every contact's other side is unmovable, all at one velocity
    std::vector<std::uint8_t> seenFrame_; // per rigid body: frame_ holds its partners' velocity
    std::vector<Vec2> frame_;             // per rigid body: the velocity of its unmovable partners
    std::vector<double> thickness_; // per rigid body: half its thinnest width (what a line must be inside it by before
                                    // its centre crosses), m
    Vec2 gravity_;
    double stepTime_ = 0.0; // dt, s
    int substeps_ = 1;
    std::vector<double> reach_; // per rigid body: speculative margin for the step
    std::vector<RoundedPolygon> shapes_;   // per rigid body: its shape at the step's start
    /// What a body's shape was made from, bit for bit: the same key, the same shape.
    struct ShapeKey {
        Vec2 position;
        double angle = 0.0;
        Vec2 halfExtents;
        BodyShape shape = BodyShape::box;
        bool made = false; // a new slot's key matches no body
        bool operator==(const ShapeKey& o) const {
            return made && o.made && same(position.x, o.position.x) && same(position.y, o.position.y) &&
                   same(angle, o.angle) && same(halfExtents.x, o.halfExtents.x) &&
                   same(halfExtents.y, o.halfExtents.y) && shape == o.shape;
        }
        static bool same(double x, double y) {
            return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y);
        }
    };
    std::vector<ShapeKey> shapeKeys_;      // per rigid body: what shapes_ holds was made from
    std::vector<int> movers_;              // the rigid bodies the substeps move (prepare), in slot order
    std::vector<std::uint8_t> fast_;       // per rigid body: moved further than its half thickness (sweep)
    std::vector<std::int8_t> struckPoint_; // per contact: its point that struck, or none (recordImpacts)
    std::vector<Box> boxes_;               // per rigid body: the box it may reach this step
    std::vector<Box> circleBoxes_;    // per circle: the box it may reach this step
    std::vector<double> circleReach_; // per circle: its speculative margin for the step
    std::vector<RoundedPolygon> segmentShapes_; // per segment: its shape this step
    std::vector<double> segmentReach_;          // per segment: how far it moves this step, m
    std::vector<Box> segmentBoxes_;             // per segment: the box it may reach this step
    RigidPairFinder pairFinder_;
    std::vector<RigidPair> pairs_;
    std::vector<Manifold> manifolds_; // per pair of pairs_: its manifold (none when neither side moves)
    std::vector<RigidContact> made_;  // per pair of pairs_ with a manifold: its contact, made by the narrowphase
    std::vector<RigidContact> madeBySegment_; // the contacts with segments, in list order
    // The step's contacts in list order, from findContacts until bind() puts them in colour order:
    // each one's slot in made_ (or -1 - its slot in madeBySegment_), and its sides' solver bodies.
    std::vector<int> listed_;
    std::vector<RigidContactEnds> listedEnds_;
    std::vector<std::uint8_t> held_; // per solver body: a pivot or joint holds it (markHeld)
    const RigidContact& listedContact(std::size_t k) const {
        const int source = listed_[k];
        return source >= 0 ? made_[static_cast<std::size_t>(source)]
                           : madeBySegment_[static_cast<std::size_t>(-1 - source)];
    }
    std::vector<SolverBody> others_; // stand-ins while the contacts are built
    std::vector<double> zeros_;
    std::vector<RigidContact> contacts_; // in colour order from bind() on (RigidColours)
    RigidColours colours_;
    RigidBlocks blocks_; // the contacts as the substeps read them, packed at bind(), unpacked before restitution
    std::vector<int> reached_;
    std::vector<std::uint8_t> stalledMotors_;
    RigidContactCache cache_; // the last step's impulses, to warm start the points found again
    std::vector<PivotConstraint> pivots_;
    JointStage joints_;
    std::vector<std::int64_t> connected_; // pairs of bodies a joint ties (they do not collide)
    RigidSolverView view_;
    RigidContactSoftness contactSoftness_;
    Softness pivotSoftness_;
};

} // namespace rube
