// World: joints (joint.hpp): adding, removing, disabling them, their slots and their coordinates.
// A joint acts while its own switch is on, both its ends are in the world's arrays and, for a
// gear, both joints it couples act; otherwise it waits outside joints_ (as ropes and pivots do).
#include "rube/physics/world.hpp"

#include "exact_springs.hpp"
#include "world_handles.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rube {

namespace {

Vec2 rotated(double angle, Vec2 r) {
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * r.x - s * r.y, s * r.x + c * r.y};
}

bool sameEnd(const JointEnd& x, const JointEnd& y) { return x.circle == y.circle && x.body == y.body; }

bool finite(double v) { return std::isfinite(v); }

// The parameter checks of addJoint, one message each.
void checkDef(const JointDef& d) {
    const auto fail = [](const char* what) { throw std::invalid_argument(what); };
    if (d.limits.on && !(d.limits.lower <= d.limits.upper)) fail("a joint's lower limit must not exceed its upper");
    if (!(d.motor.maxForce >= 0.0) || !finite(d.motor.maxForce) || !finite(d.motor.speed))
        fail("a motor's maximum force must be finite and not negative");
    switch (d.kind) {
    case JointKind::spring:
        if (!(d.stiffness >= 0.0) || !(d.damping >= 0.0) || !(d.restLength >= 0.0) || !finite(d.stiffness) ||
            !finite(d.damping) || !finite(d.restLength))
            fail("a spring's stiffness, damping and rest length must be finite and not negative");
        break;
    case JointKind::pulley:
        if (!(d.ratio > 0.0) || !(d.length > 0.0) || !finite(d.ratio) || !finite(d.length))
            fail("a pulley's ratio and length must be positive");
        break;
    case JointKind::weld:
        if (!(d.hertz >= 0.0) || !(d.dampingRatio >= 0.0) || !finite(d.hertz) || !finite(d.dampingRatio))
            fail("a weld's hertz and damping ratio must be finite and not negative");
        break;
    case JointKind::prismatic:
        if (!(d.localAxisA.length() > 0.0) || !finite(d.localAxisA.x) || !finite(d.localAxisA.y))
            fail("a prismatic joint's axis must not be zero");
        break;
    case JointKind::gear:
        if (!(d.ratio != 0.0) || !finite(d.ratio)) fail("a gear's ratio must be finite and not zero");
        break;
    case JointKind::revolute: break;
    }
}

} // namespace

void requireJointMethod(Method method, std::span<const Joint> joints, std::span<const Circle> circles, Vec2 gravity,
                        bool withBodies) {
    if (movesTurningBodies(method)) return;
    const auto refuse = [&](const std::string& why) {
        throw std::logic_error("method '" + std::string(methodName(method)) + "' cannot move joints" + why +
                               ": use method 'auto' or 'solver'");
    };
    if (method != Method::exact) refuse("");
    // Exact follows a spring to a fixed point on its closed form, where it has one (exact_springs.hpp).
    for (std::size_t k = 0; k < joints.size(); ++k) {
        const std::string why = exactSpringRefusal(joints[k], circles, gravity, withBodies);
        if (!why.empty()) refuse(" (joint " + std::to_string(k) + ": " + why + ")");
    }
}

JointId World::addJoint(const JointDef& def) {
    checkDef(def);
    Joint made{def};
    if (def.kind == JointKind::gear) {
        if (!isValid(def.jointA) || !isValid(def.jointB) || def.jointA == def.jointB)
            throw std::invalid_argument("a gear must couple two existing joints");
        const JointKind ka = joint(def.jointA).def.kind, kb = joint(def.jointB).def.kind;
        if (ka != JointKind::revolute || (kb != JointKind::revolute && kb != JointKind::prismatic))
            throw std::invalid_argument("a gear couples a revolute with a revolute or a prismatic joint");
        made.def.a = made.def.b = JointEnd{};
        made.gearConstant = jointCoordinate(def.jointA) + def.ratio * jointCoordinate(def.jointB);
    } else {
        const auto valid = [&](const JointEnd& e) {
            if (!e.circle.isNull() && !e.body.isNull()) return false;
            return e.isWorld() || (e.circle.isNull() ? isValid(e.body) : isValid(e.circle));
        };
        if (!valid(def.a) || !valid(def.b))
            throw std::invalid_argument("a joint's ends must be existing bodies or the world");
        if (sameEnd(def.a, def.b)) throw std::invalid_argument("a joint must join two different bodies");
    }
    const int entry = tables_->joints.create(static_cast<int>(joints_.size()));
    perEntry(tables_->jointOn, entry) = 1;
    joints_.push_back(made);
    syncJoints();
    wakeEnds(made.def); // a joint added to a sleeping island acts from the next step
    return handleOf<JointId>(tables_->joints, entry);
}

void World::remove(JointId id) {
    tables_->joints.at(id.index, id.generation, "joint");
    // The gears that couple it go with it.
    for (int e = 0; e < tables_->joints.entryCount(); ++e) {
        const HandleTable::Entry& entry = tables_->joints.entry(e);
        if (!entry.live || e == id.index) continue;
        const JointDef& d = joint(JointId{e, entry.generation}).def;
        if (d.kind == JointKind::gear && (d.jointA == id || d.jointB == id)) remove(JointId{e, entry.generation});
    }
    HandleTable::Entry& entry = tables_->joints.entry(id.index);
    wakeEnds(joint(id).def); // what the joint held may fall
    if (entry.enabled) {
        const int slot = entry.slot;
        tables_->joints.leave(id.index);
        joints_.erase(joints_.begin() + slot);
    }
    tables_->joints.retire(id.index);
    syncMachineJoints();
}

void World::removeJointsOf(JointEnd end) {
    for (int e = 0; e < tables_->joints.entryCount(); ++e) {
        const HandleTable::Entry& entry = tables_->joints.entry(e);
        if (!entry.live) continue;
        const JointId id{e, entry.generation};
        const JointDef& d = joint(id).def;
        if (d.kind != JointKind::gear && (sameEnd(d.a, end) || sameEnd(d.b, end))) remove(id);
    }
}

void World::setEnabled(JointId id, bool enabled) {
    tables_->joints.at(id.index, id.generation, "joint");
    tables_->jointOn[static_cast<std::size_t>(id.index)] = enabled ? 1 : 0;
    wakeEnds(joint(id).def);
    syncJoints();
}

void World::wakeEnds(const JointDef& d) {
    for (const JointEnd& end : {d.a, d.b}) {
        if (!end.circle.isNull() && isValid(end.circle)) wakeCircle(circleState(end.circle));
        if (!end.body.isNull() && isValid(end.body)) wakeBody(bodyState(end.body));
    }
    if (d.kind != JointKind::gear) return;
    for (const JointId coupled : {d.jointA, d.jointB})
        if (isValid(coupled)) wakeEnds(joint(coupled).def);
}

void World::setJointMotor(JointId id, const JointMotor& motor) {
    const HandleTable::Entry& e = tables_->joints.at(id.index, id.generation, "joint");
    Joint& j = e.enabled ? joints_[static_cast<std::size_t>(e.slot)]
                         : tables_->parkedJoints[static_cast<std::size_t>(id.index)];
    if (j.def.kind != JointKind::revolute && j.def.kind != JointKind::prismatic)
        throw std::invalid_argument("only a revolute or prismatic joint has a motor");
    JointDef def = j.def;
    def.motor = motor;
    checkDef(def);
    j.def.motor = motor;
    // A sleeping wheel or plank would not feel its motor: its island wakes.
    wakeEnds(j.def);
}

bool World::jointActs(const Joint& j) const {
    const auto on = [&](const JointEnd& e) {
        return e.isWorld() || (e.circle.isNull() ? isEnabled(e.body) : isEnabled(e.circle));
    };
    if (j.def.kind != JointKind::gear) return on(j.def.a) && on(j.def.b);
    const auto acts = [&](JointId g) {
        const HandleTable::Entry& e = tables_->joints.at(g.index, g.generation, "joint");
        const Joint& coupled = e.enabled ? joints_[static_cast<std::size_t>(e.slot)]
                                         : tables_->parkedJoints[static_cast<std::size_t>(g.index)];
        return tables_->jointOn[static_cast<std::size_t>(g.index)] && jointActs(coupled);
    };
    return acts(j.def.jointA) && acts(j.def.jointB);
}

void World::syncMachineJoints() {
    HandleTable& table = tables_->joints;
    for (int e = 0; e < table.entryCount(); ++e) {
        HandleTable::Entry& entry = table.entry(e);
        if (!entry.live) continue;
        const Joint& j = entry.enabled ? joints_[static_cast<std::size_t>(entry.slot)]
                                       : tables_->parkedJoints[static_cast<std::size_t>(e)];
        const bool acts = tables_->jointOn[static_cast<std::size_t>(e)] && jointActs(j);
        if (entry.enabled && !acts) {
            const int slot = entry.slot;
            perEntry(tables_->parkedJoints, e) = joints_[static_cast<std::size_t>(slot)];
            table.leave(e);
            joints_.erase(joints_.begin() + slot);
        } else if (!entry.enabled && acts) {
            table.enter(e);
            joints_.insert(joints_.begin() + entry.slot, tables_->parkedJoints[static_cast<std::size_t>(e)]);
        }
    }
    const auto endSlots = [&](const JointEnd& end, int& circle, int& body) {
        circle = end.circle.isNull() ? -1 : slot(end.circle);
        body = end.body.isNull() ? -1 : slot(end.body);
    };
    for (Joint& j : joints_) {
        endSlots(j.def.a, j.circleA, j.bodyA);
        endSlots(j.def.b, j.circleB, j.bodyB);
        j.jointA = j.def.kind == JointKind::gear ? slot(j.def.jointA) : -1;
        j.jointB = j.def.kind == JointKind::gear ? slot(j.def.jointB) : -1;
    }
    // A waiting joint names no slot.
    for (int e = 0; e < table.entryCount(); ++e) {
        const HandleTable::Entry& entry = table.entry(e);
        if (!entry.live || entry.enabled) continue;
        Joint& j = tables_->parkedJoints[static_cast<std::size_t>(e)];
        j.circleA = j.bodyA = j.circleB = j.bodyB = j.jointA = j.jointB = -1;
    }
}

bool World::isValid(JointId id) const { return tables_->joints.find(id.index, id.generation) != nullptr; }

bool World::isEnabled(JointId id) const {
    tables_->joints.at(id.index, id.generation, "joint");
    return tables_->jointOn[static_cast<std::size_t>(id.index)] != 0;
}

const Joint& World::joint(JointId id) const {
    const HandleTable::Entry& e = tables_->joints.at(id.index, id.generation, "joint");
    return e.enabled ? joints_[static_cast<std::size_t>(e.slot)]
                     : tables_->parkedJoints[static_cast<std::size_t>(id.index)];
}

int World::slot(JointId id) const { return tables_->joints.at(id.index, id.generation, "joint").slot; }

JointId World::jointId(int slot) const { return idOfSlot<JointId>(tables_->joints, slot); }

// ---- frames and coordinates ----

double World::angleOf(JointEnd end) const {
    if (end.isWorld()) return 0.0;
    return end.circle.isNull() ? body(end.body).angle : circle(end.circle).angle;
}

Vec2 World::worldPoint(JointEnd end, Vec2 local) const {
    if (end.isWorld()) return local;
    const Vec2 centre = end.circle.isNull() ? body(end.body).position : circle(end.circle).position;
    return centre + rotated(angleOf(end), local);
}

Vec2 World::localPoint(JointEnd end, Vec2 world) const {
    if (end.isWorld()) return world;
    const Vec2 centre = end.circle.isNull() ? body(end.body).position : circle(end.circle).position;
    return rotated(-angleOf(end), world - centre);
}

double World::jointCoordinate(JointId id) const { return coordinate(joint(id)); }

double World::coordinate(const Joint& j) const {
    const JointDef& d = j.def;
    const Vec2 pa = worldPoint(d.a, d.localAnchorA), pb = worldPoint(d.b, d.localAnchorB);
    switch (d.kind) {
    case JointKind::revolute:
    case JointKind::weld: return angleOf(d.b) - angleOf(d.a) - d.referenceAngle;
    case JointKind::prismatic: {
        const Vec2 axis = rotated(angleOf(d.a), d.localAxisA.normalized());
        return (pb - pa).dot(axis);
    }
    case JointKind::spring: return pa.distance(pb);
    case JointKind::pulley: return pa.distance(d.groundA) + d.ratio * pb.distance(d.groundB);
    case JointKind::gear: return jointCoordinate(d.jointA) + d.ratio * jointCoordinate(d.jointB);
    }
    return 0.0;
}

} // namespace rube
