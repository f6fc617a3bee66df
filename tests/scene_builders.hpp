#pragma once
// Small builders the physics tests share, so each test reads as the scene it sets up.

#include "rube/physics/body.hpp"

namespace rube::test {

/// A static line from a to b with rounded caps of `radius` (0: the lecture's thin line).
inline SegmentDef line(Vec2 a, Vec2 b, double radius = 0.0) {
    SegmentDef def;
    def.a = a;
    def.b = b;
    def.radius = radius;
    return def;
}

/// A 1 kg dynamic ball, perfectly elastic unless the caller changes its material.
inline CircleDef ball(Vec2 position, Vec2 velocity, double radius) {
    CircleDef def;
    def.position = position;
    def.velocity = velocity;
    def.radius = radius;
    return def;
}

} // namespace rube::test
