#pragma once
// The angular momentum about a point of every dynamic body in a world, L = sum (I omega + m r x v)
// (lecture 3), I and m the inverses of what the world keeps: what the wheels' tests weigh impulses by.
#include "rube/physics/world.hpp"

namespace test {

inline double angularMomentumAbout(const rube::World& world, rube::Vec2 axle) {
    double L = 0.0;
    for (const rube::Circle& c : world.circles())
        if (c.motion == rube::Motion::dynamic && c.inverseMass > 0.0)
            L += (c.inverseInertia > 0.0 ? c.angularVelocity / c.inverseInertia : 0.0) +
                 (c.position - axle).cross(c.velocity) / c.inverseMass;
    for (const rube::RigidBody& b : world.bodies())
        if (b.motion == rube::Motion::dynamic && b.inverseMass > 0.0)
            L += (b.inverseInertia > 0.0 ? b.angularVelocity / b.inverseInertia : 0.0) +
                 (b.position - axle).cross(b.velocity) / b.inverseMass;
    return L;
}

} // namespace test
