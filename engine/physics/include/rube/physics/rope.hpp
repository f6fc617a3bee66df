#pragma once
/// Ropes: an inextensible rope from a dynamic circle's centre to a fixed anchor point or to another
/// circle's centre. A rope is a one-sided distance constraint |p_a - p_b| <= length: slack when
/// shorter, it pulls (never pushes) when taut. Every time-step method supports ropes the same way:
/// the world corrects velocities and positions after the method's step (see rope_constraint.cpp).

#include "rube/physics/handles.hpp"
#include "rube/physics/vec2.hpp"

namespace rube {

/// What a caller fills in to add a rope; the default is a 1 m rope to an anchor at the origin.
struct RopeDef {
    CircleId circle;     ///< the circle at one end (dynamic, or the rope does nothing)
    CircleId other;      ///< the circle at the other end, or null for the fixed `anchor`
    Vec2 anchor;         ///< the fixed end, m (used when `other` is null)
    double length = 1.0; ///< the most the ends may be apart, m (> 0)
};

/// A rope in the world. A cut rope stays in the list and no longer acts.
struct Rope {
    int circle = -1;     ///< slot (World::circles()) of the circle at one end, -1 while the rope waits
    int other = -1;      ///< slot of the circle at the other end, or -1 for `anchor`
    CircleId circleId;   ///< the circle at one end
    CircleId otherId;    ///< the circle at the other end, null for `anchor`
    Vec2 anchor;         ///< the fixed end when `other` is -1, m
    double length = 1.0; ///< m
    bool cut = false;    ///< true once cut: the rope stops acting
};

} // namespace rube
