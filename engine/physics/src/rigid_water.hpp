#pragma once
// Internal: boxes and capsules in water (Archimedes for a body that turns). Not part of the public API.
//
// A circle's buoyancy acts through its centre (field_pass.cpp); a box's acts through the centroid of
// the part of it under water, so it also turns the body: a plank floats flat, and a tall box, whose
// centre of buoyancy moves the wrong way when it tilts, rolls onto its side as a real one does. The
// submerged part is the body's outline clipped by the pool (Sutherland-Hodgman against the pool's four
// sides): exact for a box; a capsule's caps are polygons of kCapSides sides (their area within 0.7 %).

#include "rube/physics/fields.hpp"
#include "rube/physics/rigid_body.hpp"

#include <span>

namespace rube {

/// The sides of each of a capsule's half-disc caps in its outline.
inline constexpr int kCapSides = 16;

/// The area of body `b` under the surface of `water` and its centroid (area 0: none under).
struct Submerged {
    double area = 0.0;
    Vec2 centroid;
    double waterline = 0.0; ///< the width of the body at the surface, m (what a rise uncovers per metre)
    double whole = 0.0;     ///< the whole outline's area (a capsule's with polygonal caps), when any is under
};
Submerged submergedPart(const RigidBody& b, const Water& water);

/// Changes each dynamic body's velocity and spin by what the pools do over dt: buoyancy rho A |g|
/// against gravity at the submerged centroid, and drag slowing both velocity and spin at the rate a
/// circle of the same area would feel, k = w drag (A / A_body) / m, w = 2 sqrt(A_body / pi).
void floatRigidBodies(std::span<RigidBody> bodies, std::span<const Water> waters, Vec2 gravity, double dt);

} // namespace rube
