// Boxes and capsules in water (rigid_water.hpp).
#include "rigid_water.hpp"

#include "field_pass.hpp"
#include "rigid_solver_body.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace rube {

namespace {

/// Outline points: a box's 4 corners or a capsule's 2 (kCapSides + 1), and room for the clipper's
/// extra points (one more per side clipped).
constexpr int kMaxPoints = 2 * (kCapSides + 1) + 8;

struct Polygon {
    std::array<Vec2, kMaxPoints> points;
    int count = 0;
};

/// The body's outline in the world, anticlockwise.
Polygon outlineOf(const RigidBody& b) {
    Polygon p;
    const Vec2 q = Vec2::fromAngle(b.angle);
    const auto place = [&](Vec2 local) { return b.position + rotate(q, local); };
    const double hx = b.halfExtents.x, hy = b.halfExtents.y;
    if (b.shape == BodyShape::box) {
        for (const Vec2 corner : {Vec2{-hx, -hy}, Vec2{hx, -hy}, Vec2{hx, hy}, Vec2{-hx, hy}})
            p.points[static_cast<std::size_t>(p.count++)] = place(corner);
        return p;
    }
    // A capsule: the cap about (hx, 0) from -90 to +90 degrees, then the one about (-hx, 0) on round.
    for (int cap = 0; cap < 2; ++cap) {
        const double centre = cap == 0 ? hx : -hx, start = cap == 0 ? -0.5 * std::numbers::pi : 0.5 * std::numbers::pi;
        for (int k = 0; k <= kCapSides; ++k) {
            const double a = start + std::numbers::pi * k / kCapSides;
            p.points[static_cast<std::size_t>(p.count++)] = place({centre + hy * std::cos(a), hy * std::sin(a)});
        }
    }
    return p;
}

/// Keeps the part of `p` where n . x <= offset (one Sutherland-Hodgman pass).
Polygon clip(const Polygon& p, Vec2 n, double offset) {
    Polygon out;
    for (int i = 0; i < p.count; ++i) {
        const Vec2 a = p.points[static_cast<std::size_t>(i)], b = p.points[static_cast<std::size_t>((i + 1) % p.count)];
        const double da = n.dot(a) - offset, db = n.dot(b) - offset;
        if (da <= 0.0) out.points[static_cast<std::size_t>(out.count++)] = a;
        if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0))
            out.points[static_cast<std::size_t>(out.count++)] = a + (b - a) * (da / (da - db));
    }
    return out;
}

/// Area and centroid by the shoelace formula: A = 1/2 sum x_i y_(i+1) - x_(i+1) y_i, and the centroid
/// the triangles' centroids weighted by their signed areas.
Submerged areaOf(const Polygon& p) {
    Submerged s;
    if (p.count < 3) return s;
    double twice = 0.0;
    Vec2 weighted;
    for (int i = 0; i < p.count; ++i) {
        const Vec2 a = p.points[static_cast<std::size_t>(i)], b = p.points[static_cast<std::size_t>((i + 1) % p.count)];
        const double cross = a.cross(b);
        twice += cross;
        weighted += (a + b) * cross;
    }
    if (!(twice > 0.0)) return s;
    s.area = 0.5 * twice;
    s.centroid = weighted / (3.0 * twice);
    return s;
}

} // namespace

Submerged submergedPart(const RigidBody& b, const Water& water) {
    const Polygon outline = outlineOf(b);
    Polygon p = clip(outline, {0.0, 1.0}, water.max.y); // under the surface
    p = clip(p, {0.0, -1.0}, -water.min.y); // above the pool's floor
    p = clip(p, {1.0, 0.0}, water.max.x);
    p = clip(p, {-1.0, 0.0}, -water.min.x);
    Submerged s = areaOf(p);
    if (s.area <= 0.0) return s;
    s.whole = areaOf(outline).area;
    // The waterline: the clipped outline's points on the surface, their extent along it.
    double lo = 0.0, hi = 0.0;
    bool any = false;
    for (int i = 0; i < p.count; ++i) {
        const Vec2 v = p.points[static_cast<std::size_t>(i)];
        if (std::abs(v.y - water.max.y) > 1e-12 * (1.0 + std::abs(water.max.y))) continue;
        lo = any ? std::min(lo, v.x) : v.x;
        hi = any ? std::max(hi, v.x) : v.x;
        any = true;
    }
    s.waterline = any ? hi - lo : 0.0;
    return s;
}

void floatRigidBodies(std::span<RigidBody> bodies, std::span<const Water> waters, Vec2 gravity, double dt) {
    const double g = gravity.length();
    if (!(g > 0.0)) return;
    const Vec2 up = gravity * (-1.0 / g);
    for (RigidBody& b : bodies) {
        if (b.motion != Motion::dynamic || b.inverseMass == 0.0) continue;
        const double reach = boundingRadius(b);
        for (const Water& water : waters) {
            if (b.position.y - reach > water.max.y || b.position.y + reach < water.min.y ||
                b.position.x - reach > water.max.x || b.position.x + reach < water.min.x)
                continue;
            const Submerged s = submergedPart(b, water);
            if (s.area <= 0.0) continue;
            // Archimedes: the displaced water's weight, rho A |g|, against gravity at the centroid of
            // what is displaced: Delta v = J / m, Delta omega = (r x J) / I (lecture 3).
            const double impulse = water.density * s.area * g * dt;
            Vec2 dv = up * (impulse * b.inverseMass);
            double dw = b.inverseInertia * (s.centroid - b.position).cross(up * impulse);
            // As for a circle (field_pass.cpp): a body far lighter than its water bobs faster than the
            // step can follow, and kicked explicitly gains energy; past dt^2 kappa = 1 the rise is taken
            // implicitly, v1 = (v0 + (b - |g|) dt) / (1 + dt^2 kappa), kappa = |g| rho w / m. The
            // righting spin likewise, with the waterline's second moment: kappa_turn = |g| rho w^3 / 12 / I.
            const double stiffness = dt * dt * g * water.density * s.waterline * std::abs(up.y) * b.inverseMass;
            const double w3 = s.waterline * s.waterline * s.waterline;
            const double turnStiffness = dt * dt * g * water.density * w3 / 12.0 * b.inverseInertia;
            if (turnStiffness > 1.0) dw = (b.angularVelocity + dw) / (1.0 + turnStiffness) - b.angularVelocity;
            // Drag, exact for dv/dt = -k v: the rate a circle of the same area would feel.
            const double width = 2.0 * std::sqrt(s.whole / std::numbers::pi);
            const double k = width * water.drag * (s.area / s.whole) * b.inverseMass;
            const double slow = std::expm1(-k * dt);
            if (stiffness > 1.0) {
                // Less the body's own gravity, which the method adds after this kick.
                const double own = b.gravityScale * g;
                dv = implicitFloatKick(b.velocity, up, impulse * b.inverseMass - own * dt, stiffness, k, dt, own * dt);
            } else {
                // On the velocity it moves with, mean over the step: the kick's, less half a step of its
                // own gravity. Floating at rest that is 0, so the drag holds nothing up and the body
                // sinks to where rho A |g| = m g exactly (on the velocity the step ends with, -g dt / 2
                // there, it held a 0.6 x 0.3 m box of 0.8 the water's density 3.9 mm too deep).
                const Vec2 moving = b.velocity + dv - up * (0.5 * b.gravityScale * g * dt);
                dv += moving * slow;
            }
            b.velocity += dv;
            b.angularVelocity += dw + (b.angularVelocity + dw) * slow;
        }
    }
}

} // namespace rube
