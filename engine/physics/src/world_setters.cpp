// World: setters between steps, and gravity scaled per body. A setter that changes a sleeping circle
// or rigid body wakes its island first (solver_sleep.hpp), so the change is seen by the next step.
#include "rube/physics/world.hpp"

#include "world_handles.hpp"

namespace rube {

Circle& World::circleState(CircleId id) {
    const HandleTable::Entry& e = tables_->circles.at(id.index, id.generation, "circle");
    return e.enabled ? circles_[static_cast<std::size_t>(e.slot)]
                     : tables_->parkedCircles[static_cast<std::size_t>(id.index)];
}

RigidBody& World::bodyState(BodyId id) {
    const HandleTable::Entry& e = tables_->bodies.at(id.index, id.generation, "rigid body");
    return e.enabled ? bodies_[static_cast<std::size_t>(e.slot)]
                     : tables_->parkedBodies[static_cast<std::size_t>(id.index)];
}

void World::wakeIsland(int island) {
    for (Circle& other : circles_)
        if (other.sleep.asleep && other.sleep.island == island) other.sleep = SleepState{};
    for (RigidBody& other : bodies_)
        if (other.sleep.asleep && other.sleep.island == island) other.sleep = SleepState{};
}

void World::wakeCircle(const Circle& c) {
    if (c.sleep.asleep) wakeIsland(c.sleep.island);
}

void World::wakeBody(const RigidBody& b) {
    if (b.sleep.asleep) wakeIsland(b.sleep.island);
}

void World::wakeEnds(const Rope& rope) {
    // A rope added, cut, enabled or removed changes what holds its circles (solver_sleep_ropes.cpp).
    if (isValid(rope.circleId)) wakeCircle(circleState(rope.circleId));
    if (!rope.otherId.isNull() && isValid(rope.otherId)) wakeCircle(circleState(rope.otherId));
}

void World::setPosition(CircleId id, Vec2 position) {
    Circle& c = circleState(id);
    wakeCircle(c);
    // A kinematic circle's path is an offset from where it was placed: the whole path moves.
    c.origin += position - c.position;
    c.position = position;
}

void World::setPosition(BodyId id, Vec2 position) {
    RigidBody& b = bodyState(id);
    wakeBody(b);
    b.position = position;
}

void World::setVelocity(CircleId id, Vec2 velocity) {
    Circle& c = circleState(id);
    if (c.motion != Motion::dynamic) return;
    wakeCircle(c);
    c.velocity = velocity;
}

void World::setVelocity(BodyId id, Vec2 velocity) {
    RigidBody& b = bodyState(id);
    if (b.motion == Motion::fixed) return;
    wakeBody(b);
    b.velocity = velocity;
}

void World::setAngularVelocity(CircleId id, double omega) {
    Circle& c = circleState(id);
    if (c.inverseInertia == 0.0) return;
    wakeCircle(c);
    c.angularVelocity = omega;
}

void World::setAngularVelocity(BodyId id, double omega) {
    RigidBody& b = bodyState(id);
    if (b.motion == Motion::fixed || b.fixedRotation) return;
    wakeBody(b);
    b.angularVelocity = omega;
}

void World::applyImpulse(CircleId id, Vec2 impulse) {
    Circle& c = circleState(id);
    if (c.inverseMass == 0.0) return;
    wakeCircle(c);
    c.velocity += impulse * c.inverseMass; // lecture 3: impulse = change of momentum
}

void World::applyImpulse(BodyId id, Vec2 impulse) {
    RigidBody& b = bodyState(id);
    if (b.inverseMass == 0.0) return;
    wakeBody(b);
    b.velocity += impulse * b.inverseMass;
}

void World::applyImpulseAt(BodyId id, Vec2 impulse, Vec2 point) {
    RigidBody& b = bodyState(id);
    if (b.inverseMass == 0.0 && b.inverseInertia == 0.0) return;
    wakeBody(b);
    // Delta v = J / m, Delta omega = (r x J) / I with r from the centre of mass to the point.
    b.velocity += impulse * b.inverseMass;
    b.angularVelocity += (point - b.position).cross(impulse) * b.inverseInertia;
}

void World::setGravityScale(CircleId id, double scale) {
    Circle& c = circleState(id);
    wakeCircle(c);
    c.gravityScale = scale;
}

void World::setGravityScale(BodyId id, double scale) {
    RigidBody& b = bodyState(id);
    wakeBody(b);
    b.gravityScale = scale;
}

void World::setRadius(CircleId id, double radius) {
    Circle& c = circleState(id);
    wakeCircle(c);
    c.radius = radius;
}

// Every method moves a dynamic body under the world's gravity g; a body with scale s feels s g, so it
// also feels the constant force (s - 1) g m. As a thruster's (fields.cpp, kickThrusters), its impulse
// is split in halves around the move: the move at constant velocity then lands exactly on
// x0 + v0 t + s g t^2 / 2 wherever the method is exact for gravity, and v ends at v0 + s g t.
// Called twice a step, before and after the method; bodies of scale 1 (the default) cost nothing, and
// asleep circles are held by their contacts as under plain gravity.
void World::applyGravityScales(double dt) {
    for (Circle& c : circles_)
        if (c.gravityScale != 1.0 && c.motion == Motion::dynamic && c.inverseMass > 0.0 && !c.sleep.asleep)
            c.velocity += def_.gravity * ((c.gravityScale - 1.0) * 0.5 * dt);
    for (RigidBody& b : bodies_)
        if (b.gravityScale != 1.0 && b.motion == Motion::dynamic && b.inverseMass > 0.0 && !b.sleep.asleep)
            b.velocity += def_.gravity * ((b.gravityScale - 1.0) * 0.5 * dt);
}

} // namespace rube
