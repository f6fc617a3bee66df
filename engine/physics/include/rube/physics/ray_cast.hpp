#pragma once
/// Ray casts against a World's circles and segments: the first surface a ray from a point meets.
/// The physics knows nothing of what casts them (a laser's beam in the game, a line of sight).
///
/// A ray is p(t) = origin + t d, t >= 0, d a unit direction, so t is the distance travelled. It meets
/// a circle (centre c, radius r) where |p(t) - c|^2 = r^2: t^2 + 2 t (d . m) + |m|^2 - r^2 = 0 with
/// m = origin - c, the smaller root t = -(d . m) - sqrt((d . m)^2 - |m|^2 + r^2) (lecture 5's
/// line-circle intersection). A segment with a radius is a capsule: its two end caps are circles,
/// and its two sides are the lines through a and b moved out by r along the unit normal n, met at
/// t = (r - (origin - a) . n) / (d . n) from the side the ray approaches. Only surfaces the ray
/// enters count: a ray that starts on or inside a shape (a beam leaving a mirror it just struck)
/// does not meet that shape again.
/// Rigid bodies count too: a capsule as a segment's capsule, a box by clipping the ray against its
/// four faces' half-planes (Cyrus-Beck): it enters at the largest t of the faces it crosses inwards,
/// if that comes before the smallest t of those it crosses outwards.

#include "rube/physics/vec2.hpp"

#include <cstdint>
#include <optional>

namespace rube {

class World;

/// What a ray met first.
struct RayHit {
    enum class Shape : std::uint8_t { circle, segment, body };
    Shape shape = Shape::circle;
    int slot = -1;         ///< the circle's, segment's or body's slot in World::circles(), segments() or bodies()
    double distance = 0.0; ///< t: how far along the ray, m
    Vec2 point;            ///< where: origin + distance * direction
    Vec2 normal;           ///< the unit normal of the surface there, pointing out of the shape (against the ray)
};

/// The first circle, segment, box or capsule surface the ray from `origin` along unit `direction`
/// enters within `maxDistance` m, if any. Every enabled body counts, whatever its motion.
std::optional<RayHit> rayCast(const World& world, Vec2 origin, Vec2 direction, double maxDistance);

/// The ray from `origin` along unit `direction` against one circle: the distance at which it enters,
/// if it does (none when it starts inside or on it, or misses).
std::optional<double> rayCircle(Vec2 origin, Vec2 direction, Vec2 centre, double radius);

} // namespace rube
