// World: handles, remove and disable, the caller's values and the setters between steps. The arrays
// stay packed in insertion order; what leaves or enters them moves the others' slots, and everything
// kept per slot (the world's escape flags and finite poses, the methods' warm starts and stints,
// sleeping islands, the last step's impacts) follows (world_handles.hpp).
#include "rube/physics/world.hpp"

#include "speed_limits.hpp"
#include "step_method.hpp"
#include "world_handles.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

namespace rube {

namespace {

SlotMap identity(int count) {
    SlotMap map;
    map.size = count;
    map.to.resize(static_cast<std::size_t>(count));
    for (int s = 0; s < count; ++s) map.to[static_cast<std::size_t>(s)] = s;
    return map;
}

template <class T>
void eraseSlot(std::vector<T>& items, int slot) {
    items.erase(items.begin() + slot);
}

template <class T>
void insertSlot(std::vector<T>& items, int slot, const T& item) {
    items.insert(items.begin() + slot, item);
}

// Per new slot: true when some old slot moved there (false: it just entered).
std::vector<std::uint8_t> filled(const SlotMap& map) {
    std::vector<std::uint8_t> out(static_cast<std::size_t>(map.size), 0);
    for (const int to : map.to)
        if (to >= 0) out[static_cast<std::size_t>(to)] = 1;
    return out;
}

} // namespace

// Wakes the islands of sleepers touching segment `s` (within a centimetre): what rested on it falls.
void World::wakeNear(const Segment& s) {
    const Vec2 ab = s.b - s.a;
    const double l2 = ab.lengthSquared();
    for (const Circle& c : circles_) {
        if (!c.sleep.asleep) continue;
        // The closest point by scalar projection, clamped to the segment (lecture 5).
        const double t = l2 > 0.0 ? std::clamp((c.position - s.a).dot(ab) / l2, 0.0, 1.0) : 0.0;
        if (c.position.distance(s.a + ab * t) <= c.radius + s.radius + 0.01) wakeCircle(c);
    }
    // A rigid body by the circle around it (its centre to its farthest point): a few more wake than
    // touch, none that touches stays asleep.
    for (const RigidBody& b : bodies_) {
        if (!b.sleep.asleep) continue;
        const double t = l2 > 0.0 ? std::clamp((b.position - s.a).dot(ab) / l2, 0.0, 1.0) : 0.0;
        if (b.position.distance(s.a + ab * t) <= boundingRadius(b) + s.radius + 0.01) wakeBody(b);
    }
}

// ---- where slots went ----

void World::remapSlots(const SlotRemap& remap) {
    remapParallel(escaped_, remap.circles, std::uint8_t{0});
    remapParallel(escapedBodies_, remap.bodies, std::uint8_t{0});
    // Finite poses: a body that (re)entered is finite where it stands (the next check records it).
    if (finite_->circlePositions.size() == remap.circles.to.size()) {
        remapParallel(finite_->circlePositions, remap.circles, Vec2{});
        const std::vector<std::uint8_t> kept = filled(remap.circles);
        for (std::size_t s = 0; s < circles_.size(); ++s)
            if (!kept[s]) finite_->circlePositions[s] = circles_[s].position;
    }
    if (finite_->bodyPositions.size() == remap.bodies.to.size()) {
        remapParallel(finite_->bodyPositions, remap.bodies, Vec2{});
        remapParallel(finite_->bodyAngles, remap.bodies, 0.0);
        const std::vector<std::uint8_t> kept = filled(remap.bodies);
        for (std::size_t s = 0; s < bodies_.size(); ++s)
            if (!kept[s]) {
                finite_->bodyPositions[s] = bodies_[s].position;
                finite_->bodyAngles[s] = bodies_[s].angle;
            }
    }
    // A sleeping island is named by one of its circles' slots, or with no circle by -1 - one of its
    // rigid bodies' slots: by that member's new slot, or, when it left, by the new slot of the first
    // member that stayed (circles first, as islands are named).
    std::vector<std::pair<int, int>> orphans; // old island, its new name
    const auto rename = [&](SleepState& sleep, int newName) {
        if (!sleep.asleep) return;
        const int old = sleep.island;
        int to = old >= 0 ? remap.circles(old) : -1 - remap.bodies(-1 - old);
        if (old >= 0 ? to < 0 : to >= 0) {
            auto it = std::find_if(orphans.begin(), orphans.end(), [&](const auto& o) { return o.first == old; });
            if (it == orphans.end()) it = orphans.insert(orphans.end(), {old, newName});
            to = it->second;
        }
        sleep.island = to;
    };
    for (std::size_t s = 0; s < circles_.size(); ++s) rename(circles_[s].sleep, static_cast<int>(s));
    for (std::size_t s = 0; s < bodies_.size(); ++s) rename(bodies_[s].sleep, -1 - static_cast<int>(s));
    // The last step's impacts name slots too: those of what left are dropped.
    std::vector<Impact> kept;
    for (Impact impact : impacts_) {
        const bool otherCircle = impact.otherKind == Other::circle;
        const SlotMap& others = otherCircle                       ? remap.circles
                                : impact.otherKind == Other::body ? remap.bodies
                                                                  : remap.segments;
        const int circle = remap.circles(impact.circle), other = others(impact.other), body = remap.bodies(impact.body);
        if ((impact.circle >= 0 && circle < 0) || (impact.other >= 0 && other < 0) || (impact.body >= 0 && body < 0))
            continue;
        impact.circle = circle;
        impact.other = other;
        impact.body = body;
        kept.push_back(impact);
    }
    impacts_.swap(kept);
    method_->remapSlots(remap);
}

void World::leaveCircle(int entry) {
    HandleTable& table = tables_->circles;
    const int slot = table.entry(entry).slot;
    const Circle c = circles_[static_cast<std::size_t>(slot)];
    // Whatever slept on it wakes: it may have been resting on this one.
    wakeCircle(c);
    perEntry(tables_->parkedCircles, entry) = circles_[static_cast<std::size_t>(slot)];
    perEntry(tables_->circleEscaped, entry) = escaped_[static_cast<std::size_t>(slot)];
    SlotRemap remap{table.leave(entry), identity(static_cast<int>(segments_.size())),
                    identity(static_cast<int>(bodies_.size()))};
    eraseSlot(circles_, slot);
    remapSlots(remap);
}

void World::leaveBody(int entry) {
    HandleTable& table = tables_->bodies;
    const int slot = table.entry(entry).slot;
    // Whatever slept on it wakes: it may have been resting on this one.
    wakeBody(bodies_[static_cast<std::size_t>(slot)]);
    perEntry(tables_->parkedBodies, entry) = bodies_[static_cast<std::size_t>(slot)];
    perEntry(tables_->bodyEscaped, entry) = escapedBodies_[static_cast<std::size_t>(slot)];
    SlotRemap remap{identity(static_cast<int>(circles_.size())), identity(static_cast<int>(segments_.size())),
                    table.leave(entry)};
    eraseSlot(bodies_, slot);
    remapSlots(remap);
}

// Ropes and pivots act while their own switch is on and their bodies are in the arrays; they wait
// outside their arrays otherwise. Their slots are refreshed from their handles after every change.
void World::syncJoints() {
    HandleTable& ropes = tables_->ropes;
    for (int e = 0; e < ropes.entryCount(); ++e) {
        HandleTable::Entry& entry = ropes.entry(e);
        if (!entry.live) continue;
        const Rope& rope = entry.enabled ? ropes_[static_cast<std::size_t>(entry.slot)]
                                         : tables_->parkedRopes[static_cast<std::size_t>(e)];
        const bool acts = tables_->ropeOn[static_cast<std::size_t>(e)] && isEnabled(rope.circleId) &&
                          (rope.otherId.isNull() || isEnabled(rope.otherId));
        if (entry.enabled && !acts) {
            const int slot = entry.slot;
            perEntry(tables_->parkedRopes, e) = ropes_[static_cast<std::size_t>(slot)];
            tables_->parkedRopes[static_cast<std::size_t>(e)].circle = tables_->parkedRopes[static_cast<std::size_t>(e)]
                                                                           .other = -1;
            ropes.leave(e);
            eraseSlot(ropes_, slot);
        } else if (!entry.enabled && acts) {
            ropes.enter(e);
            insertSlot(ropes_, entry.slot, tables_->parkedRopes[static_cast<std::size_t>(e)]);
        }
    }
    for (Rope& rope : ropes_) {
        rope.circle = slot(rope.circleId);
        rope.other = rope.otherId.isNull() ? -1 : slot(rope.otherId);
    }
    HandleTable& pivots = tables_->pivots;
    for (int e = 0; e < pivots.entryCount(); ++e) {
        HandleTable::Entry& entry = pivots.entry(e);
        if (!entry.live) continue;
        const Pivot& pivot = entry.enabled ? pivots_[static_cast<std::size_t>(entry.slot)]
                                           : tables_->parkedPivots[static_cast<std::size_t>(e)];
        const bool acts = tables_->pivotOn[static_cast<std::size_t>(e)] && isEnabled(pivot.bodyId);
        if (entry.enabled && !acts) {
            const int slot = entry.slot;
            perEntry(tables_->parkedPivots, e) = pivots_[static_cast<std::size_t>(slot)];
            tables_->parkedPivots[static_cast<std::size_t>(e)].body = -1;
            pivots.leave(e);
            eraseSlot(pivots_, slot);
        } else if (!entry.enabled && acts) {
            pivots.enter(e);
            insertSlot(pivots_, entry.slot, tables_->parkedPivots[static_cast<std::size_t>(e)]);
        }
    }
    for (Pivot& pivot : pivots_) pivot.body = slot(pivot.bodyId);
    syncMachineJoints();
}

// ---- remove ----

void World::remove(CircleId id) {
    tables_->circles.at(id.index, id.generation, "circle");
    // Its ropes go with it.
    for (int e = 0; e < tables_->ropes.entryCount(); ++e) {
        const HandleTable::Entry& entry = tables_->ropes.entry(e);
        if (!entry.live) continue;
        const Rope& r = rope(RopeId{e, entry.generation});
        if (r.circleId == id || r.otherId == id) remove(RopeId{e, entry.generation});
    }
    removeJointsOf(JointEnd{id, {}});
    if (tables_->circles.entry(id.index).enabled) leaveCircle(id.index);
    tables_->circles.retire(id.index);
    syncJoints(); // the other ropes' slots moved
}

void World::remove(SegmentId id) {
    HandleTable::Entry& entry = tables_->segments.at(id.index, id.generation, "segment");
    if (entry.enabled) {
        const int slot = entry.slot;
        SlotRemap remap{identity(static_cast<int>(circles_.size())), tables_->segments.leave(id.index),
                        identity(static_cast<int>(bodies_.size()))};
        wakeNear(segments_[static_cast<std::size_t>(slot)]); // what rested on it falls
        eraseSlot(segments_, slot);
        remapSlots(remap);
    }
    tables_->segments.retire(id.index);
}

void World::remove(BodyId id) {
    tables_->bodies.at(id.index, id.generation, "rigid body");
    // Its pivots go with it.
    for (int e = 0; e < tables_->pivots.entryCount(); ++e) {
        const HandleTable::Entry& entry = tables_->pivots.entry(e);
        if (entry.live && pivot(PivotId{e, entry.generation}).bodyId == id) remove(PivotId{e, entry.generation});
    }
    removeJointsOf(JointEnd{{}, id});
    if (tables_->bodies.entry(id.index).enabled) leaveBody(id.index);
    tables_->bodies.retire(id.index);
    syncJoints(); // the other pivots' slots moved
}

void World::remove(RopeId id) {
    HandleTable::Entry& entry = tables_->ropes.at(id.index, id.generation, "rope");
    wakeEnds(rope(id));
    if (entry.enabled) {
        const int slot = entry.slot;
        tables_->ropes.leave(id.index);
        eraseSlot(ropes_, slot);
    }
    tables_->ropes.retire(id.index);
}

void World::remove(PivotId id) {
    HandleTable::Entry& entry = tables_->pivots.at(id.index, id.generation, "pivot");
    if (isValid(pivot(id).bodyId)) wakeBody(bodyState(pivot(id).bodyId)); // what it held may fall
    if (entry.enabled) {
        const int slot = entry.slot;
        tables_->pivots.leave(id.index);
        eraseSlot(pivots_, slot);
    }
    tables_->pivots.retire(id.index);
}

// ---- disable and enable ----

void World::setEnabled(CircleId id, bool enabled) {
    HandleTable::Entry& entry = tables_->circles.at(id.index, id.generation, "circle");
    if (entry.enabled == enabled) return;
    if (!enabled) {
        leaveCircle(id.index);
    } else {
        HandleTable& table = tables_->circles;
        SlotRemap remap{table.enter(id.index), identity(static_cast<int>(segments_.size())),
                        identity(static_cast<int>(bodies_.size()))};
        Circle c = tables_->parkedCircles[static_cast<std::size_t>(id.index)];
        c.sleep = SleepState{}; // back awake: its island is gone
        insertSlot(circles_, table.entry(id.index).slot, c);
        remapSlots(remap);
        escaped_[static_cast<std::size_t>(table.entry(id.index).slot)] =
            tables_->circleEscaped[static_cast<std::size_t>(id.index)];
    }
    syncJoints();
}

void World::setEnabled(SegmentId id, bool enabled) {
    HandleTable::Entry& entry = tables_->segments.at(id.index, id.generation, "segment");
    if (entry.enabled == enabled) return;
    HandleTable& table = tables_->segments;
    SlotRemap remap{identity(static_cast<int>(circles_.size())), {}, identity(static_cast<int>(bodies_.size()))};
    if (!enabled) {
        const int slot = entry.slot;
        perEntry(tables_->parkedSegments, id.index) = segments_[static_cast<std::size_t>(slot)];
        remap.segments = table.leave(id.index);
        wakeNear(segments_[static_cast<std::size_t>(slot)]); // what rested on it falls
        eraseSlot(segments_, slot);
    } else {
        remap.segments = table.enter(id.index);
        insertSlot(segments_, table.entry(id.index).slot, tables_->parkedSegments[static_cast<std::size_t>(id.index)]);
    }
    remapSlots(remap);
}

void World::setSurfaceSpeed(SegmentId id, double speed) {
    const HandleTable::Entry& entry = tables_->segments.at(id.index, id.generation, "segment");
    if (!std::isfinite(speed)) throw std::invalid_argument("a segment's surface speed must be finite");
    if (!entry.enabled) {
        tables_->parkedSegments[static_cast<std::size_t>(id.index)].surfaceSpeed = speed; // as it will be
        return;
    }
    Segment& s = segments_[static_cast<std::size_t>(entry.slot)];
    if (s.surfaceSpeed == speed) return;
    s.surfaceSpeed = speed;
    wakeNear(s); // a crate asleep on a belt that starts is carried, one on a belt that stops slides on
}

void World::setEnabled(BodyId id, bool enabled) {
    HandleTable::Entry& entry = tables_->bodies.at(id.index, id.generation, "rigid body");
    if (entry.enabled == enabled) return;
    if (!enabled) {
        leaveBody(id.index);
    } else {
        HandleTable& table = tables_->bodies;
        SlotRemap remap{identity(static_cast<int>(circles_.size())), identity(static_cast<int>(segments_.size())),
                        table.enter(id.index)};
        insertSlot(bodies_, table.entry(id.index).slot, tables_->parkedBodies[static_cast<std::size_t>(id.index)]);
        remapSlots(remap);
        escapedBodies_[static_cast<std::size_t>(table.entry(id.index).slot)] =
            tables_->bodyEscaped[static_cast<std::size_t>(id.index)];
    }
    syncJoints();
}

void World::setEnabled(RopeId id, bool enabled) {
    tables_->ropes.at(id.index, id.generation, "rope");
    wakeEnds(rope(id));
    tables_->ropeOn[static_cast<std::size_t>(id.index)] = enabled ? 1 : 0;
    syncJoints();
}

void World::setEnabled(PivotId id, bool enabled) {
    tables_->pivots.at(id.index, id.generation, "pivot");
    tables_->pivotOn[static_cast<std::size_t>(id.index)] = enabled ? 1 : 0;
    if (isValid(pivot(id).bodyId)) wakeBody(bodyState(pivot(id).bodyId));
    syncJoints();
}

void World::cutRope(RopeId id) {
    HandleTable::Entry& entry = tables_->ropes.at(id.index, id.generation, "rope");
    Rope& r = entry.enabled ? ropes_[static_cast<std::size_t>(entry.slot)]
                            : tables_->parkedRopes[static_cast<std::size_t>(id.index)];
    if (!r.cut) wakeEnds(r); // what it held falls
    r.cut = true;
}

// ---- lookups ----

bool World::isValid(CircleId id) const { return tables_->circles.find(id.index, id.generation) != nullptr; }
bool World::isValid(SegmentId id) const { return tables_->segments.find(id.index, id.generation) != nullptr; }
bool World::isValid(BodyId id) const { return tables_->bodies.find(id.index, id.generation) != nullptr; }
bool World::isValid(RopeId id) const { return tables_->ropes.find(id.index, id.generation) != nullptr; }
bool World::isValid(PivotId id) const { return tables_->pivots.find(id.index, id.generation) != nullptr; }

bool World::isEnabled(CircleId id) const { return tables_->circles.at(id.index, id.generation, "circle").enabled; }
bool World::isEnabled(SegmentId id) const { return tables_->segments.at(id.index, id.generation, "segment").enabled; }
bool World::isEnabled(BodyId id) const { return tables_->bodies.at(id.index, id.generation, "rigid body").enabled; }
bool World::isEnabled(RopeId id) const {
    tables_->ropes.at(id.index, id.generation, "rope");
    return tables_->ropeOn[static_cast<std::size_t>(id.index)] != 0;
}
bool World::isEnabled(PivotId id) const {
    tables_->pivots.at(id.index, id.generation, "pivot");
    return tables_->pivotOn[static_cast<std::size_t>(id.index)] != 0;
}

const Circle& World::circle(CircleId id) const {
    const HandleTable::Entry& e = tables_->circles.at(id.index, id.generation, "circle");
    return e.enabled ? circles_[static_cast<std::size_t>(e.slot)]
                     : tables_->parkedCircles[static_cast<std::size_t>(id.index)];
}
const Segment& World::segment(SegmentId id) const {
    const HandleTable::Entry& e = tables_->segments.at(id.index, id.generation, "segment");
    return e.enabled ? segments_[static_cast<std::size_t>(e.slot)]
                     : tables_->parkedSegments[static_cast<std::size_t>(id.index)];
}
const RigidBody& World::body(BodyId id) const {
    const HandleTable::Entry& e = tables_->bodies.at(id.index, id.generation, "rigid body");
    return e.enabled ? bodies_[static_cast<std::size_t>(e.slot)]
                     : tables_->parkedBodies[static_cast<std::size_t>(id.index)];
}
const Rope& World::rope(RopeId id) const {
    const HandleTable::Entry& e = tables_->ropes.at(id.index, id.generation, "rope");
    return e.enabled ? ropes_[static_cast<std::size_t>(e.slot)]
                     : tables_->parkedRopes[static_cast<std::size_t>(id.index)];
}
const Pivot& World::pivot(PivotId id) const {
    const HandleTable::Entry& e = tables_->pivots.at(id.index, id.generation, "pivot");
    return e.enabled ? pivots_[static_cast<std::size_t>(e.slot)]
                     : tables_->parkedPivots[static_cast<std::size_t>(id.index)];
}

int World::slot(CircleId id) const { return tables_->circles.at(id.index, id.generation, "circle").slot; }
int World::slot(SegmentId id) const { return tables_->segments.at(id.index, id.generation, "segment").slot; }
int World::slot(BodyId id) const { return tables_->bodies.at(id.index, id.generation, "rigid body").slot; }
int World::slot(RopeId id) const { return tables_->ropes.at(id.index, id.generation, "rope").slot; }
int World::slot(PivotId id) const { return tables_->pivots.at(id.index, id.generation, "pivot").slot; }

CircleId World::circleId(int slot) const { return idOfSlot<CircleId>(tables_->circles, slot); }
SegmentId World::segmentId(int slot) const { return idOfSlot<SegmentId>(tables_->segments, slot); }
BodyId World::bodyId(int slot) const { return idOfSlot<BodyId>(tables_->bodies, slot); }
RopeId World::ropeId(int slot) const { return idOfSlot<RopeId>(tables_->ropes, slot); }
PivotId World::pivotId(int slot) const { return idOfSlot<PivotId>(tables_->pivots, slot); }

std::uint64_t World::userValue(CircleId id) const {
    return tables_->circles.at(id.index, id.generation, "circle").userValue;
}
std::uint64_t World::userValue(BodyId id) const {
    return tables_->bodies.at(id.index, id.generation, "rigid body").userValue;
}
void World::setUserValue(CircleId id, std::uint64_t value) {
    tables_->circles.at(id.index, id.generation, "circle").userValue = value;
}
void World::setUserValue(BodyId id, std::uint64_t value) {
    tables_->bodies.at(id.index, id.generation, "rigid body").userValue = value;
}

void World::nameFirstIsolated() {
    if (stats_.firstIsolatedKind == Other::body) stats_.firstIsolatedBody = bodyId(stats_.firstIsolatedSlot);
    else stats_.firstIsolatedCircle = circleId(stats_.firstIsolatedSlot);
}

void World::resolveThrusters() {
    std::vector<int>& slots = tables_->thrusterSlots;
    slots.resize(fields_.thrusters.size());
    for (std::size_t k = 0; k < slots.size(); ++k) {
        const CircleId id = fields_.thrusters[k].circle;
        slots[k] = isValid(id) ? slot(id) : -1;
    }
}

} // namespace rube
