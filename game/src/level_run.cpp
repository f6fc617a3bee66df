// LevelRun: the game's rules on top of the physics. The physics reports impacts; this decides
// what they mean (a target hit, a switch pressed, a bomb touched) and acts on it between steps.
#include "level_run.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace rube::game {

namespace {

// A ball counts as at rest in a bucket below this speed ...
constexpr double kRestSpeed = 0.3; // m/s
// ... held for this long, so a ball bouncing through the bucket's middle does not count.
constexpr double kRestSeconds = 0.5;
// A path's velocity is its offset's change over this step, s (paths are straight between keys).
constexpr double kPathProbe = 1e-3;

// What a World circle is to the game, kept in its user value: item i's circle holds i + 1, a shot
// from cannon c holds kShotMark + c, the scene's [[circle]] i holds kSceneMark + i.
constexpr std::uint64_t kShotMark = std::uint64_t{1} << 63;
constexpr std::uint64_t kSceneMark = std::uint64_t{1} << 62;
constexpr std::uint64_t kMarks = kShotMark | kSceneMark;

// The rim of the wheel joint `id` turns (its end b): a circle's radius, a body's larger half extent, m.
double rimRadius(const World& world, JointId id) {
    const JointEnd& wheel = world.joint(id).def.b;
    if (!wheel.circle.isNull()) return world.circle(wheel.circle).radius;
    if (!wheel.body.isNull())
        return std::max(world.body(wheel.body).halfExtents.x, world.body(wheel.body).halfExtents.y);
    return 1.0;
}

} // namespace

std::int64_t levelSteps(const SceneDesc& level) {
    if (level.level.goal && level.level.goal->timeLimit)
        return static_cast<std::int64_t>(std::ceil(*level.level.goal->timeLimit / level.world.timeStep - 1e-9));
    return level.defaultSteps();
}

LevelRun::LevelRun(const SceneDesc& scene, const std::vector<Placement>& placements)
    : scene_(scene), world_(buildWorld(scene)) {
    // buildWorld adds the scene's ropes first and in file order, so rope i is in slot i now.
    for (std::size_t i = 0; i < scene.ropes.size(); ++i) ropes_.push_back(world_.ropeId(static_cast<int>(i)));
    // ... and its circles first, in file order: circle i is the scene's [[circle]] i.
    for (std::size_t i = 0; i < scene.circles.size(); ++i)
        world_.setUserValue(world_.circleId(static_cast<int>(i)), kSceneMark + i);
    for (const ItemDesc& item : scene.level.items) addItem(item);
    for (const Placement& p : placements) addItem(placedItem(p));
    addItemJoints();
}

void LevelRun::addItemJoints() {
    // A named item's end: its first rigid body, else its first circle (checked by the kind's
    // checkReferences when the level was read; an item without either is the world).
    const auto endOf = [&](const ItemHandles& own, const ItemJointEnd& end) -> JointEnd {
        switch (end.to) {
        case ItemJointEnd::To::world: return {};
        case ItemJointEnd::To::circle: return {own.circles.at(static_cast<std::size_t>(end.index)), {}};
        case ItemJointEnd::To::body: return {{}, own.bodies.at(static_cast<std::size_t>(end.index))};
        case ItemJointEnd::To::item: {
            const int other = find(end.item);
            if (other < 0) return {};
            const ItemState& state = states_[static_cast<std::size_t>(other)];
            if (!state.body.isNull()) return {{}, state.body};
            return {state.circle, {}};
        }
        }
        return {};
    };
    // Gears couple joints, which may be another item's: every item's own joints first, then gears.
    for (const bool gears : {false, true}) {
        for (std::size_t i = 0; i < pendingJoints_.size(); ++i) {
            const ItemHandles& own = pendingJoints_[i];
            ItemState& state = states_[i];
            if (!gears) state.joints.assign(own.joints.size(), JointId{});
            for (std::size_t j = 0; j < own.joints.size(); ++j) {
                const ItemJoint& joint = own.joints[j];
                if ((joint.def.kind == JointKind::gear) != gears) continue;
                JointDef def = joint.def;
                if (gears) {
                    const auto jointOf = [&](int index, const std::string& item) -> JointId {
                        if (index >= 0) return state.joints.at(static_cast<std::size_t>(index));
                        const int other = find(item);
                        const auto& joints = states_[static_cast<std::size_t>(std::max(other, 0))].joints;
                        return other < 0 || joints.empty() ? JointId{} : joints.front();
                    };
                    def.jointA = jointOf(joint.gearA, joint.gearItemA);
                    def.jointB = jointOf(joint.gearB, joint.gearItemB);
                    if (def.jointA.isNull() || def.jointB.isNull()) continue;
                    if (joint.ratio != ItemJoint::Ratio::given) {
                        const double rims = rimRadius(world_, def.jointB) / rimRadius(world_, def.jointA);
                        def.ratio = joint.ratio == ItemJoint::Ratio::belt ? -rims : rims;
                    }
                } else {
                    def.a = endOf(own, joint.a);
                    def.b = endOf(own, joint.b);
                }
                state.joints[j] = world_.addJoint(def);
            }
        }
    }
    pendingJoints_.clear();
}

void LevelRun::addItem(const ItemDesc& item) {
    ItemState state;
    state.aim = item.angle;
    const ItemBodies bodies = itemBodies(item);
    ItemHandles handles;
    for (CircleDef c : bodies.circles) {
        c.userValue = items_.size() + 1;
        const CircleId circle = world_.addCircle(c);
        if (state.circle.isNull()) state.circle = circle;
        handles.circles.push_back(circle);
    }
    for (const SegmentDef& s : bodies.segments) state.segments.push_back(world_.addSegment(s));
    for (RigidBodyDef b : bodies.rigidBodies) {
        b.userValue = items_.size() + 1;
        handles.bodies.push_back(world_.addBody(b));
        if (state.body.isNull()) state.body = handles.bodies.back();
    }
    handles.joints = bodies.joints;
    Fields& fields = world_.fields();
    if (bodies.magnet) {
        state.field = static_cast<int>(fields.magnets.size());
        fields.magnets.push_back(*bodies.magnet);
    }
    if (bodies.wind) {
        state.field = static_cast<int>(fields.winds.size());
        fields.winds.push_back(*bodies.wind);
    }
    if (bodies.thruster) {
        state.field = static_cast<int>(fields.thrusters.size());
        fields.thrusters.push_back(*bodies.thruster);
        fields.thrusters.back().circle = state.circle;
    }
    items_.push_back(item);
    states_.push_back(state);
    pendingJoints_.push_back(std::move(handles));
}

int LevelRun::find(std::string_view name) const {
    for (std::size_t i = 0; i < items_.size(); ++i)
        if (!name.empty() && items_[i].name == name) return static_cast<int>(i);
    return -1;
}

int LevelRun::itemOf(CircleId circle) const {
    const std::uint64_t value = world_.userValue(circle);
    return value == 0 || (value & kMarks) != 0 ? -1 : static_cast<int>(value - 1);
}

bool LevelRun::isProjectile(CircleId circle) const { return (world_.userValue(circle) & kShotMark) != 0; }

std::string LevelRun::nameOf(CircleId circle) const {
    const std::uint64_t value = world_.userValue(circle);
    if (value & kShotMark) return items_[static_cast<std::size_t>(value - kShotMark)].name;
    if (value & kSceneMark) return scene_.circleNames[static_cast<std::size_t>(value - kSceneMark)];
    if (const int item = itemOf(circle); item >= 0) return items_[static_cast<std::size_t>(item)].name;
    return "";
}

Vec2 LevelRun::itemPosition(int item) const {
    const ItemState& state = states_[static_cast<std::size_t>(item)];
    if (!state.circle.isNull()) return world_.circle(state.circle).position;
    if (!state.body.isNull()) return world_.body(state.body).position;
    return items_[static_cast<std::size_t>(item)].position;
}

Vec2 LevelRun::itemVelocity(int item) const {
    const ItemDesc& desc = items_[static_cast<std::size_t>(item)];
    if (const int index = desc.kind->path(desc); index >= 0) {
        const KinematicPath& path = world_.paths()[static_cast<std::size_t>(index)];
        return (path.offsetAt(world_.time() + kPathProbe) - path.offsetAt(world_.time())) / kPathProbe;
    }
    const ItemState& state = states_[static_cast<std::size_t>(item)];
    if (!state.circle.isNull()) return world_.circle(state.circle).velocity;
    if (!state.body.isNull()) return world_.body(state.body).velocity;
    return {};
}

Vec2 LevelRun::launchVelocity(int cannon) const {
    const ItemDesc& item = items_[static_cast<std::size_t>(cannon)];
    return aimInDirection(states_[static_cast<std::size_t>(cannon)].aim, item.kind->muzzleSpeed(item)).velocity;
}

void LevelRun::aim(int cannon, double angle) { states_[static_cast<std::size_t>(cannon)].aim = angle; }

std::string LevelRun::aimAtPoint(int cannon, Vec2 point, bool highArc) {
    const ItemDesc& item = items_[static_cast<std::size_t>(cannon)];
    const GravityShot shot = aimGravityShot(item.position, point, item.kind->muzzleSpeed(item), world_.def().gravity);
    if (!shot.reachable())
        return "cannon '" + item.name + "' cannot reach " + formatPair(point.x, point.y) + ": " + shot.reason;
    // At exactly the minimum speed there is one arc, reported as the low one.
    const Arc& arc = highArc && shot.highArc ? *shot.highArc : *shot.lowArc;
    aim(cannon, arc.shot.angle);
    return "";
}

std::string LevelRun::aimAtItem(int cannon, int target, bool highArc) {
    const Vec2 velocity = itemVelocity(target);
    if (velocity == Vec2{}) return aimAtPoint(cannon, itemPosition(target), highArc);
    const ItemDesc& item = items_[static_cast<std::size_t>(cannon)];
    const double speed = item.kind->muzzleSpeed(item);
    const auto intercept = leadMovingTarget(item.position, itemPosition(target), velocity, speed, world_.def().gravity);
    if (!intercept)
        return "cannon '" + item.name + "' cannot catch '" + items_[static_cast<std::size_t>(target)].name +
               "' at speed " + formatNumber(speed) + " m/s";
    aim(cannon, intercept->shot.angle);
    return "";
}

void LevelRun::fire(int cannon) {
    ItemState& state = states_[static_cast<std::size_t>(cannon)];
    const ItemDesc& item = items_[static_cast<std::size_t>(cannon)];
    CircleDef def = *item.kind->shot(item);
    def.velocity = launchVelocity(cannon);
    def.userValue = kShotMark + static_cast<std::uint64_t>(cannon);
    world_.addCircle(def);
    state.fired = true;
    events_.push_back({EventKind::shot, steps(), world_.time(), item.name, item.position, 0, ""});
}

std::string LevelRun::fireWhen(int cannon, int target) {
    const ItemDesc& item = items_[static_cast<std::size_t>(cannon)];
    ItemState& state = states_[static_cast<std::size_t>(cannon)];
    const ShotTiming timing = timeFixedAngleShot(item.position, Vec2::fromAngle(state.aim),
                                                 item.kind->muzzleSpeed(item), itemPosition(target),
                                                 itemVelocity(target), world_.def().gravity);
    if (!timing.possible)
        return "cannon '" + item.name + "' cannot time a shot at '" + items_[static_cast<std::size_t>(target)].name +
               "' at its aim: " + timing.reason;
    // Shots leave between steps, so the wait is rounded to the nearest step: off by at most dt / 2.
    if (timing.delay < 0.5 * world_.def().timeStep) fire(cannon);
    else state.timedShot = world_.time() + timing.delay;
    return "";
}

void LevelRun::detonate(int bomb) { toggle(bomb); }

void LevelRun::toggle(int item) { items_[static_cast<std::size_t>(item)].kind->trigger(*this, item); }

void LevelRun::cutRope(std::string_view name) {
    if (const int rope = scene_.findRope(name); rope >= 0) world_.cutRope(ropes_[static_cast<std::size_t>(rope)]);
}

int LevelRun::itemOfBody(int slot) const {
    if (slot < 0 || static_cast<std::size_t>(slot) >= world_.bodies().size()) return -1;
    // An item's bodies hold its index + 1 (addItem); the scene's own boxes and capsules hold 0.
    const std::uint64_t value = world_.userValue(world_.bodyId(slot));
    return value > 0 && (value & kMarks) == 0 && value <= items_.size() ? static_cast<int>(value - 1) : -1;
}

std::string LevelRun::bodyName(int slot) const {
    if (const int item = itemOfBody(slot); item >= 0) return items_[static_cast<std::size_t>(item)].name;
    // The scene's boxes and capsules are the World's first bodies, in file order.
    return slot >= 0 && static_cast<std::size_t>(slot) < scene_.bodyNames.size()
               ? scene_.bodyNames[static_cast<std::size_t>(slot)]
               : std::string();
}

void LevelRun::step() {
    const double dt = world_.def().timeStep;
    for (std::size_t i = 0; i < items_.size(); ++i) items_[i].kind->beforeStep(*this, static_cast<int>(i));
    world_.step();
    // The items struck, in the order of the impacts, gathered first: a hit may remove a body (a bomb
    // going off), which renumbers the world's slots and its list of impacts.
    struct Struck {
        int item;
        Vec2 point;
        std::string by;
    };
    std::vector<Struck> struckItems;
    for (const Impact& impact : world_.lastImpacts()) {
        // A ball striking an item's rigid body (a flipper's bat) touches that item as well.
        if (impact.otherKind == Other::body && impact.circle >= 0)
            if (const int item = itemOfBody(impact.other); item >= 0)
                struckItems.push_back({item, impact.pointOfImpact, nameOf(world_.circleId(impact.circle))});
        // What was struck: the other circle (whoever struck it: a ball, or a box or domino, whose impact
        // has circle -1 and body set), or the circle a body struck (a ball's impact on a body).
        int struck = -1;
        std::string by;
        if (impact.otherKind == Other::circle) {
            struck = impact.other;
            if (impact.circle >= 0) by = nameOf(world_.circleId(impact.circle));
            else by = bodyName(impact.body);
        } else if (impact.otherKind == Other::body && impact.circle >= 0) {
            struck = impact.circle;
            by = bodyName(impact.other);
        }
        if (struck < 0) continue;
        if (const int item = itemOf(world_.circleId(struck)); item >= 0)
            struckItems.push_back({item, impact.pointOfImpact, std::move(by)});
    }
    for (const Struck& s : struckItems)
        items_[static_cast<std::size_t>(s.item)].kind->hit(*this, s.item, s.point, s.by);
    for (std::size_t i = 0; i < items_.size(); ++i) {
        items_[i].kind->afterStep(*this, static_cast<int>(i));
        if (states_[i].timedShot && world_.time() >= *states_[i].timedShot - 0.5 * dt) {
            states_[i].timedShot.reset();
            fire(static_cast<int>(i));
        }
    }
    checkGoal();
}

CircleId LevelRun::ballRestingIn(const ItemDesc& bucket) const {
    const auto circles = world_.circles();
    for (std::size_t i = 0; i < circles.size(); ++i) {
        const Circle& c = circles[i];
        if (c.motion != Motion::dynamic || c.velocity.length() > kRestSpeed) continue;
        if (bucket.kind->holds(bucket, c.position)) return world_.circleId(static_cast<int>(i));
    }
    return {};
}

bool LevelRun::timeUp() const {
    const auto& goal = scene_.level.goal;
    return goal && !goalStep_ && goal->timeLimit && pastTimeLimit(*goal->timeLimit);
}

void LevelRun::checkGoal() {
    const auto& goal = scene_.level.goal;
    if (!goal || goalStep_) return;
    if (goal->timeLimit && pastTimeLimit(*goal->timeLimit)) return;
    bool reached = false;
    // Where the goal happened and what did it: the hit that completed it, or the ball in the bucket.
    Vec2 where;
    std::string by;
    switch (goal->kind) {
    case GoalKind::targetHit: {
        const int target = find(goal->item);
        reached = target >= 0 && states_[static_cast<std::size_t>(target)].hit;
        break;
    }
    case GoalKind::allTargets:
        reached = true;
        for (std::size_t i = 0; i < items_.size(); ++i)
            if (items_[i].kind->plays(PartRole::goalTarget) && !states_[i].hit) reached = false;
        break;
    case GoalKind::ballInBucket: {
        const int bucket = find(goal->item);
        const CircleId ball = bucket >= 0 ? ballRestingIn(items_[static_cast<std::size_t>(bucket)]) : CircleId{};
        bucketRestSteps_ = ball.isNull() ? 0 : bucketRestSteps_ + 1;
        reached = static_cast<double>(bucketRestSteps_) * world_.def().timeStep >= kRestSeconds;
        if (reached) {
            where = world_.circle(ball).position;
            by = nameOf(ball);
        }
        break;
    }
    case GoalKind::reachArea: {
        if (!goal->item.empty()) {
            // A popped balloon or a spent bomb has no body left to arrive.
            const int item = find(goal->item);
            const ItemState& state = states_[static_cast<std::size_t>(item)];
            const Vec2 at = itemPosition(item);
            reached = (!state.circle.isNull() || !state.body.isNull()) && goal->area.contains(at);
            if (reached) {
                where = at;
                by = goal->item;
            }
            break;
        }
        // Any ball: the first dynamic circle, in the World's order, whose centre is in the area.
        const auto circles = world_.circles();
        for (std::size_t i = 0; i < circles.size() && !reached; ++i) {
            const Circle& c = circles[i];
            if (c.motion != Motion::dynamic || !goal->area.contains(c.position)) continue;
            reached = true;
            where = c.position;
            by = nameOf(world_.circleId(static_cast<int>(i)));
        }
        break;
    }
    }
    if (!reached) return;
    if (goal->kind == GoalKind::targetHit || goal->kind == GoalKind::allTargets) {
        // The hit that completed it: the latest on the goal's target, or on any goal target.
        for (auto e = events_.rbegin(); e != events_.rend(); ++e) {
            if (e->kind != EventKind::hit) continue;
            const int item = find(e->item);
            const bool counts = goal->kind == GoalKind::targetHit
                                    ? e->item == goal->item
                                    : item >= 0 &&
                                          items_[static_cast<std::size_t>(item)].kind->plays(PartRole::goalTarget);
            if (!counts) continue;
            where = e->position;
            by = e->by;
            break;
        }
    }
    goalStep_ = steps();
    events_.push_back({EventKind::goal, steps(), world_.time(), goal->item, where, 0, by});
}

} // namespace rube::game
