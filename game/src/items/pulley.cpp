// The pulley: a rope over a fixed wheel with a load on each end, a bucket that catches balls or a
// counterweight. The rope is the engine's pulley joint, |pA - gA| + |pB - gB| <= L (joint.hpp),
// with gA, gB the wheel's two sides: it only pulls, so a side resting on the floor stays there while
// the other hangs. As balls land in a bucket it outweighs the other side and sinks, lifting it at
// Atwood's a = g (m2 - m1) / (m1 + m2) (the wheel's own inertia left out: a light wheel). At its
// defaults the empty bucket and the counterweight weigh the same, so it stays as placed until
// something lands in the bucket.
#include "part_common.hpp"

#include <algorithm>
#include <cmath>

namespace rube::game::parts {
namespace {

constexpr double kWheelBounciness = 0.3;
constexpr double kLoadBounciness = 0.1;   // a bucket keeps what falls in
constexpr double kBucketWidth = 1.0;      // m, outside
constexpr double kBucketHeight = 0.5;     // its walls, m
constexpr double kWall = 0.05;            // a wall's and the floor's half thickness, m
constexpr double kWeightSide = 0.5;       // the counterweight's side, m
constexpr double kBucketFloorShare = 0.6; // of a bucket's mass, in its floor (the rest in its two walls)
// The smallest wheel: the loads hang a wheel's width apart, and two buckets need 0.1 m between them.
constexpr double kMinRadius = 0.5 * kBucketWidth + 0.05;

// What hangs on one end of the rope.
enum class Load : std::uint8_t { bucket, weight };
constexpr std::string_view kLoadNames[] = {"bucket", "weight"};

struct Side {
    Load load;
    double mass = 1.0; // kg: a weight's, or a bucket's own (empty)
    double drop = 2.0; // m: from the wheel's centre down to where the rope holds the load
};

struct PulleyParams {
    double radius = 0.6; // the wheel's, m
    Side left{Load::bucket, 1.0, 1.5};
    Side right{Load::weight, 1.0, 2.5};
};

constexpr PartKey kKeys[] = {
    kKindKey,
    kNameKey,
    {"position", "required", "[x, y] m: the wheel's axle"},
    {"radius", "0.6", "the wheel's, m (0.55 or more): the rope hangs from its two sides"},
    {"left", "bucket",
     "what hangs on the left: bucket (1 m wide, 0.5 m deep: catches balls) or weight (a 0.5 m block)"},
    {"left_mass", "1", "the left load's own mass, kg (a bucket's, empty)"},
    {"left_drop", "1.5", "how far below the axle the rope holds the left load (a bucket's rim), m"},
    {"right", "weight", "what hangs on the right: bucket or weight"},
    {"right_mass", "1", "the right load's own mass, kg"},
    {"right_drop", "2.5", "how far below the axle the rope holds the right load, m"}};

// Where the rope leaves the wheel on a side (-1 left, +1 right): the wheel's side, at its axle's height.
Vec2 groundOf(const ItemDesc& item, double side) {
    return item.position + Vec2{side * item.params.as<PulleyParams>().radius, 0.0};
}

// Adds one side's load, hanging from `hook` (the rope's end), to `bodies`; returns the index of the
// body the rope holds and, in `anchor`, where on that body (its own frame).
int addLoad(ItemBodies& bodies, const Side& side, Vec2 hook, Vec2& anchor) {
    const int first = static_cast<int>(bodies.rigidBodies.size());
    RigidBodyDef body;
    body.material = bouncy(kLoadBounciness);
    if (side.load == Load::weight) {
        body.position = hook - Vec2{0.0, 0.5 * kWeightSide};
        body.halfExtents = {0.5 * kWeightSide, 0.5 * kWeightSide};
        body.mass = side.mass;
        bodies.rigidBodies.push_back(body);
        anchor = {0.0, 0.5 * kWeightSide}; // its top's middle
        return first;
    }
    // A bucket: a floor and two walls welded to it; the rope holds its bail, over the middle of its
    // rim, above the bucket's centre of mass so it hangs upright.
    const Vec2 floor = hook - Vec2{0.0, kBucketHeight - kWall};
    body.position = floor;
    body.halfExtents = {0.5 * kBucketWidth, kWall};
    body.mass = kBucketFloorShare * side.mass;
    bodies.rigidBodies.push_back(body);
    anchor = {0.0, kBucketHeight - kWall};
    for (const double x : {-1.0, 1.0}) {
        const Vec2 offset{x * (0.5 * kBucketWidth - kWall), 0.5 * kBucketHeight};
        RigidBodyDef wall;
        wall.material = body.material;
        wall.position = floor + offset;
        wall.halfExtents = {kWall, 0.5 * kBucketHeight - kWall};
        wall.mass = 0.5 * (1.0 - kBucketFloorShare) * side.mass;
        bodies.rigidBodies.push_back(wall);
        ItemJoint weld;
        weld.def.kind = JointKind::weld;
        weld.def.localAnchorA = offset; // the wall's centre, in the floor's frame
        weld.a = {ItemJointEnd::To::body, first, {}};
        weld.b = {ItemJointEnd::To::body, static_cast<int>(bodies.rigidBodies.size()) - 1, {}};
        bodies.joints.push_back(weld);
    }
    return first;
}

void readSide(TableReader& table, const char* load, const char* mass, const char* drop, Side& side) {
    if (const auto k = table.choice(load, kLoadNames)) side.load = static_cast<Load>(*k);
    if (const auto m = table.number(mass, NumberRange{0.0, 1e4, true})) side.mass = *m;
    if (const auto d = table.number(drop, kSizeRange)) side.drop = *d;
}

class PulleyKind final : public PartKind {
public:
    std::string_view name() const override { return "pulley"; }
    int order() const override { return 80; }
    std::string_view summary() const override {
        return "a rope over a fixed wheel, a bucket or a counterweight on each end: the heavier side sinks";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    ItemDesc make(Vec2 position) const override { return made(position, PulleyParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        PulleyParams& p = item.params.as<PulleyParams>();
        if (const auto r = table.number("radius", NumberRange{kMinRadius, kMaxItemSize})) p.radius = *r;
        readSide(table, "left", "left_mass", "left_drop", p.left);
        readSide(table, "right", "right_mass", "right_drop", p.right);
    }
    // Circle 0: the wheel, fixed (a ball may roll over it). Then the left load's bodies, the right's;
    // the buckets' welds, and last the rope: a pulley joint of length left_drop + right_drop.
    ItemBodies bodies(const ItemDesc& item) const override {
        const PulleyParams& p = item.params.as<PulleyParams>();
        ItemBodies bodies;
        bodies.circles.push_back(roundPart(item, p.radius, kWheelBounciness));
        const Vec2 gA = groundOf(item, -1.0), gB = groundOf(item, 1.0);
        ItemJoint rope;
        rope.def.kind = JointKind::pulley;
        rope.def.groundA = gA;
        rope.def.groundB = gB;
        rope.def.length = p.left.drop + p.right.drop;
        rope.a = {
            ItemJointEnd::To::body, addLoad(bodies, p.left, gA - Vec2{0.0, p.left.drop}, rope.def.localAnchorA), {}};
        rope.b = {
            ItemJointEnd::To::body, addLoad(bodies, p.right, gB - Vec2{0.0, p.right.drop}, rope.def.localAnchorB), {}};
        bodies.joints.push_back(rope);
        return bodies;
    }
    // The wheel, which stays where it was placed, is what a click picks.
    bool picked(const ItemDesc& item, Vec2 at, Vec2 cursor, double tolerance) const override {
        (void)at;
        return cursor.distance(item.position) <= item.params.as<PulleyParams>().radius + tolerance;
    }
    // The ropes and loads are drawn with the world's bodies and joints; here the wheel, turning as
    // the rope runs over it: by (left length now - left_drop) / radius, counter-clockwise as the left sinks.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const PulleyParams& p = item.params.as<PulleyParams>();
        const ItemState& state = stateOf(d);
        double turned = 0.0;
        if (!state.joints.empty()) {
            // The rope's two runs (joint_drawing.cpp draws them too in a level; the parts' pictures
            // draw no joints), from the wheel's sides to the hooks.
            const World& world = d.run.world();
            const JointDef& rope = world.joint(state.joints.back()).def;
            const Vec2 hookA = world.worldPoint(rope.a, rope.localAnchorA);
            const Vec2 hookB = world.worldPoint(rope.b, rope.localAnchorB);
            const render::Color line = render::Palette::greybox()["rope"];
            d.list.line(pt(rope.groundA), pt(hookA), 2.0f, line);
            d.list.line(pt(rope.groundB), pt(hookB), 2.0f, line);
            turned = (hookA.distance(rope.groundA) - p.left.drop) / p.radius;
        }
        const float r = static_cast<float>(p.radius);
        d.list.circle(pt(item.position), r, style("box", "box_outline"));
        const render::Color spoke = render::Palette::greybox()["spoke"];
        for (int k = 0; k < 4; ++k) {
            const Vec2 out = Vec2::fromAngle(turned + 0.5 * std::numbers::pi * k) * (0.85 * p.radius);
            d.list.line(pt(item.position), pt(item.position + out), 2.0f, spoke);
        }
        const float h = std::min(0.08f, 0.3f * r);
        d.list.circle(pt(item.position), h, style("ground", "box_outline"));
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        render::Style look = style("box", "box_outline");
        if (!available) look.fill = look.fill.withAlpha(0x60);
        const float s = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        const render::Point top{c.x, c.y + 0.55f * s};
        const render::Color rope = render::Palette::greybox()["rope"];
        list.line({top.x - 0.3f * s, top.y}, {top.x - 0.3f * s, c.y - 0.3f * s}, 2.0f, rope);
        list.line({top.x + 0.3f * s, top.y}, {top.x + 0.3f * s, c.y - 0.5f * s}, 2.0f, rope);
        list.circle(top, 0.3f * s, look);
        // A bucket on the left, a block on the right.
        list.box({c.x - 0.3f * s, c.y - 0.5f * s}, {0.25f * s, 0.04f * s}, 0.0f, look);
        list.box({c.x - 0.53f * s, c.y - 0.4f * s}, {0.04f * s, 0.12f * s}, 0.0f, look);
        list.box({c.x - 0.07f * s, c.y - 0.4f * s}, {0.04f * s, 0.12f * s}, 0.0f, look);
        list.box({c.x + 0.3f * s, c.y - 0.68f * s}, {0.18f * s, 0.18f * s}, 0.0f, look);
    }
};

} // namespace
RUBE_PART(pulley, PulleyKind)
} // namespace rube::game::parts
