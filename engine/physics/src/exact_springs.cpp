// The exact method's springs: the closed form of a circle on a spring to a fixed point, and when it
// exists (see exact_springs.hpp).
#include "exact_springs.hpp"

#include <cmath>

namespace rube {

namespace {

/// How far off the spring's line a velocity or gravity may point, relative to its size, and still
/// count as along it: round-off of a line that is not axis-aligned, not a real sideways motion.
constexpr double kLineTolerance = 1e-9;

const char* kindName(JointKind kind) {
    switch (kind) {
    case JointKind::revolute: return "revolute";
    case JointKind::prismatic: return "prismatic";
    case JointKind::weld: return "weld";
    case JointKind::spring: return "spring";
    case JointKind::pulley: return "pulley";
    case JointKind::gear: return "gear";
    }
    return "joint";
}

/// The circle end of a spring to the world: its slot, its anchor on the circle, and the fixed point.
struct SpringEnds {
    int circle = -1;
    Vec2 localAnchor;
    Vec2 fixedPoint;
};

SpringEnds endsOf(const Joint& j) {
    const bool aIsWorld = j.def.a.isWorld();
    return aIsWorld ? SpringEnds{j.circleB, j.def.localAnchorB, j.def.localAnchorA}
                    : SpringEnds{j.circleA, j.def.localAnchorA, j.def.localAnchorB};
}

/// Along the line through the origin with direction n (unit): |x cross n| <= tolerance |x|.
bool alongLine(Vec2 x, Vec2 n) { return std::abs(x.cross(n)) <= kLineTolerance * x.length(); }

} // namespace

int springCircle(const Joint& j) { return endsOf(j).circle; }

SpringPath springPathOf(const Joint& j, const Circle& c, Vec2 gravity) {
    const SpringEnds ends = endsOf(j);
    const JointDef& d = j.def;
    SpringPath path;
    path.omega = std::sqrt(d.stiffness * c.inverseMass);        // omega^2 = k / m
    path.zeta = d.damping * c.inverseMass / (2.0 * path.omega); // c / (2 sqrt(k m))
    const Vec2 along = c.position - ends.fixedPoint;            // d; n = d / |d| when L0 > 0
    const Vec2 rest = d.restLength > 0.0 ? along.normalized() * d.restLength : Vec2{};
    path.equilibrium = ends.fixedPoint + rest + gravity * (1.0 / (path.omega * path.omega)); // anchor + L0 n + m g / k
    return path;
}

void springMove(const SpringPath& path, Vec2& position, Vec2& velocity, double t) {
    const double w = path.omega, zeta = path.zeta, a = zeta * w;
    const Vec2 y0 = position - path.equilibrium, u0 = velocity;
    const double decay = std::exp(-a * t);
    // y = decay (y0 P + (u0 + a y0) Q),  u = decay (u0 P - (w^2 y0 + a u0) Q), with P and Q the
    // cos and sin / wd (under-damped), 1 and t (critical), cosh and sinh / s (over-damped).
    double p = 1.0, q = t;
    if (zeta < 1.0) {
        const double wd = w * std::sqrt(1.0 - zeta * zeta);
        p = std::cos(wd * t);
        q = std::sin(wd * t) / wd;
    } else if (zeta > 1.0) {
        const double s = w * std::sqrt(zeta * zeta - 1.0);
        p = std::cosh(s * t);
        q = std::sinh(s * t) / s;
    }
    const Vec2 y = (y0 * p + (u0 + y0 * a) * q) * decay;
    const Vec2 u = (u0 * p - (y0 * (w * w) + u0 * a) * q) * decay;
    position = path.equilibrium + y;
    velocity = u;
}

double springSpeedBound(const SpringPath& path, Vec2 position, Vec2 velocity) {
    const Vec2 y0 = position - path.equilibrium;
    return std::sqrt(velocity.lengthSquared() + path.omega * path.omega * y0.lengthSquared());
}

std::string exactSpringRefusal(const Joint& j, std::span<const Circle> circles, Vec2 gravity, bool withBlocks) {
    const JointDef& d = j.def;
    if (d.kind != JointKind::spring)
        return std::string("the exact method follows only springs to fixed points, not a ") + kindName(d.kind) +
               " joint";
    if (j.bodyA >= 0 || j.bodyB >= 0)
        return "a spring on a box or capsule: the exact method follows springs on circles only";
    if (!d.a.isWorld() && !d.b.isWorld()) return "a spring between two bodies couples them: it has no closed form";
    const SpringEnds ends = endsOf(j);
    if (ends.circle < 0 || static_cast<std::size_t>(ends.circle) >= circles.size()) return {};
    const Circle& c = circles[static_cast<std::size_t>(ends.circle)];
    if (c.motion != Motion::dynamic || c.inverseMass <= 0.0) return {}; // an infinite mass: the spring moves nothing
    if (d.springSide != SpringSide::both) return "a one-sided spring is piecewise: it has no single closed form";
    if (!(d.stiffness > 0.0)) return "a spring of stiffness 0 is a damper alone: it has no closed form here";
    if (ends.localAnchor.x != 0.0 || ends.localAnchor.y != 0.0)
        return "a spring anchored off its circle's centre turns the circle: it has no closed form";
    if (c.gravityScale != 1.0) return "its circle's gravity scale is not 1";
    if (withBlocks) return "the world has boxes, whose searches assume parabolas: a spring's path is not one";
    if (d.restLength == 0.0 && d.damping == 0.0) return {}; // f = -k d: the 2-D isotropic oscillator
    // Otherwise only along the spring's line: the body on it, moving along it, gravity along it.
    const Vec2 along = c.position - ends.fixedPoint;
    const Vec2 n = along.length() > 0.0        ? along.normalized()
                   : c.velocity.length() > 0.0 ? c.velocity.normalized()
                                               : gravity.normalized();
    const char* why = d.restLength > 0.0 ? "a spring with a rest length" : "a damped spring";
    if (d.restLength > 0.0 && along.length() == 0.0)
        return std::string(why) + " has no direction with its circle on the fixed point";
    if (!alongLine(c.velocity, n) || !alongLine(gravity, n))
        return std::string(why) + " is linear only along its line, and its circle moves (or gravity pulls) off it";
    if (d.restLength > 0.0) {
        // s = d . n must keep its sign: |y| never exceeds sqrt(y0^2 + u0^2 / omega^2) (energy).
        const SpringPath path = springPathOf(j, c, gravity);
        const double sEq = (path.equilibrium - ends.fixedPoint).dot(n);
        const double reach = std::sqrt((along.dot(n) - sEq) * (along.dot(n) - sEq) +
                                       c.velocity.lengthSquared() / (path.omega * path.omega));
        if (!(sEq - reach > 0.0)) return "a spring with a rest length whose circle may pass through its fixed point";
    }
    return {};
}

void ExactSprings::build(const StepContext& ctx) {
    held_.clear();
    index_.assign(ctx.circles.size(), -1);
    const bool withBlocks = !ctx.bodies.empty();
    for (std::size_t k = 0; k < ctx.joints.size(); ++k) {
        const Joint& j = ctx.joints[k];
        const std::string why = exactSpringRefusal(j, ctx.circles, ctx.def.gravity, withBlocks);
        if (!why.empty()) throw SpringNotExact("method 'exact' cannot move joint " + std::to_string(k) + ": " + why);
        const int circle = endsOf(j).circle;
        if (circle < 0 || ctx.circles[static_cast<std::size_t>(circle)].motion != Motion::dynamic ||
            ctx.circles[static_cast<std::size_t>(circle)].inverseMass <= 0.0)
            continue;
        if (index_[static_cast<std::size_t>(circle)] >= 0)
            throw SpringNotExact("method 'exact' cannot move joint " + std::to_string(k) +
                                 ": a circle on two springs has no closed form here");
        index_[static_cast<std::size_t>(circle)] = static_cast<int>(held_.size());
        held_.push_back(Held{static_cast<int>(k), circle,
                             springPathOf(j, ctx.circles[static_cast<std::size_t>(circle)], ctx.def.gravity)});
    }
}

std::string ExactSprings::recheck(const StepContext& ctx, int i) const {
    const int k = i < static_cast<int>(index_.size()) ? index_[static_cast<std::size_t>(i)] : -1;
    if (k < 0) return {};
    const Held& held = held_[static_cast<std::size_t>(k)];
    return exactSpringRefusal(ctx.joints[static_cast<std::size_t>(held.joint)], ctx.circles, ctx.def.gravity,
                              !ctx.bodies.empty());
}

} // namespace rube
