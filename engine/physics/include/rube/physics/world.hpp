#pragma once
/// World: the bodies, the time-step method that advances them, and what happened in each step.

#include "rube/physics/body.hpp"
#include "rube/physics/fields.hpp"
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
    discrete,  ///< fixed step, move everything, push overlaps apart (lecture 5, first method): tunnels when speed x dt > 2r
    turnBased, ///< bodies move one by one until their first impact (lecture 3): order matters
    exact,     ///< earliest time of impact over all pairs, resolved one at a time (lecture 3's ideal method)
    solver,    ///< substepped sequential-impulse contact solver, for piles and resting contact
    automatic, ///< "auto": the cheapest that holds, step by step and island by island: exact where bodies are few and impacts sparse and nothing needs friction or turning, else the solver
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

/// Everything that sets up a world; a caller changes only what it needs.
struct WorldDef {
    Vec2 gravity{0.0, -9.81};   ///< m/s^2, the same for every dynamic body
    double timeStep = 1.0 / 60; ///< seconds per step
    Method method = Method::exact;
    Aabb bounds;                ///< leaving it is reported as an escape
    int maxEventsPerStep = 4096; ///< impacts one step may resolve before it gives up (counted as a cap hit)
    double restingSpeed = 0.0;  ///< approach speeds below this are resting contact; 0 picks 2 |g| dt + 1 mm/s
    int substeps = 8;           ///< solver only: substeps per step
    AirDrag airDrag;            ///< drag of still air on every dynamic circle; none by default
    /// solver and auto: circles that, with everything they touch, stay under `sleepSpeed` (m/s, and
    /// their surfaces' spin) for `timeToSleep` seconds rest until something reaches them; 0 never.
    /// Worlds with ropes or rigid bodies keep every circle awake.
    double sleepSpeed = 0.01;
    double timeToSleep = 0.5;   ///< seconds, see sleepSpeed
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

/// One resolved impact: for debugging overlays, game triggers and the trace.
struct Impact {
    int circle = -1;            ///< the dynamic circle
    Other otherKind = Other::circle;
    int other = -1;             ///< index of the circle or segment it hit
    double time = 0.0;          ///< world time of the impact, seconds
    Vec2 pointOfImpact;         ///< where the surfaces touch
    Vec2 normal;                ///< unit collision normal, pointing from the other body to the circle
    double approachSpeed = 0.0; ///< normal speed of approach before the resolve, m/s
    int body = -1;              ///< the block, for a block's impact (circle is then -1; normal points towards the block)
};

/// Counters over the world's life, for the summary and the bench.
struct StepStats {
    std::int64_t steps = 0;
    std::int64_t impacts = 0;        ///< impacts resolved
    std::int64_t restingContacts = 0; ///< impacts treated as resting contact (approach below restingSpeed)
    std::int64_t capsHit = 0;        ///< steps that hit maxEventsPerStep
    std::int64_t escapes = 0;        ///< circles and rigid bodies that left the bounds (each counted once)
    int maxEventsInStep = 0;
    std::int64_t autoSolverSteps = 0; ///< auto: the steps it gave to the solver, for some or all bodies (the rest went to exact)
    std::int64_t exactBodySteps = 0;  ///< auto: dynamic bodies (circles and rigid bodies) moved by exact, summed over steps
    std::int64_t solverBodySteps = 0; ///< auto: dynamic bodies moved by the solver (asleep ones too), summed over steps
    bool nonFinite = false;          ///< a NaN or infinity appeared in a body's state (circles and rigid bodies)
    std::int64_t speedClamps = 0;    ///< solver and auto: speeds cut to WorldDef::maxTranslation or maxRotation (one per body and step)
    std::int64_t isolatedBodies = 0; ///< bodies frozen because their state went non-finite (see World::step)
    Other firstIsolatedKind = Other::circle; ///< the first isolated body: a circle or a rigid body (Other::body)
    int firstIsolated = -1;          ///< its index among the world's circles or bodies, -1 when none was isolated
};

class StepMethod;
struct RopeStart;
struct FiniteSnapshot;

/// A physics world. Not copyable (it owns its method); movable.
class World {
public:
    explicit World(const WorldDef& def = WorldDef{});
    ~World();
    World(World&&) noexcept;
    World& operator=(World&&) noexcept;

    /// Adds a circle and returns its index.
    int addCircle(const CircleDef& def);
    /// Adds a segment and returns its index.
    int addSegment(const SegmentDef& def);
    /// Adds a rigid body (box or capsule) and returns its index.
    int addBody(const RigidBodyDef& def);
    /// Pins a rigid body to the world at a point, free to turn about it, and returns the pivot's index;
    /// throws std::invalid_argument for a body index out of range.
    int addPivot(const PivotDef& def);
    /// Adds a scripted path for kinematic bodies and returns its index.
    int addPath(KinematicPath path);
    /// Adds a rope between existing circles (or a circle and a fixed anchor) and returns its index;
    /// throws std::invalid_argument for a circle index out of range or a length that is not positive.
    int addRope(const RopeDef& def);
    /// Cuts rope `index`: from the next step on it no longer acts (cutting it again does nothing).
    void cutRope(int index);

    /// The world's winds, magnets and thrusters: add to them, or switch them, between steps.
    Fields& fields() { return fields_; }
    const Fields& fields() const { return fields_; }

    /// Advances the world by one time step with its method. Under solver and auto, speeds past
    /// WorldDef::maxTranslation and maxRotation are clamped first (StepStats::speedClamps); a body whose
    /// state is or becomes non-finite is frozen at its last finite pose with infinite mass, so it cannot
    /// corrupt the others, and reported (StepStats::isolatedBodies, nonFinite). Throws std::logic_error when the world has
    /// rigid bodies that turn (not fixed-rotation boxes), capsules or pivots, and its method is one
    /// that does not model them (discrete, turn-based, exact): only solver and auto do.
    void step();
    /// Switches the time-step method (for running any scene under every method).
    void setMethod(Method method);

    const WorldDef& def() const { return def_; }
    double time() const { return time_; }
    const StepStats& stats() const { return stats_; }
    /// The impacts resolved during the last step, in the order they were resolved.
    std::span<const Impact> lastImpacts() const { return impacts_; }

    std::span<Circle> circles() { return circles_; }
    std::span<const Circle> circles() const { return circles_; }
    std::span<Segment> segments() { return segments_; }
    std::span<const Segment> segments() const { return segments_; }
    std::span<RigidBody> bodies() { return bodies_; }
    std::span<const RigidBody> bodies() const { return bodies_; }
    std::span<const KinematicPath> paths() const { return paths_; }
    std::span<const Rope> ropes() const { return ropes_; }
    std::span<const Pivot> pivots() const { return pivots_; }

private:
    void moveKinematicBodies();
    void checkState();

    WorldDef def_;
    std::vector<Circle> circles_;
    std::vector<Segment> segments_;
    std::vector<RigidBody> bodies_;
    std::vector<KinematicPath> paths_;
    std::vector<Rope> ropes_;
    std::vector<Pivot> pivots_;
    std::vector<RopeStart> ropeStarts_; ///< per rope, refilled before each step that has ropes
    Fields fields_;
    std::vector<Impact> impacts_;
    std::vector<std::uint8_t> escaped_;
    std::vector<std::uint8_t> escapedBodies_; ///< per rigid body, as escaped_ per circle
    std::unique_ptr<StepMethod> method_;
    std::unique_ptr<FiniteSnapshot> finite_; ///< each body's last finite pose, for isolating one that goes non-finite
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

/// A 64-bit FNV-1a hash of every body's position and velocity bits: equal hashes mean
/// bit-identical states (the determinism check, as Box2D's determinism test does).
std::uint64_t stateHash(const World& world);

} // namespace rube
