#pragma once
/// World: the bodies, the time-step method that advances them, and what happened in each step.

#include "rube/physics/body.hpp"
#include "rube/physics/fields.hpp"
#include "rube/physics/handles.hpp"
#include "rube/physics/joint.hpp"
#include "rube/physics/pivot.hpp"
#include "rube/physics/rigid_body.hpp"
#include "rube/physics/rope.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <optional>
#include <vector>

namespace rube {

/// The time-step methods of the course, each honest about where it fails (see README).
enum class Method : std::uint8_t {
    discrete, ///< fixed step, move everything, push overlaps apart (lecture 5, first method): tunnels when speed x dt >
              ///< 2r
    turnBased, ///< bodies move one by one until their first impact (lecture 3): order matters
    exact,     ///< earliest time of impact over all pairs, resolved one at a time (lecture 3's ideal method)
    solver,    ///< substepped sequential-impulse contact solver, for piles and resting contact
    automatic, ///< "auto": the cheapest that holds, step by step and island by island: exact where bodies are few and
               ///< impacts sparse and nothing needs friction or turning, else the solver
};

/// The method's name as scene files and the command line spell it ("turn-based", ...).
std::string_view methodName(Method);
/// The method named `name`, or nothing when no method has that name.
std::optional<Method> methodFromName(std::string_view name);

/// An axis-aligned box; bodies whose centre leaves the world's bounds count as escaped.
struct Aabb {
    Vec2 min{-1e6, -1e6};
    Vec2 max{1e6, 1e6};
    bool contains(Vec2 p) const { return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y; }
};

/// The most worker threads a world may have (WorldDef::workers).
constexpr int kMaxWorkers = 64;

/// Everything that sets up a world; a caller changes only what it needs.
struct WorldDef {
    Vec2 gravity{0.0, -9.81};   ///< m/s^2, the same for every dynamic body
    double timeStep = 1.0 / 60; ///< seconds per step
    Method method = Method::exact;
    Aabb bounds;                 ///< leaving it is reported as an escape
    int maxEventsPerStep = 4096; ///< impacts one step may resolve before it gives up (counted as a cap hit)
    double restingSpeed = 0.0;   ///< approach speeds below this are resting contact; 0 picks 2 |g| dt + 1 mm/s
    int substeps = 8;            ///< solver only: substeps per step
    /// solver (and auto's solver islands): threads that share the rigid contacts and bodies of a step,
    /// this one included; 1 starts none. Results are bit for bit the same for any count. 1 to 64
    /// (World's constructor throws std::invalid_argument otherwise).
    int workers = 1;
    AirDrag airDrag;             ///< drag of still air on every dynamic circle; none by default
    /// solver and auto: circles that, with everything they touch, stay under `sleepSpeed` (m/s, and
    /// their surfaces' spin) for `timeToSleep` seconds rest until something reaches them; 0 never.
    /// The solver puts rigid bodies (omega times their bounding radius counted too), pivots and
    /// joints in the same islands, and ropes (a rope's circles share an island; a taut rope holds
    /// its circle towards its other end); auto lets the islands it gives the solver sleep so.
    double sleepSpeed = 0.01;
    double timeToSleep = 0.5; ///< seconds, see sleepSpeed
    /// solver and auto: the most a dynamic rigid body (box, capsule; not a circle, which the solver
    /// sweeps) may move in one step, m.
    /// Faster bodies are slowed to it before the step and counted (StepStats::speedClamps): as Box2D's
    /// b2_maxTranslation (2 m a step), a bound where the solver cannot resolve the motion.
    double maxTranslation = 2.0;
    /// solver and auto: the most a turning rigid body may turn in one step, radians (Box2D v3's
    /// 0.25 pi): past it the contact manifold of the step's start no longer describes the body.
    double maxRotation = 0.25 * 3.14159265358979323846;
};

/// What kind of thing a circle (or a block) hit.
enum class Other : std::uint8_t { circle, segment, segmentCap, body };

/// One resolved impact: for debugging overlays, game triggers and the trace. Bodies are named by
/// their slots in World::circles(), segments() and bodies() during the step (World::circleId(slot)
/// and its kin give their handles, valid until the next remove, disable or enable).
struct Impact {
    int circle = -1; ///< the dynamic circle's slot
    Other otherKind = Other::circle;
    int other = -1;             ///< slot of the circle or segment it hit
    double time = 0.0;          ///< world time of the impact, seconds
    Vec2 pointOfImpact;         ///< where the surfaces touch
    Vec2 normal;                ///< unit collision normal, pointing from the other body to the circle
    double approachSpeed = 0.0; ///< normal speed of approach before the resolve, m/s
    int body = -1; ///< the block's slot, for a block's impact (circle is then -1; normal points towards the block)
};

/// Counters over the world's life, for the summary and the bench.
struct StepStats {
    std::int64_t steps = 0;
    std::int64_t impacts = 0;         ///< impacts resolved
    std::int64_t restingContacts = 0; ///< impacts treated as resting contact (approach below restingSpeed)
    std::int64_t capsHit = 0;         ///< steps that hit maxEventsPerStep
    std::int64_t escapes = 0;         ///< circles and rigid bodies that left the bounds (each counted once)
    int maxEventsInStep = 0;
    std::int64_t autoSolverSteps =
        0; ///< auto: the steps it gave to the solver, for some or all bodies (the rest went to exact)
    std::int64_t exactBodySteps =
        0; ///< auto: dynamic bodies (circles and rigid bodies) moved by exact, summed over steps
    std::int64_t solverBodySteps = 0; ///< auto: dynamic bodies moved by the solver (asleep ones too), summed over steps
    bool nonFinite = false;           ///< a NaN or infinity appeared in a body's state (circles and rigid bodies)
    std::int64_t speedClamps =
        0; ///< solver and auto: speeds cut to WorldDef::maxTranslation or maxRotation (one per body and step)
    std::int64_t isolatedBodies = 0;         ///< bodies frozen because their state went non-finite (see World::step)
    Other firstIsolatedKind = Other::circle; ///< the first isolated body: a circle or a rigid body (Other::body)
    CircleId firstIsolatedCircle;            ///< the first isolated body when it is a circle, else null
    BodyId firstIsolatedBody;                ///< the first isolated body when it is a rigid body, else null
    int firstIsolatedSlot = -1; ///< its slot among the world's circles or bodies when isolated, -1 when none was
    /// solver: steps of a world entirely asleep and still, which visited no body but to check that
    /// (no ropes, fields, rigid bodies or joints need the full step; see World::step)
    std::int64_t quietSteps = 0;
};

class StepMethod;
struct StepContext;
struct RopeStart;
struct FiniteSnapshot;
struct WorldTables;
struct SlotRemap;
class WorkerPool;

/// A physics world. Not copyable (it owns its method); movable.
class World {
public:
    explicit World(const WorldDef& def = WorldDef{});
    ~World();
    World(World&&) noexcept;
    World& operator=(World&&) noexcept;

    /// Adds a circle and returns its handle.
    CircleId addCircle(const CircleDef& def);
    /// Adds a segment and returns its handle.
    SegmentId addSegment(const SegmentDef& def);
    /// Adds a rigid body (box or capsule) and returns its handle.
    BodyId addBody(const RigidBodyDef& def);
    /// Pins a rigid body to the world at a point, free to turn about it, and returns the pivot's handle;
    /// throws std::invalid_argument for a body handle that is not valid.
    PivotId addPivot(const PivotDef& def);
    /// Adds a joint (joint.hpp) and returns its handle; throws std::invalid_argument for an end that is
    /// not valid, both ends the same body or both the world, a gear whose joints are not a revolute and
    /// a revolute or prismatic, or a parameter out of its range (negative stiffness, a limit's lower
    /// above its upper, a pulley's ratio or length not positive).
    JointId addJoint(const JointDef& def);
    /// Adds a scripted path for kinematic bodies and returns its index (paths are never removed).
    int addPath(KinematicPath path);
    /// Adds a rope between existing circles (or a circle and a fixed anchor) and returns its handle;
    /// throws std::invalid_argument for a circle handle that is not valid or a length that is not positive.
    RopeId addRope(const RopeDef& def);
    /// Cuts a rope: from the next step on it no longer acts (cutting it again does nothing).
    void cutRope(RopeId rope);

    /// Removes a circle, and every rope and joint attached to it. Its handle (and theirs) is stale from now on.
    void remove(CircleId circle);
    /// Removes a segment.
    void remove(SegmentId segment);
    /// Removes a rigid body, and every pivot and joint that holds it.
    void remove(BodyId body);
    /// Removes a rope.
    void remove(RopeId rope);
    /// Removes a pivot.
    void remove(PivotId pivot);
    /// Removes a joint, and every gear that couples it.
    void remove(JointId joint);
    /// Disables (false) or enables again (true) a circle: a disabled one takes no part in the step
    /// (no motion, no contacts, its ropes do not act) and keeps its state until it is enabled.
    void setEnabled(CircleId circle, bool enabled);
    /// As for circles: a disabled segment is met by nothing.
    void setEnabled(SegmentId segment, bool enabled);
    /// As for circles: a disabled rigid body neither moves nor is met, and its pivots do not act.
    void setEnabled(BodyId body, bool enabled);
    /// A disabled rope does not act (it also waits while either circle is disabled).
    void setEnabled(RopeId rope, bool enabled);
    /// A disabled pivot does not act (it also waits while its body is disabled).
    void setEnabled(PivotId pivot, bool enabled);
    /// A disabled joint does not act (it also waits while an end, or a joint a gear couples, waits).
    void setEnabled(JointId joint, bool enabled);
    /// Sets a revolute's or prismatic's motor (a switch turning a machine's motor on or off: maxForce 0
    /// is off), waking the islands of its circles; throws std::invalid_argument for a joint of another
    /// kind, and as addJoint does for a negative or non-finite force or speed.
    void setJointMotor(JointId joint, const JointMotor& motor);
    /// Sets a segment's surface speed (a conveyor a switch starts or stops: 0 is still), waking what
    /// sleeps on it, since a body resting on a belt that starts must feel it; throws
    /// std::invalid_argument for a speed that is not finite.
    void setSurfaceSpeed(SegmentId segment, double speed);
    /// True while the handle names something of this world (not removed, not null).
    bool isValid(CircleId id) const;
    bool isValid(SegmentId id) const; ///< as isValid(CircleId)
    bool isValid(BodyId id) const;    ///< as isValid(CircleId)
    bool isValid(RopeId id) const;    ///< as isValid(CircleId)
    bool isValid(PivotId id) const;   ///< as isValid(CircleId)
    bool isValid(JointId id) const;   ///< as isValid(CircleId)
    /// True unless disabled; throws std::invalid_argument for a stale handle (as every accessor below).
    bool isEnabled(CircleId id) const;
    bool isEnabled(SegmentId id) const; ///< as isEnabled(CircleId)
    bool isEnabled(BodyId id) const;    ///< as isEnabled(CircleId)
    bool isEnabled(RopeId id) const;    ///< as isEnabled(CircleId); a rope whose own switch is on
    bool isEnabled(PivotId id) const;   ///< as isEnabled(CircleId); a pivot whose own switch is on
    bool isEnabled(JointId id) const;   ///< as isEnabled(CircleId); a joint whose own switch is on

    /// The circle's state (also while disabled).
    const Circle& circle(CircleId id) const;
    const Segment& segment(SegmentId id) const; ///< the segment's state
    const RigidBody& body(BodyId id) const;     ///< the rigid body's state
    const Rope& rope(RopeId id) const;          ///< the rope (its slots are -1 while it waits)
    const Pivot& pivot(PivotId id) const;       ///< the pivot (its slot is -1 while it waits)
    const Joint& joint(JointId id) const;       ///< the joint (its slots are -1 while it waits)
    /// Its slot in circles() (and in Impact), -1 while disabled.
    int slot(CircleId id) const;
    int slot(SegmentId id) const; ///< its slot in segments(), -1 while disabled
    int slot(BodyId id) const;    ///< its slot in bodies(), -1 while disabled
    int slot(RopeId id) const;    ///< its slot in ropes(), -1 while it does not act
    int slot(PivotId id) const;   ///< its slot in pivots(), -1 while it does not act
    int slot(JointId id) const;   ///< its slot in joints(), -1 while it does not act
    /// The handle of the circle in `slot` of circles(); throws std::out_of_range past the end.
    CircleId circleId(int slot) const;
    SegmentId segmentId(int slot) const; ///< the handle of segments()[slot]
    BodyId bodyId(int slot) const;       ///< the handle of bodies()[slot]
    RopeId ropeId(int slot) const;       ///< the handle of ropes()[slot]
    PivotId pivotId(int slot) const;     ///< the handle of pivots()[slot]
    JointId jointId(int slot) const;     ///< the handle of joints()[slot]

    /// The point `worldPoint` in the frame of joint end `end` as it stands now (the world's frame
    /// for the world): what JointDef::localAnchorA and B hold.
    Vec2 localPoint(JointEnd end, Vec2 worldPoint) const;
    /// The point `localPoint` of `end`'s frame in the world now.
    Vec2 worldPoint(JointEnd end, Vec2 localPoint) const;
    /// The angle of `end` now (0 for the world), rad.
    double angleOf(JointEnd end) const;
    /// A joint's coordinate now: a revolute's and a weld's angle (b's less a's, less the reference
    /// angle), a prismatic's slide along its axis, a spring's length, a pulley's
    /// |pA - groundA| + ratio |pB - groundB|, a gear's coordA + ratio coordB.
    double jointCoordinate(JointId id) const;

    /// The caller's own value for a circle (0 until set; also CircleDef::userValue).
    std::uint64_t userValue(CircleId id) const;
    std::uint64_t userValue(BodyId id) const; ///< as for circles (RigidBodyDef::userValue)
    /// Sets the caller's value for a circle, for its own bookkeeping.
    void setUserValue(CircleId id, std::uint64_t value);
    void setUserValue(BodyId id, std::uint64_t value); ///< as for circles

    // Setters between steps. Each wakes the island of a sleeping circle it changes.
    /// Moves a circle's centre (a kinematic one's path origin moves with it).
    void setPosition(CircleId id, Vec2 position);
    void setPosition(BodyId id, Vec2 position); ///< moves a rigid body's centre of mass
    /// Sets a dynamic circle's velocity, m/s.
    void setVelocity(CircleId id, Vec2 velocity);
    void setVelocity(BodyId id, Vec2 velocity); ///< as for circles
    /// Sets a circle's spin, rad/s (only a circle with inertia turns).
    void setAngularVelocity(CircleId id, double omega);
    void setAngularVelocity(BodyId id, double omega); ///< as for circles
    /// Adds an impulse at the centre, N s: Delta v = J / m (nothing for infinite mass).
    void applyImpulse(CircleId id, Vec2 impulse);
    void applyImpulse(BodyId id, Vec2 impulse); ///< as for circles
    /// Adds an impulse at a world point: Delta v = J / m, Delta omega = (r x J) / I (lecture 3).
    void applyImpulseAt(BodyId id, Vec2 impulse, Vec2 point);
    /// Sets how much of the world's gravity acts on it: 1 all, 0 none, -1 it rises at g (a balloon).
    void setGravityScale(CircleId id, double scale);
    void setGravityScale(BodyId id, double scale); ///< as for circles
    /// Sets a circle's radius, m (a changed shape: the world finds its contacts anew).
    void setRadius(CircleId id, double radius);

    /// The world's winds, magnets and thrusters: add to them, or switch them, between steps.
    Fields& fields() { return fields_; }
    const Fields& fields() const { return fields_; }

    /// Advances the world by one time step with its method. Under solver and auto, speeds past
    /// WorldDef::maxTranslation and maxRotation are clamped first (StepStats::speedClamps); a body whose
    /// state is or becomes non-finite is frozen at its last finite pose with infinite mass, so it cannot
    /// corrupt the others, and reported (StepStats::isolatedBodies, nonFinite). Throws std::logic_error when the world
    /// has rigid bodies that turn (not fixed-rotation boxes), capsules or pivots, and its method is one that does not
    /// model them (discrete, turn-based, exact): only solver and auto do. A solver world of circles,
    /// segments and ropes that is entirely asleep and still takes the step without its per-body
    /// passes, as they would change nothing (StepStats::quietSteps).
    void step();
    /// Switches the time-step method (for running any scene under every method).
    void setMethod(Method method);

    const WorldDef& def() const { return def_; }
    double time() const { return time_; }
    const StepStats& stats() const { return stats_; }
    /// The impacts resolved during the last step, in the order they were resolved.
    std::span<const Impact> lastImpacts() const { return impacts_; }

    /// The enabled circles, packed in insertion order (a slot is a position in this span).
    std::span<const Circle> circles() const { return circles_; }
    /// The enabled segments, packed in insertion order.
    std::span<const Segment> segments() const { return segments_; }
    /// The enabled rigid bodies, packed in insertion order.
    std::span<const RigidBody> bodies() const { return bodies_; }
    /// The scripted paths, by index.
    std::span<const KinematicPath> paths() const { return paths_; }
    /// The ropes that act (enabled, both ends enabled), cut ones too, in insertion order.
    std::span<const Rope> ropes() const { return ropes_; }
    /// The pivots that act (enabled, body enabled), in insertion order.
    std::span<const Pivot> pivots() const { return pivots_; }
    /// The joints that act (enabled, ends enabled), in insertion order.
    std::span<const Joint> joints() const { return joints_; }

private:
    void moveKinematicBodies();
    bool stepQuietly();
    /// Whether this step lets islands fall asleep (StepContext::sleep).
    bool sleepsThisStep() const;
    /// What the method is handed this step, its sleep flag left false.
    StepContext stepContext();
    void checkState();
    void applyGravityScales(double dt);
    void nameFirstIsolated();
    void resolveThrusters();
    Circle& circleState(CircleId id);
    RigidBody& bodyState(BodyId id);
    void wakeCircle(const Circle& c);
    void wakeBody(const RigidBody& b);
    void wakeIsland(int island);      ///< every asleep circle and rigid body of `island` (SleepState::island)
    void wakeEnds(const JointDef& d); ///< the islands of a joint's ends (a gear's: its joints' ends)
    void wakeEnds(const Rope& rope);  ///< the islands of a rope's circles
    void wakeNear(const Segment& s);
    void remapSlots(const SlotRemap& remap);
    void leaveCircle(int entry);
    void leaveBody(int entry);
    void syncJoints();
    void syncMachineJoints();
    void removeJointsOf(JointEnd end);
    bool jointActs(const Joint& joint) const;
    double coordinate(const Joint& joint) const;

    WorldDef def_;
    std::vector<Circle> circles_;
    std::vector<Segment> segments_;
    std::vector<RigidBody> bodies_;
    std::vector<KinematicPath> paths_;
    std::vector<Rope> ropes_;
    std::vector<Pivot> pivots_;
    std::vector<Joint> joints_;
    std::vector<RopeStart> ropeStarts_; ///< per rope, refilled before each step that has ropes
    Fields fields_;
    std::vector<Impact> impacts_;
    std::vector<std::uint8_t> escaped_;
    std::vector<std::uint8_t> escapedBodies_; ///< per rigid body, as escaped_ per circle
    std::unique_ptr<StepMethod> method_;
    std::unique_ptr<WorldTables> tables_;    ///< handles, and what is disabled (world_handles.hpp)
    std::unique_ptr<FiniteSnapshot> finite_; ///< each body's last finite pose, for isolating one that goes non-finite
    std::unique_ptr<WorkerPool> workers_;    ///< WorldDef::workers' threads (worker_pool.hpp)
    StepStats stats_;
    double time_ = 0.0;
    bool mayHaveSleepers_ = false; ///< some step let islands sleep since every circle was last woken
};

/// True when `method` moves bodies that turn (rotating boxes, capsules, pivots): the solver and auto.
bool movesTurningBodies(Method method);

/// True when some body turns or is pinned: anything but lecture 3's blocks (see isBlock), or a pivot.
bool anyTurning(std::span<const RigidBody> bodies, std::span<const Pivot> pivots);

/// Throws std::logic_error unless `method` models these bodies and pivots: lecture 3's axis-aligned
/// blocks (fixed-rotation boxes) suit every method; turning bodies, capsules and pivots need solver or auto.
void requireRigidBodyMethod(Method method, std::span<const RigidBody> bodies, std::span<const Pivot> pivots);

/// Throws std::logic_error unless `method` carries `joints` as the bodies stand: solver and auto
/// carry every joint; exact only springs from a circle's centre to a fixed point, where the motion
/// has a closed form (rest length 0 and undamped, or the circle moving along the spring's line with
/// gravity along it), and not beside rigid bodies; discrete and turn-based none. The message names
/// the first joint refused and why.
void requireJointMethod(Method method, std::span<const Joint> joints, std::span<const Circle> circles, Vec2 gravity,
                        bool withBodies);

/// A 64-bit FNV-1a hash of every body's position and velocity bits: equal hashes mean
/// bit-identical states (the determinism check, as Box2D's determinism test does).
std::uint64_t stateHash(const World& world);

} // namespace rube
