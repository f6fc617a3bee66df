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
// holds kShotMark, the scene's own circles hold 0.
constexpr std::uint64_t kShotMark = std::uint64_t{1} << 63;

} // namespace

LevelRun::LevelRun(const SceneDesc& scene, const std::vector<Placement>& placements)
    : scene_(scene), world_(buildWorld(scene)) {
    // buildWorld adds the scene's ropes first and in file order, so rope i is in slot i now.
    for (std::size_t i = 0; i < scene.ropes.size(); ++i) ropes_.push_back(world_.ropeId(static_cast<int>(i)));
    for (const ItemDesc& item : scene.level.items) addItem(item);
    for (const Placement& p : placements) addItem(placedItem(p));
}

void LevelRun::addItem(const ItemDesc& item) {
    ItemState state;
    state.aim = item.angle;
    const ItemBodies bodies = itemBodies(item);
    for (CircleDef c : bodies.circles) {
        c.userValue = items_.size() + 1;
        const CircleId circle = world_.addCircle(c);
        if (state.circle.isNull()) state.circle = circle;
    }
    for (const SegmentDef& s : bodies.segments) world_.addSegment(s);
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
}

int LevelRun::find(std::string_view name) const {
    for (std::size_t i = 0; i < items_.size(); ++i)
        if (!name.empty() && items_[i].name == name) return static_cast<int>(i);
    return -1;
}

int LevelRun::itemOf(CircleId circle) const {
    const std::uint64_t value = world_.userValue(circle);
    return value == 0 || value == kShotMark ? -1 : static_cast<int>(value - 1);
}

bool LevelRun::isProjectile(CircleId circle) const { return world_.userValue(circle) == kShotMark; }

Vec2 LevelRun::itemPosition(int item) const {
    const ItemState& state = states_[static_cast<std::size_t>(item)];
    if (!state.circle.isNull()) return world_.circle(state.circle).position;
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
    def.userValue = kShotMark;
    world_.addCircle(def);
    state.fired = true;
    events_.push_back({EventKind::shot, frame(), world_.time(), item.name, item.position, 0});
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

void LevelRun::step() {
    const double dt = world_.def().timeStep;
    for (std::size_t i = 0; i < items_.size(); ++i) items_[i].kind->beforeStep(*this, static_cast<int>(i));
    world_.step();
    // The items struck, in the order of the impacts, gathered first: a hit may remove a body (a bomb
    // going off), which renumbers the world's slots and its list of impacts.
    std::vector<std::pair<int, Vec2>> struckItems;
    for (const Impact& impact : world_.lastImpacts()) {
        // What was struck: the other circle (whoever struck it: a ball, or a box or domino, whose impact
        // has circle -1 and body set), or the circle a body struck (a ball's impact on a body).
        int struck = -1;
        if (impact.otherKind == Other::circle) struck = impact.other;
        else if (impact.otherKind == Other::body && impact.circle >= 0) struck = impact.circle;
        if (struck < 0) continue;
        if (const int item = itemOf(world_.circleId(struck)); item >= 0)
            struckItems.emplace_back(item, impact.pointOfImpact);
    }
    for (const auto& [item, point] : struckItems) items_[static_cast<std::size_t>(item)].kind->hit(*this, item, point);
    for (std::size_t i = 0; i < items_.size(); ++i) {
        items_[i].kind->afterStep(*this, static_cast<int>(i));
        if (states_[i].timedShot && world_.time() >= *states_[i].timedShot - 0.5 * dt) {
            states_[i].timedShot.reset();
            fire(static_cast<int>(i));
        }
    }
    checkGoal();
}

bool LevelRun::ballRestsIn(const ItemDesc& bucket) const {
    for (const Circle& c : world_.circles()) {
        if (c.motion != Motion::dynamic || c.velocity.length() > kRestSpeed) continue;
        if (bucket.kind->holds(bucket, c.position)) return true;
    }
    return false;
}

bool LevelRun::timeUp() const {
    const auto& goal = scene_.level.goal;
    return goal && !goalFrame_ && goal->timeLimit && pastTimeLimit(*goal->timeLimit);
}

void LevelRun::checkGoal() {
    const auto& goal = scene_.level.goal;
    if (!goal || goalFrame_) return;
    if (goal->timeLimit && pastTimeLimit(*goal->timeLimit)) return;
    bool reached = false;
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
        bucketRestSteps_ = bucket >= 0 && ballRestsIn(items_[static_cast<std::size_t>(bucket)]) ? bucketRestSteps_ + 1
                                                                                                : 0;
        reached = static_cast<double>(bucketRestSteps_) * world_.def().timeStep >= kRestSeconds;
        break;
    }
    }
    if (!reached) return;
    goalFrame_ = frame();
    events_.push_back({EventKind::goal, frame(), world_.time(), goal->item, {}, 0});
}

} // namespace rube::game
