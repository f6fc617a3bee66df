// Circles held on static line faces within an exact step (see exact_held_faces.hpp).
#include "exact_held_faces.hpp"

#include "polynomial.hpp"

#include <algorithm>
#include <cmath>

namespace rube {
namespace {

// Two faces hold a circle still when their normals are not parallel (|n1 x n2| above round-off).
constexpr double kParallelSine = 1e-9;

} // namespace

void HeldFaces::reset(std::size_t circleCount, Vec2 gravity) {
    faces_.clear();
    accelerations_.assign(circleCount, gravity);
    free_.assign(circleCount, gravity);
}

void HeldFaces::setFreeAcceleration(int circle, Vec2 free) {
    free_[static_cast<std::size_t>(circle)] = free;
    accelerations_[static_cast<std::size_t>(circle)] = free;
}

// A face that carries no weight (gravity, or gravity and a magnet, pull the circle off it) holds nothing. Lines of a
// world with blocks are left to the end-of-step settle (the blocks' search assumes plain gravity): the caller holds
// only in worlds without them.
void HeldFaces::hold(StepContext& ctx, int circle, int segment, Vec2 normal) {
    const Segment& s = ctx.segments[segment];
    if (s.motion() != Motion::fixed || !(free_[static_cast<std::size_t>(circle)].dot(normal) < 0.0)) return;
    Circle& c = ctx.circles[circle];
    for (const HeldFace& held : faces_) {
        // Held by two faces at an angle, it is wedged: the only velocity both leave is zero.
        if (held.circle == circle && std::abs(held.normal.cross(normal)) > kParallelSine) c.velocity = {};
    }
    faces_.push_back(HeldFace{circle, segment, normal});
    accelerations_[static_cast<std::size_t>(circle)] = heldAcceleration(circle);
}

// The free acceleration g (gravity, and a magnet's pull) less what the faces holding the circle
// cancel: the nearest acceleration to g that pushes into none of them (a ~ g - (g . n) n on one
// face; zero in a V).
Vec2 HeldFaces::heldAcceleration(int circle) const {
    const Vec2 g = free_[static_cast<std::size_t>(circle)];
    const auto pushesIntoNone = [&](Vec2 a) {
        for (const HeldFace& held : faces_)
            if (held.circle == circle && a.dot(held.normal) < 0.0) return false;
        return true;
    };
    if (pushesIntoNone(g)) return g;
    for (const HeldFace& held : faces_) {
        if (held.circle != circle) continue;
        const Vec2 along = g - held.normal * g.dot(held.normal);
        // Round-off may leave a hair into the face itself: that one holds it, so it counts as on it.
        bool ok = true;
        for (const HeldFace& other : faces_)
            if (other.circle == circle && &other != &held && along.dot(other.normal) < 0.0) ok = false;
        if (ok) return along;
    }
    return {};
}

// along(t) = along0 + v t + a t^2 / 2 against 0 and the face's length.
std::optional<double> HeldFaces::leavesFace(const StepContext& ctx, int f, double horizon) const {
    const HeldFace& held = faces_[static_cast<std::size_t>(f)];
    const Segment& s = ctx.segments[held.segment];
    const Circle& c = ctx.circles[held.circle];
    const Vec2 axis = s.b - s.a;
    const double length = axis.length();
    const Vec2 u = axis * (1.0 / length);
    const double along = (c.position - s.a).dot(u);
    const double speed = c.velocity.dot(u);
    const double accel = acceleration(held.circle).dot(u);
    if (along < 0.0 || along > length) return 0.0; // already past an end (round-off at a joint)
    std::optional<double> first;
    for (const double end : {0.0, length}) {
        const Polynomial p{{along - end, speed, 0.5 * accel, 0.0, 0.0}};
        const auto t = earliestRoot(p, 0.0, horizon, true);
        if (t && (!first || *t < *first)) first = t;
    }
    return first;
}

HeldFace HeldFaces::release(int f) {
    const HeldFace held = faces_[static_cast<std::size_t>(f)];
    faces_.erase(faces_.begin() + f);
    accelerations_[static_cast<std::size_t>(held.circle)] = heldAcceleration(held.circle);
    return held;
}

void HeldFaces::letGo(int circle) {
    std::erase_if(faces_, [&](const HeldFace& held) { return held.circle == circle; });
    accelerations_[static_cast<std::size_t>(circle)] = free_[static_cast<std::size_t>(circle)];
}

} // namespace rube
