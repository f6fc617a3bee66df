// The seesaw: a plank (a box) on a revolute pivot fixed in the world, with tilt limits if asked for.
// The lever law: loads m1 at l1 and m2 at l2 either side of the pivot tip it towards the larger
// moment m g l, with angular acceleration alpha = g (m1 l1 - m2 l2) / I about the pivot (the
// plank's own weight adds its moment when the pivot is off its middle); equal moments balance.
// A weight dropped on the long arm throws what rests on the short one up.
#include "part_common.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace rube::game::parts {
namespace {

constexpr double kHalfThickness = 0.06; // m: half the plank's thickness
constexpr double kPostHeight = 0.4;     // m: the drawn post from the pivot down

struct SeesawParams {
    double length = 3.0; // m
    double mass = 2.0;   // kg
    double pivot = 0.0;  // m along the plank from its middle to the pivot (negative: towards its left end)
    double limit = 25.0; // degrees either side of level; 0: none
};

constexpr PartKey kKeys[] = {
    kKindKey,
    kNameKey,
    {"position", "required", "[x, y] m: the pivot"},
    {"angle", "0", "the plank's tilt at the start, degrees (within the limit)"},
    {"length", "3", "the plank's, m"},
    {"mass", "2", "the plank's, kg"},
    {"pivot", "0", "where the pivot is along the plank from its middle, m (negative: towards its left end)"},
    {"limit", "25", "the most it tilts either side of level, degrees (0: no limit)"}};

/// The plank's centre: the pivot is `pivot` along the plank from it.
Vec2 plankCentre(const ItemDesc& item) {
    return item.position - Vec2::fromAngle(item.angle) * item.params.as<SeesawParams>().pivot;
}

class SeesawKind final : public PartKind {
public:
    std::string_view name() const override { return "seesaw"; }
    int order() const override { return 70; }
    std::string_view summary() const override {
        return "a plank on a fixed pivot: tips towards the larger moment m g l, throws up what rests on the short arm";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    ItemDesc make(Vec2 position) const override { return made(position, SeesawParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        SeesawParams& p = item.params.as<SeesawParams>();
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto l = table.number("length", kSizeRange)) p.length = *l;
        if (const auto m = table.number("mass", NumberRange{0.0, 1e4, true})) p.mass = *m;
        if (const auto d = table.number("pivot", NumberRange{-kMaxItemSize, kMaxItemSize})) p.pivot = *d;
        if (const auto t = table.number("limit", NumberRange{0.0, 90.0})) p.limit = *t;
        if (std::abs(p.pivot) > 0.5 * p.length)
            table.error(table.valuePlace("pivot"), "pivot must be on the plank (at most half its length, " +
                                                       formatNumber(0.5 * p.length) + " m, from its middle)");
        if (p.limit > 0.0 && std::abs(item.angle) > radians(p.limit))
            table.error(table.valuePlace("angle"),
                        "angle must be within the limit, " + formatNumber(p.limit) + " degrees either side");
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const SeesawParams& p = item.params.as<SeesawParams>();
        ItemBodies bodies;
        RigidBodyDef plank;
        plank.position = plankCentre(item);
        plank.angle = item.angle;
        plank.halfExtents = {0.5 * p.length, kHalfThickness};
        plank.mass = p.mass;
        plank.material = bouncy(0.2);
        bodies.rigidBodies.push_back(plank);
        // The pivot: fixed in the world at the item's position, `pivot` along the plank from its
        // middle; the limits are tilts from level (reference angle 0).
        ItemJoint pivot;
        pivot.def.kind = JointKind::revolute;
        pivot.def.localAnchorA = item.position; // the world's frame
        pivot.def.localAnchorB = {p.pivot, 0.0};
        pivot.def.referenceAngle = 0.0;
        if (p.limit > 0.0) pivot.def.limits = {true, -radians(p.limit), radians(p.limit)};
        pivot.b = {ItemJointEnd::To::body, 0, {}};
        bodies.joints.push_back(pivot);
        return bodies;
    }
    /// Picked anywhere on the plank as it lies at the start, `tolerance` around it.
    bool picked(const ItemDesc& item, Vec2 at, Vec2 cursor, double tolerance) const override {
        (void)at; // the editor passes the pivot, a run the plank's middle: the item says both
        const SeesawParams& p = item.params.as<SeesawParams>();
        const Vec2 x = Vec2::fromAngle(item.angle), d = cursor - plankCentre(item);
        return std::abs(d.dot(x)) <= 0.5 * p.length + tolerance &&
               std::abs(d.dot(x.perpendicular())) <= kHalfThickness + tolerance;
    }
    // The plank is drawn with the bodies; here the post under the pivot and the pin through it.
    void draw(const PartDrawing& d) const override {
        const Vec2 at = itemOf(d).position;
        const render::Point post[] = {pt(at), pt(at + Vec2{0.22, -kPostHeight}), pt(at + Vec2{-0.22, -kPostHeight})};
        d.list.polygon(post, style("ground", "ground_outline"));
        d.list.circle(pt(at), 0.05f, style("highlight", "box_outline"));
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        render::Style plank = style("box", "box_outline");
        if (!available) plank.fill = plank.fill.withAlpha(0x60);
        const float r = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        const render::Point post[] = {c, {c.x + 0.3f * r, c.y - 0.6f * r}, {c.x - 0.3f * r, c.y - 0.6f * r}};
        list.polygon(post, style("ground", "ground_outline"));
        list.box(c, {0.9f * r, 0.08f * r}, 0.25f, plank);
    }
};

} // namespace
RUBE_PART(seesaw, SeesawKind)
} // namespace rube::game::parts
