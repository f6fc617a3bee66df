// World: owns the bodies, moves kinematic bodies along their paths, delegates the step to its method.
#include "rube/physics/world.hpp"

#include "field_pass.hpp"
#include "kinematic_pose.hpp"
#include "quiet_step.hpp"
#include "rigid_water.hpp"
#include "rope_constraint.hpp"
#include "solver_sleep.hpp"
#include "speed_limits.hpp"
#include "step_method.hpp"
#include "worker_pool.hpp"
#include "world_handles.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <iterator>
#include <stdexcept>

namespace rube {

namespace {

std::unique_ptr<StepMethod> makeMethod(Method method) {
    switch (method) {
    case Method::discrete: return makeDiscreteMethod();
    case Method::turnBased: return makeTurnBasedMethod();
    case Method::exact: return makeExactMethod();
    case Method::solver: return makeSolverMethod();
    case Method::automatic: return makeAutoMethod();
    }
    throw std::invalid_argument("unknown method");
}

constexpr std::string_view kMethodNames[] = {"discrete", "turn-based", "exact", "solver", "auto"};

} // namespace

bool movesTurningBodies(Method method) { return method == Method::solver || method == Method::automatic; }

bool anyTurning(std::span<const RigidBody> bodies, std::span<const Pivot> pivots) {
    return !pivots.empty() || std::any_of(bodies.begin(), bodies.end(), [](const RigidBody& b) { return !isBlock(b); });
}

void requireRigidBodyMethod(Method method, std::span<const RigidBody> bodies, std::span<const Pivot> pivots) {
    // Lecture 3's axis-aligned blocks (fixed-rotation boxes) are every method's; anything that turns
    // needs the solver's rotation and contact manifolds, and is refused rather than silently ignored.
    if (!movesTurningBodies(method) && anyTurning(bodies, pivots))
        throw std::logic_error(
            "method '" + std::string(methodName(method)) +
            "' cannot move rotating rigid bodies, capsules or pivots: use method 'auto' or 'solver'");
}

std::string_view methodName(Method method) { return kMethodNames[static_cast<int>(method)]; }

std::optional<Method> methodFromName(std::string_view name) {
    for (int i = 0; i < static_cast<int>(std::size(kMethodNames)); ++i)
        if (kMethodNames[i] == name) return static_cast<Method>(i);
    return std::nullopt;
}

namespace {

const WorldDef& checkWorkers(const WorldDef& def) {
    if (def.workers < 1 || def.workers > kMaxWorkers)
        throw std::invalid_argument("workers must be from 1 to " + std::to_string(kMaxWorkers) + ", got " +
                                    std::to_string(def.workers));
    return def;
}

} // namespace

World::World(const WorldDef& def)
    : def_(checkWorkers(def)), method_(makeMethod(def.method)), tables_(std::make_unique<WorldTables>()),
      finite_(std::make_unique<FiniteSnapshot>()), workers_(std::make_unique<WorkerPool>(def.workers)) {}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

CircleId World::addCircle(const CircleDef& d) {
    Circle c;
    c.position = d.position;
    c.origin = d.position;
    c.velocity = d.motion == Motion::dynamic ? d.velocity : Vec2{};
    c.radius = d.radius;
    c.inverseMass = d.motion == Motion::dynamic && d.mass > 0.0 ? 1.0 / d.mass : 0.0;
    c.material = d.material;
    c.motion = d.motion;
    c.path = d.motion == Motion::kinematic ? d.path : -1;
    c.magnetic = d.magnetic;
    if (c.motion == Motion::dynamic && c.inverseMass > 0.0 && d.inertiaFactor > 0.0 && d.radius > 0.0) {
        c.inverseInertia = c.inverseMass / (d.inertiaFactor * d.radius * d.radius); // 1 / (k m r^2)
        c.angularVelocity = d.angularVelocity;
    }
    if (c.path < 0 && c.motion == Motion::kinematic) c.motion = Motion::fixed;
    c.gravityScale = d.gravityScale;
    const int entry = tables_->circles.create(static_cast<int>(circles_.size()));
    tables_->circles.entry(entry).userValue = d.userValue;
    circles_.push_back(c);
    escaped_.push_back(0);
    return handleOf<CircleId>(tables_->circles, entry);
}

SegmentId World::addSegment(const SegmentDef& d) {
    Segment s;
    s.a = s.originA = d.a;
    s.b = s.originB = d.b;
    s.radius = d.radius;
    s.material = d.material;
    s.path = d.path;
    s.surfaceSpeed = d.surfaceSpeed;
    s.pivotAlong = d.pivotAlong;
    // A paddle starts turned as its path says at t = 0 (a translating path's first offset waits for the first step, as
    // before).
    if (d.path >= 0 && static_cast<std::size_t>(d.path) < paths_.size() &&
        paths_[static_cast<std::size_t>(d.path)].turns())
        placeTurningSegment(s, paths_[static_cast<std::size_t>(d.path)], 0.0);
    const int entry = tables_->segments.create(static_cast<int>(segments_.size()));
    segments_.push_back(s);
    return handleOf<SegmentId>(tables_->segments, entry);
}

BodyId World::addBody(const RigidBodyDef& d) {
    RigidBody b;
    b.shape = d.shape;
    b.position = d.position;
    b.angle = d.fixedRotation ? 0.0 : d.angle;
    b.halfExtents = d.halfExtents;
    b.material = d.material;
    b.motion = d.motion;
    b.fixedRotation = d.fixedRotation;
    const bool dynamic = d.motion == Motion::dynamic && d.mass > 0.0;
    b.velocity = d.motion == Motion::fixed ? Vec2{} : d.velocity;
    b.inverseMass = dynamic ? 1.0 / d.mass : 0.0;
    b.inverseInertia = dynamic && !d.fixedRotation ? 1.0 / momentOfInertia(d.shape, d.halfExtents, d.mass) : 0.0;
    b.angularVelocity = d.motion == Motion::fixed || d.fixedRotation ? 0.0 : d.angularVelocity;
    b.gravityScale = d.gravityScale;
    const int entry = tables_->bodies.create(static_cast<int>(bodies_.size()));
    tables_->bodies.entry(entry).userValue = d.userValue;
    bodies_.push_back(b);
    escapedBodies_.push_back(0);
    return handleOf<BodyId>(tables_->bodies, entry);
}

PivotId World::addPivot(const PivotDef& d) {
    if (!isValid(d.body)) throw std::invalid_argument("a pivot must pin an existing rigid body");
    const int entry = tables_->pivots.create(static_cast<int>(pivots_.size()));
    perEntry(tables_->pivotOn, entry) = 1;
    pivots_.push_back(Pivot{slot(d.body), d.body, d.localAnchor, d.worldAnchor});
    // A disabled body's pivot waits with it.
    if (!isEnabled(d.body)) syncJoints();
    return handleOf<PivotId>(tables_->pivots, entry);
}

int World::addPath(KinematicPath path) {
    paths_.push_back(std::move(path));
    return static_cast<int>(paths_.size()) - 1;
}

RopeId World::addRope(const RopeDef& d) {
    if (!isValid(d.circle) || (!d.other.isNull() && (!isValid(d.other) || d.other == d.circle)))
        throw std::invalid_argument("a rope must join an existing circle to an anchor or to another circle");
    if (!(d.length > 0.0) || !std::isfinite(d.length)) throw std::invalid_argument("a rope's length must be positive");
    const int entry = tables_->ropes.create(static_cast<int>(ropes_.size()));
    perEntry(tables_->ropeOn, entry) = 1;
    const int other = d.other.isNull() ? -1 : slot(d.other);
    ropes_.push_back(Rope{slot(d.circle), other, d.circle, d.other, d.anchor, d.length, false});
    wakeEnds(ropes_.back()); // a rope shorter than its circles are apart pulls them at once
    // A rope to a disabled circle waits with it.
    if (!isEnabled(d.circle) || (!d.other.isNull() && !isEnabled(d.other))) syncJoints();
    return handleOf<RopeId>(tables_->ropes, entry);
}

void World::setMethod(Method method) {
    def_.method = method;
    method_ = makeMethod(method);
}

// Each kinematic body moves in a straight line during a step, from its path's offset at the
// start to the offset at the end: v = (offset(t + dt) - offset(t)) / dt.
void World::moveKinematicBodies() {
    const double dt = def_.timeStep;
    for (Circle& c : circles_) {
        if (c.motion != Motion::kinematic) continue;
        const KinematicPath& p = paths_[c.path];
        c.position = c.origin + p.offsetAt(time_);
        c.velocity = (p.offsetAt(time_ + dt) - p.offsetAt(time_)) / dt;
    }
    for (Segment& s : segments_) {
        if (s.path < 0) continue;
        const KinematicPath& p = paths_[s.path];
        if (p.turns()) {
            // A paddle: set onto its path, then the pivot's chord velocity and the step's mean turn rate.
            placeTurningSegment(s, p, time_);
            s.velocity = (p.offsetAt(time_ + dt) - p.offsetAt(time_)) / dt;
            s.angularVelocity = (p.angleAt(time_ + dt) - p.angleAt(time_)) / dt;
            continue;
        }
        const Vec2 offset = p.offsetAt(time_);
        s.a = s.originA + offset;
        s.b = s.originB + offset;
        s.velocity = (p.offsetAt(time_ + dt) - offset) / dt;
    }
}

bool World::sleepsThisStep() const {
    // Sleep is the solver's (auto's solver islands too); methods that move every body anyway keep
    // every body awake. Rigid bodies, pivots, joints and ropes join the solver's islands
    // (keepsRigidSleep: the solver and auto).
    const bool rigidWorld = !bodies_.empty() || !joints_.empty() || !ropes_.empty();
    return def_.sleepSpeed > 0.0 && method_->keepsSleep() && (!rigidWorld || method_->keepsRigidSleep());
}

StepContext World::stepContext() {
    // The resting threshold must exceed the speed gravity adds in one step, or a resting ball
    // would register as a fresh impact every step.
    const double resting = def_.restingSpeed > 0.0 ? def_.restingSpeed
                                                   : 2.0 * def_.gravity.length() * def_.timeStep + 1e-3;
    StepContext context{def_, circles_, segments_, bodies_, time_, resting, impacts_, stats_, pivots_, ropes_};
    context.joints = joints_;
    context.workers = workers_.get();
    return context;
}

void World::step() {
    if (stepQuietly()) return;
    moveKinematicBodies();
    impacts_.clear();
    const double dt = def_.timeStep;
    // Model no more than a scene needs: a world without fields never enters the pass.
    if (!fields_.thrusters.empty()) resolveThrusters();
    if (def_.airDrag.active() || !fields_.empty())
        applyFields(circles_, fields_, tables_->thrusterSlots, def_.airDrag, def_.gravity, time_, dt);
    // Boxes and capsules feel the pools (rigid_water.hpp); the other fields act on circles only.
    if (!fields_.waters.empty() && !bodies_.empty()) floatRigidBodies(bodies_, fields_.waters, def_.gravity, dt);
    applyGravityScales(dt);
    if (!bodies_.empty()) requireRigidBodyMethod(def_.method, bodies_, pivots_);
    if (!joints_.empty()) requireJointMethod(def_.method, joints_, circles_, def_.gravity, !bodies_.empty());
    // Issue 27: a body made non-finite between steps (a field's kick, a caller) is frozen before it
    // can reach the others, and where the solver cannot resolve a speed it is clamped (speed_limits.cpp).
    const bool noneIsolated = stats_.isolatedBodies == 0;
    if (isolateNonFinite(circles_, bodies_, *finite_, stats_, false) && noneIsolated) nameFirstIsolated();
    if (movesTurningBodies(def_.method)) limitSpeeds(circles_, bodies_, def_, stats_);
    StepContext context = stepContext();
    context.sleep = sleepsThisStep();
    context.magnets = fields_.magnets;
    // Only the solver puts bodies to sleep, so a world that never let it pays no pass to wake them.
    if (!context.sleep && mayHaveSleepers_) wakeAll(circles_, bodies_);
    mayHaveSleepers_ = context.sleep;
    // Model no more than a scene needs: a world without ropes never enters either rope pass.
    const bool hasRopes = !ropes_.empty();
    if (hasRopes) recordRopeStarts(circles_, ropes_, ropeStarts_);
    method_->step(context, dt);
    // The rest of each thruster's impulse, after the move (see kickThrusters): exact for a constant force.
    if (!fields_.thrusters.empty())
        kickThrusters(circles_, fields_.thrusters, tables_->thrusterSlots, time_, dt, BurnShare::afterMove);
    applyGravityScales(dt);
    // The rest of linear air drag's step, likewise (see linearDragAfterMove): exact x(t) and v(t) in free flight.
    if (def_.airDrag.linear > 0.0) linearDragAfterMove(circles_, def_.airDrag, def_.gravity, dt);
    if (hasRopes) enforceRopes(circles_, ropes_, ropeStarts_, impacts_, dt);
    // Methods that do not model friction cannot change a spin; it carries the angle on (none of
    // them pays for it unless something spins).
    if (!method_->integratesRotation())
        for (Circle& c : circles_)
            if (c.angularVelocity != 0.0) c.angle += c.angularVelocity * dt;
    ++stats_.steps;
    // Integer step count times dt, not a running sum: the clock does not drift over long runs.
    time_ = static_cast<double>(stats_.steps) * dt;
    // The methods only translated turning segments: the frame between steps shows them turned.
    placeTurningSegments(segments_, paths_, time_);
    checkState();
}

// Issue 26: a world entirely asleep and still (quiet_step.hpp) is stepped without the passes below,
// which would change nothing: no kinematic body to move, no field, drag or gravity scale acts on a
// sleeper, every state is finite (nothing to isolate) and every dynamic speed is 0 (nothing to clamp),
// and the method's step moves no sleeper (restQuietly renews what it keeps). The rope pass runs only
// when some rope is not plainly within its length. Each step of a settled scene then costs one pass
// that checks it.
bool World::stepQuietly() {
    if (!sleepsThisStep() || !fields_.empty() || def_.airDrag.active()) return false;
    const double dt = def_.timeStep;
    StepContext context = stepContext();
    context.sleep = true;
    if (!method_->restsQuietly(context)) return false;
    const Stillness stillness = asleepAndStill(circles_, segments_, ropes_);
    if (stillness == Stillness::moving) return false;
    const bool ropesPull = stillness == Stillness::ropesToPull;
    impacts_.clear();
    mayHaveSleepers_ = true;
    if (ropesPull) recordRopeStarts(circles_, ropes_, ropeStarts_);
    method_->restQuietly(context);
    if (ropesPull) enforceRopes(circles_, ropes_, ropeStarts_, impacts_, dt);
    ++stats_.steps;
    ++stats_.quietSteps;
    time_ = static_cast<double>(stats_.steps) * dt;
    // No segment follows a path (asleepAndStill): none to turn.
    if (ropesPull) { // the rope pass may have put a sleeper back on its rope
        checkState();
        return true;
    }
    // What checkState does, less what cannot have changed: every state is finite as checked, and a
    // sleeper has not moved since the step that last recorded its pose and checked its bounds
    // (whatever moves one wakes it, and the records follow slots as bodies leave and enter:
    // World::remapSlots).
    if (!bodies_.empty() || finite_->circlePositions.size() != circles_.size())
        recordFinitePoses(circles_, bodies_, *finite_);
    Vec2* const recorded = finite_->circlePositions.data();
    const std::size_t circleCount = circles_.size();
    for (std::size_t i = 0; i < circleCount; ++i) {
        const Circle& c = circles_[i];
        if (c.sleep.asleep) continue;
        recorded[i] = c.position;
        if (!escaped_[i] && !def_.bounds.contains(c.position)) {
            escaped_[i] = 1;
            ++stats_.escapes;
        }
    }
    return true;
}

void World::checkState() {
    // A body the step made non-finite is frozen where it last was finite and reported (speed_limits.cpp).
    const bool noneIsolated = stats_.isolatedBodies == 0;
    if (isolateNonFinite(circles_, bodies_, *finite_, stats_, true) && noneIsolated) nameFirstIsolated();
    for (std::size_t i = 0; i < circles_.size(); ++i) {
        const Circle& c = circles_[i];
        if (!escaped_[i] && !def_.bounds.contains(c.position)) {
            escaped_[i] = 1;
            ++stats_.escapes;
        }
    }
    // Rigid bodies as circles: their centre leaving the bounds, a NaN in any part of the state.
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        const RigidBody& b = bodies_[i];
        if (!escapedBodies_[i] && !def_.bounds.contains(b.position)) {
            escapedBodies_[i] = 1;
            ++stats_.escapes;
        }
    }
}

} // namespace rube
