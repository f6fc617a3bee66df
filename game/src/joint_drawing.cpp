// The joints in the picture (issue 21): springs as coils, pulleys as ropes over their wheels, belts
// as the two straight runs between their wheels, gear teeth turning with their wheels, pistons as a
// rail with a rod, and the pins of hinges and the marks of welds. The renderer knows nothing of
// physics: each joint becomes lines, polylines, circles and polygons of the draw list here.
#include "scene_view.hpp"

#include "rube/render/palette.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace rube::game {

namespace {

using render::Palette;
using render::Point;
using render::Style;

constexpr float kLineWidth = 2.0f;     // pixels: ropes, belts, coils (a rope's width)
constexpr float kPinRadius = 0.06f;    // m: a hinge's pin, as a pivot's
constexpr float kPulleyRadius = 0.12f; // m: the wheel a pulley's rope runs over
constexpr double kCoilWidth = 0.08;    // m: half the width of a spring's zigzag
constexpr int kCoils = 8;              // zigzags a spring is drawn with, whatever its length
constexpr double kToothPitch = 0.2;    // m of rim per tooth
constexpr double kToothDepth = 0.08;   // m the teeth stand out of the rim
constexpr float kRailRadius = 0.05f;   // m: a piston's cylinder

Point toPoint(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

Style fixedStyle(float width) {
    const Palette& p = Palette::greybox();
    return {p["ground"], p["ground_outline"], width};
}

/// The centre, angle and rim radius of a joint's end b (the wheel of a revolute).
struct Wheel {
    Vec2 centre;
    double angle = 0.0;
    double radius = 0.0;
};

Wheel wheelOf(const World& world, const JointEnd& end) {
    if (!end.circle.isNull()) {
        const Circle& c = world.circle(end.circle);
        return {c.position, c.angle, c.radius};
    }
    if (!end.body.isNull()) {
        const RigidBody& b = world.body(end.body);
        return {b.position, b.angle, std::max(b.halfExtents.x, b.halfExtents.y)};
    }
    return {};
}

void drawSpring(const World& world, const JointDef& d, render::DrawList& list) {
    const Vec2 a = world.worldPoint(d.a, d.localAnchorA), b = world.worldPoint(d.b, d.localAnchorB);
    const double length = a.distance(b);
    if (length <= 0.0) return;
    const Vec2 along = (b - a) * (1.0 / length), across = along.perpendicular();
    // Straight ends a tenth of its length each, the coils between: they bunch up as it shortens.
    std::vector<Point> points{toPoint(a), toPoint(a + along * (0.1 * length))};
    for (int k = 0; k < 2 * kCoils; ++k) {
        const double t = 0.1 + 0.8 * (k + 0.5) / (2 * kCoils);
        points.push_back(toPoint(a + along * (t * length) + across * (k % 2 == 0 ? kCoilWidth : -kCoilWidth)));
    }
    points.push_back(toPoint(a + along * (0.9 * length)));
    points.push_back(toPoint(b));
    list.polyline(points, kLineWidth, Palette::greybox()["rope"]);
}

void drawPulley(const World& world, const JointDef& d, render::DrawList& list) {
    const auto rope = Palette::greybox()["rope"];
    const Vec2 a = world.worldPoint(d.a, d.localAnchorA), b = world.worldPoint(d.b, d.localAnchorB);
    list.line(toPoint(d.groundA), toPoint(a), kLineWidth, rope);
    list.line(toPoint(d.groundB), toPoint(b), kLineWidth, rope);
    list.line(toPoint(d.groundA), toPoint(d.groundB), kLineWidth, rope);
    list.circle(toPoint(d.groundA), kPulleyRadius, fixedStyle(1.0f));
    list.circle(toPoint(d.groundB), kPulleyRadius, fixedStyle(1.0f));
}

void drawPiston(const World& world, const JointDef& d, render::DrawList& list) {
    const Vec2 a = world.worldPoint(d.a, d.localAnchorA), b = world.worldPoint(d.b, d.localAnchorB);
    const Vec2 axis = world.worldPoint(d.a, d.localAxisA.normalized()) - world.worldPoint(d.a, {});
    // The cylinder over the limits (or from the anchor to where b is), the rod from its end to b.
    const double slide = (b - a).dot(axis);
    const double lower = d.limits.on ? d.limits.lower : std::min(0.0, slide);
    const double upper = d.limits.on ? d.limits.upper : std::max(0.0, slide);
    list.capsule(toPoint(a + axis * lower), toPoint(a + axis * upper), kRailRadius, fixedStyle(1.0f));
    list.line(toPoint(a + axis * lower), toPoint(b), 2.0f * kLineWidth, Palette::greybox()["ground_outline"]);
}

/// Teeth round a wheel's rim, turning with it.
void drawTeeth(const Wheel& w, render::DrawList& list) {
    if (w.radius <= 0.0) return;
    const int teeth = std::clamp(static_cast<int>(std::lround(2.0 * std::numbers::pi * w.radius / kToothPitch)), 6, 72);
    const double step = 2.0 * std::numbers::pi / teeth;
    const Palette& p = Palette::greybox();
    const Style style{p["box"], p["box_outline"], 1.0f};
    for (int k = 0; k < teeth; ++k) {
        const double at = w.angle + k * step;
        const auto rim = [&](double angle, double r) {
            return toPoint(w.centre + Vec2{std::cos(angle), std::sin(angle)} * r);
        };
        const Point tooth[4] = {rim(at - 0.3 * step, w.radius - 0.01), rim(at - 0.15 * step, w.radius + kToothDepth),
                                rim(at + 0.15 * step, w.radius + kToothDepth), rim(at + 0.3 * step, w.radius - 0.01)};
        list.polygon(tooth, style);
    }
}

/// A belt's two straight runs: the outer tangents of the two rims (both wheels turn the same way).
void drawBelt(const Wheel& one, const Wheel& two, render::DrawList& list) {
    const Vec2 d = two.centre - one.centre;
    const double distance = d.length();
    if (distance <= std::abs(one.radius - two.radius)) return;
    const Vec2 u = d * (1.0 / distance);
    const double c = (one.radius - two.radius) / distance, s = std::sqrt(1.0 - c * c);
    for (const double side : {1.0, -1.0}) {
        const Vec2 n = u * c + u.perpendicular() * (side * s);
        list.line(toPoint(one.centre + n * one.radius), toPoint(two.centre + n * two.radius), kLineWidth,
                  Palette::greybox()["rope"]);
    }
}

void drawGear(const World& world, const JointDef& d, render::DrawList& list) {
    const JointDef& first = world.joint(d.jointA).def;
    const JointDef& second = world.joint(d.jointB).def;
    const Wheel one = wheelOf(world, first.b);
    if (second.kind != JointKind::revolute) {
        drawTeeth(one, list); // a pinion on its rack
        return;
    }
    const Wheel two = wheelOf(world, second.b);
    // Turning the same way (ratio < 0) is a belt's coupling; turning opposite ways, meshing teeth.
    if (d.ratio < 0.0) {
        drawBelt(one, two, list);
    } else {
        drawTeeth(one, list);
        drawTeeth(two, list);
    }
}

} // namespace

void drawJoints(const World& world, render::DrawList& list) {
    for (const Joint& joint : world.joints()) {
        const JointDef& d = joint.def;
        switch (d.kind) {
        case JointKind::spring: drawSpring(world, d, list); break;
        case JointKind::pulley: drawPulley(world, d, list); break;
        case JointKind::prismatic: drawPiston(world, d, list); break;
        case JointKind::gear: drawGear(world, d, list); break;
        case JointKind::revolute:
        case JointKind::weld: break; // their marks go on top (drawJointPins)
        }
    }
}

void drawJointPins(const World& world, render::DrawList& list) {
    const auto outline = Palette::greybox()["ground_outline"];
    for (const Joint& joint : world.joints()) {
        const JointDef& d = joint.def;
        const Vec2 at = world.worldPoint(d.b, d.localAnchorB);
        if (d.kind == JointKind::revolute) {
            list.circle(toPoint(at), kPinRadius, fixedStyle(1.0f));
        } else if (d.kind == JointKind::weld) {
            // A weld's mark: a small cross at the seam.
            const double r = kPinRadius;
            list.line(toPoint(at + Vec2{-r, -r}), toPoint(at + Vec2{r, r}), kLineWidth, outline);
            list.line(toPoint(at + Vec2{-r, r}), toPoint(at + Vec2{r, -r}), kLineWidth, outline);
        }
    }
}

} // namespace rube::game
