// The hammer: a handle (a capsule) welded to a head (a box), on a revolute at the handle's end fixed
// in the world. It starts raised along its angle and swings down under gravity, at once or, latched
// (a motor at speed 0 holds it), when a switch, click or script releases it. A compound pendulum:
// from the handle's start angle theta0 its centre of mass, d from the pivot, falls
// h = d (sin theta0 + 1) to the bottom, where it turns at omega = sqrt(2 M g h / I), I its moment of
// inertia about the pivot (handle and head, each m k^2 + m r^2 by the parallel-axis theorem).
#include "part_common.hpp"

#include "script_file.hpp"

#include <cmath>

namespace rube::game::parts {
namespace {

constexpr double kHandleRadius = 0.04; // m: half the handle's thickness (its capsule's radius)
constexpr double kHandleMass = 0.3;    // kg
constexpr Vec2 kHeadHalf{0.12, 0.22};  // m: half the head along the handle and across it
constexpr double kLatch = 1e4;         // N m: the latch's hold (the pivot's motor at speed 0)
constexpr double kPinRadius = 0.06;    // m: the pivot's pin as drawn
constexpr double kWeldHertz = 3000.0;  // the weld's stiffness as a spring's frequency (see bodies())

struct HammerParams {
    double length = 1.0; // m from the pivot to the head's centre
    double mass = 2.0;   // the head's, kg
    bool latched = true;
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             {"position", "required", "[x, y] m: the pivot at the handle's end"},
                             {"angle", "0", "the handle's direction from the pivot at the start, degrees"},
                             {"length", "1", "from the pivot to the head's centre, m"},
                             {"mass", "2", "the head's, kg"},
                             {"latched", "true", "held raised until a switch, click or script releases it"}};

class HammerKind final : public PartKind {
public:
    std::string_view name() const override { return "hammer"; }
    int order() const override { return 72; }
    std::string_view summary() const override {
        return "a head welded on a handle that swings down about a pivot at its end, when released (latched) or at "
               "once";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; }
    bool plays(PartRole role) const override { return role == PartRole::toggle || role == PartRole::triggered; }
    ItemDesc make(Vec2 position) const override { return made(position, HammerParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        HammerParams& p = item.params.as<HammerParams>();
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto l = table.number("length", NumberRange{2.0 * kHeadHalf.x, 10.0})) p.length = *l;
        if (const auto m = table.number("mass", NumberRange{0.0, 1e4, true})) p.mass = *m;
        if (const auto l = table.boolean("latched")) p.latched = *l;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const HammerParams& p = item.params.as<HammerParams>();
        const Vec2 u = Vec2::fromAngle(item.angle);
        ItemBodies bodies;
        // The handle, from the pivot to the head's centre (its caps round both ends).
        RigidBodyDef handle;
        handle.shape = BodyShape::capsule;
        handle.position = item.position + u * (0.5 * p.length);
        handle.angle = item.angle;
        handle.halfExtents = {0.5 * p.length, kHandleRadius};
        handle.mass = kHandleMass;
        handle.material = bouncy(0.2);
        bodies.rigidBodies.push_back(handle);
        RigidBodyDef head;
        head.position = item.position + u * p.length;
        head.angle = item.angle;
        head.halfExtents = kHeadHalf;
        head.mass = p.mass;
        head.material = bouncy(0.2);
        bodies.rigidBodies.push_back(head);
        // Joint 0, the pivot at the handle's end, latched by its motor if asked.
        ItemJoint pivot;
        pivot.def.kind = JointKind::revolute;
        pivot.def.localAnchorA = item.position; // the world's frame
        pivot.def.localAnchorB = {-0.5 * p.length, 0.0};
        pivot.def.referenceAngle = item.angle;
        if (p.latched) pivot.def.motor = {0.0, kLatch};
        pivot.b = {ItemJointEnd::To::body, 0, {}};
        bodies.joints.push_back(pivot);
        // Joint 1, the head welded on at the handle's other end.
        ItemJoint weld;
        weld.def.kind = JointKind::weld;
        weld.def.localAnchorA = {0.5 * p.length, 0.0};
        weld.def.localAnchorB = {};
        weld.def.referenceAngle = 0.0;
        // Stiffer than the joints' own softness (120 Hz), under which a blow on a ball moved the head
        // 1 to 4 mm off the handle's end (tests/parts/hammer_test.cpp, measured); at 3000 Hz, under 0.8 mm.
        weld.def.hertz = kWeldHertz;
        weld.a = {ItemJointEnd::To::body, 0, {}};
        weld.b = {ItemJointEnd::To::body, 1, {}};
        bodies.joints.push_back(weld);
        return bodies;
    }
    /// Picked on the pivot's pin or the handle as it starts, `tolerance` around them (the head is a
    /// body of its own, which a click on it would not find first).
    bool picked(const ItemDesc& item, Vec2 at, Vec2 cursor, double tolerance) const override {
        (void)at; // the editor passes the pivot, a run the handle's middle: the item says both
        const HammerParams& p = item.params.as<HammerParams>();
        const Vec2 x = Vec2::fromAngle(item.angle), d = cursor - item.position;
        const double along = d.dot(x);
        return along >= -kPinRadius - tolerance && along <= p.length + kHeadHalf.x + tolerance &&
               std::abs(d.dot(x.perpendicular())) <=
                   (along > p.length - kHeadHalf.x ? kHeadHalf.y : kPinRadius) + tolerance;
    }
    double speedGiven(const ItemDesc& item, double lightest, double g, double seconds) const override {
        (void)lightest, (void)seconds;
        // The head's fastest: falling the handle's length twice from straight up, v = sqrt(2 g 2 L);
        // a ball at rest struck by it leaves at up to twice that.
        return 2.0 * std::sqrt(4.0 * std::abs(g) * item.params.as<HammerParams>().length);
    }
    // Releases the latch (once: a released hammer swings free).
    void trigger(LevelRun& run, int item) const override { releaseLatch(run, item); }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    // The handle and head are drawn with the bodies; here the bracket the pivot hangs on and its pin,
    // lit while latched.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const bool latched = firstMotorOn(d);
        d.list.box(pt(item.position), {0.1f, 0.1f}, 0.0f, style("ground", "ground_outline"));
        d.list.circle(pt(item.position), static_cast<float>(kPinRadius),
                      style(latched ? "highlight" : "ground", "ground_outline"));
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        render::Style look = style("box", "box_outline");
        if (!available) look.fill = look.fill.withAlpha(0x60);
        const float r = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        list.capsule({c.x - 0.8f * r, c.y - 0.5f * r}, {c.x + 0.5f * r, c.y + 0.4f * r}, 0.08f * r, look);
        list.box({c.x + 0.5f * r, c.y + 0.4f * r}, {0.2f * r, 0.4f * r}, 0.6f, look);
    }
};

} // namespace
RUBE_PART(hammer, HammerKind)
} // namespace rube::game::parts
