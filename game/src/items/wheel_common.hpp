#pragma once
/// What the wheels share (wheel, motor, and the kinds that drive or are driven by them): a disc on
/// an axle fixed in the world at the item's position, with paddles welded to it if asked for.
/// Joint 0 of every wheel is its axle, the joint a belt or a gear names. Internal to game/src/items.

#include "part_common.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

namespace rube::game::parts {

/// Paddles stand out of the rim by this much by default, m.
inline constexpr double kPaddleLength = 0.5;
/// A paddle's half thickness: a capsule's radius, m.
inline constexpr double kPaddleRadius = 0.06;
/// A paddle's mass, kg.
inline constexpr double kPaddleMass = 0.2;
/// A paddle starts this far out from the axle, as a fraction of the disc's radius (inside the disc),
/// unless its neighbours would overlap there (wheelBodies).
inline constexpr double kPaddleRoot = 0.3;

/// A wheel's parameters.
struct WheelParams {
    double radius = 0.4;                 ///< the disc's, m
    double mass = 2.0;                   ///< the disc's, kg
    int paddles = 0;                     ///< paddles round the rim, evenly spaced; the first along the item's angle
    double paddleLength = kPaddleLength; ///< how far each stands out of the rim, m
};

/// The keys every wheel has after kind, name and position, in this order.
inline constexpr PartKey kWheelAngleKey{"angle", "0", "the first paddle's direction, degrees"};
inline constexpr PartKey kWheelMassKey{"mass", "2", "the disc's mass, kg"};
inline constexpr PartKey kWheelPaddlesKey{"paddles", "0", "paddles round the rim (0 to 8), welded to the disc"};
inline constexpr PartKey kWheelPaddleKey{"paddle", "0.5", "how far each paddle stands out of the rim, m"};

/// Reads the wheel's own keys (radius, mass, angle, paddles, paddle) into `p` and the item.
inline void readWheel(TableReader& table, ItemDesc& item, WheelParams& p) {
    if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
    if (const auto r = table.number("radius", kSizeRange)) p.radius = *r;
    if (const auto m = table.number("mass", NumberRange{0.0, 1e4, true})) p.mass = *m;
    if (const auto n = table.integer("paddles", 0, 8)) p.paddles = static_cast<int>(*n);
    if (const auto l = table.number("paddle", kSizeRange)) p.paddleLength = *l;
}

/// The disc (circle 0), its axle to the world (joint 0, with `motor`), and its paddles (rigid
/// bodies 0..n-1), each welded to the disc (joints 1..n).
inline ItemBodies wheelBodies(const ItemDesc& item, const WheelParams& p, JointMotor motor, double bounciness) {
    ItemBodies bodies;
    CircleDef disc;
    disc.position = item.position;
    disc.radius = p.radius;
    disc.mass = p.mass;
    disc.material = bouncy(bounciness);
    bodies.circles.push_back(disc);
    ItemJoint axle;
    axle.def.kind = JointKind::revolute;
    axle.def.localAnchorA = item.position; // the world's frame
    axle.def.motor = motor;
    axle.b = {ItemJointEnd::To::circle, 0, {}};
    bodies.joints.push_back(axle);
    // Each paddle: a capsule from inside the disc to paddleLength past its rim, along its angle.
    // Each paddle is welded to the disc, not to its neighbours, so neighbours that overlapped at the
    // root would collide: three or more start where neighbours' capsules clear each other,
    // 2 root sin(pi / n) > 2 kPaddleRadius (and never past the middle of the paddle).
    const double tip = p.radius + p.paddleLength;
    const double clear = p.paddles > 2 ? 1.01 * kPaddleRadius / std::sin(std::numbers::pi / p.paddles) : 0.0;
    const double root = std::min(std::max(kPaddleRoot * p.radius, clear), 0.5 * tip);
    for (int k = 0; k < p.paddles; ++k) {
        const double angle = item.angle + 2.0 * std::numbers::pi * k / p.paddles;
        const double middle = 0.5 * (root + tip);
        RigidBodyDef paddle;
        paddle.shape = BodyShape::capsule;
        paddle.position = item.position + Vec2::fromAngle(angle) * middle;
        paddle.angle = angle;
        paddle.halfExtents = {0.5 * (tip - root), kPaddleRadius};
        paddle.mass = kPaddleMass;
        paddle.material = bouncy(bounciness);
        bodies.rigidBodies.push_back(paddle);
        // Welded at the axle: the disc's centre, which is -middle along the paddle's own x axis.
        ItemJoint weld;
        weld.def.kind = JointKind::weld;
        weld.def.localAnchorA = {};
        weld.def.localAnchorB = {-middle, 0.0};
        weld.def.referenceAngle = angle; // the disc starts at angle 0
        weld.a = {ItemJointEnd::To::circle, 0, {}};
        weld.b = {ItemJointEnd::To::body, k, {}};
        bodies.joints.push_back(weld);
    }
    return bodies;
}

/// The fastest any point of the wheel moves turning at `omega`: its paddles' tips, or its rim, m/s.
inline double tipSpeed(const WheelParams& p, double omega) {
    return std::abs(omega) * (p.radius + (p.paddles > 0 ? p.paddleLength : 0.0));
}

/// Draws the disc as it turns: its rim, three spokes and, over the axle, a hub of `hub`'s colour.
inline void drawWheel(const PartDrawing& d, const render::Style& look, const char* hub) {
    const Circle& c = d.run.world().circle(stateOf(d).circle);
    const float r = static_cast<float>(c.radius);
    d.list.circle(pt(c.position), r, look);
    const render::Color spoke = render::Palette::greybox()["spoke"];
    for (int k = 0; k < 3; ++k) {
        const Vec2 out = Vec2::fromAngle(c.angle + 2.0 * std::numbers::pi * k / 3.0) * (0.85 * c.radius);
        d.list.line(pt(c.position), pt(c.position + out), 2.0f, spoke);
    }
    const float h = std::min(0.12f, 0.35f * r);
    d.list.box(pt(c.position), {h, h}, static_cast<float>(c.angle), style(hub, "box_outline"));
}

/// A wheel's inventory icon: a disc with spokes and a paddle.
inline void drawWheelIcon(Vec2 centre, double size, bool available, const char* hub, render::DrawList& list) {
    render::Style look = style("box", "box_outline");
    if (!available) look.fill = look.fill.withAlpha(0x60);
    const float r = 0.5f * static_cast<float>(0.5 * size);
    const render::Point c = pt(centre);
    list.capsule(c, {c.x + 1.8f * r, c.y}, 0.15f * r, look);
    list.circle(c, r, look);
    for (int k = 0; k < 3; ++k) {
        const double a = 2.0 * std::numbers::pi * k / 3.0 + 0.5;
        list.line(c, pt(centre + Vec2::fromAngle(a) * (0.85 * r)), 1.5f, render::Palette::greybox()["spoke"]);
    }
    list.box(c, {0.3f * r, 0.3f * r}, 0.0f, style(hub, "box_outline"));
}

} // namespace rube::game::parts
