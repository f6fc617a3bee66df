#pragma once
// Internal: narrowphase for rigid bodies. Every shape the rigid contacts meet is a convex "rounded
// polygon" of one to four core vertices and a radius: a box is four vertices and radius 0, a capsule
// (and a line segment with rounded line caps) two vertices and its radius, a circle one vertex and
// its radius. One routine then finds the contact manifold of any pair (separating axis test on the
// cores, a reference face and the incident edge clipped against its side planes, as Box2D does).
// Not part of the public API.

#include "rube/physics/body.hpp"
#include "rube/physics/rigid_body.hpp"

#include <cstdint>

namespace rube {

/// A convex core polygon (counter-clockwise, world frame) swollen by `radius`.
struct RoundedPolygon {
    Vec2 vertices[4];
    Vec2 normals[4]; ///< outward unit normal of the edge from vertex i to vertex i + 1 (count >= 2)
    int count = 0;   ///< 1 (circle), 2 (capsule, segment) or 4 (box)
    double radius = 0.0;
};

/// The body's shape at `position` and `angle`.
RoundedPolygon makeRoundedPolygon(const RigidBody& body, Vec2 position, double angle);
/// A circle as a one-vertex rounded polygon.
RoundedPolygon makeRoundedPolygon(const Circle& circle);
/// A segment with rounded line caps as a two-vertex rounded polygon.
RoundedPolygon makeRoundedPolygon(const Segment& segment);

/// One point of a manifold.
struct ManifoldPoint {
    Vec2 point;           ///< world point midway between the two surfaces
    double separation;    ///< surface gap along the normal (negative: overlap), m
    std::uint32_t id = 0; ///< the features that made it (reference face, incident edge and end), equal from step to
                          ///< step while they touch
};

/// Up to two contact points sharing one normal.
struct Manifold {
    Vec2 normal; ///< unit, from shape A towards shape B
    ManifoldPoint points[2];
    int count = 0;
};

/// The distance between the cores of A and B (each of two or four vertices), with their closest
/// points pa and pb; -1 when the cores overlap (no separating axis among both shapes' edge normals).
double coreDistance(const RoundedPolygon& a, const RoundedPolygon& b, Vec2& pa, Vec2& pb);

/// The contact manifold of A and B, keeping only points whose gap is below `speculative` (m):
/// touching and overlapping points, and those close enough to touch within the step.
Manifold collideRoundedPolygons(const RoundedPolygon& a, const RoundedPolygon& b, double speculative);

} // namespace rube
