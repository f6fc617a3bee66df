// The flipper: a pinball bat (a capsule) on a hinge at one end, a revolute to the world whose limits
// let it swing `swing` degrees up from its rest, one way (a left flipper counter-clockwise, a right
// one clockwise). Its motor holds it down against the lower limit; triggered (a ball striking the bat,
// with trigger = "impact"; or a switch, plate, detector, click or script) the motor drives it up at
// `speed` with at most `torque` to the upper limit, where it stays until triggered again, which
// swings it back down. A ball lying on the bat r from the hinge is carried at omega r and leaves
// along the bat's normal at omega r when the bat stops at its limit (tests/parts/flipper_test.cpp
// holds it to that within 20 %). A ball struck in flight would leave at up to (1 + C) omega r for an
// unyielding bat (v' = u - C (v - u), lecture 3, with u = omega r held); the motor's torque limit and
// the bat pushing on after the blow make it 0.8 to 1.9 omega r as measured, so no test claims it.
#include "part_common.hpp"

#include "script_file.hpp"

#include <algorithm>
#include <cmath>

namespace rube::game::parts {
namespace {

constexpr double kBatRadius = 0.1;  // m: the capsule's radius, the bat's half thickness at its tip
constexpr double kHubRadius = 0.15; // m: the round hinge as drawn (the bat tapers from it to the tip)
constexpr double kBatMass = 1.5;    // kg
constexpr double kBounciness = 0.5; // the bat's rubber

// Which way it swings up.
enum class Side : std::uint8_t { left, right };
constexpr std::string_view kSideNames[] = {"left", "right"};
// What swings it up besides a switch, click or script.
enum class Trigger : std::uint8_t { impact, switchOnly };
constexpr std::string_view kTriggerNames[] = {"impact", "switch"};

struct FlipperParams {
    double length = 1.0;   // m from the hinge to the tip's centre
    double swing = 60.0;   // degrees from rest to the upper limit
    double speed = 12.0;   // rad/s, the motor's
    double torque = 600.0; // N m, the most the motor gives
    Side side = Side::left;
    Trigger trigger = Trigger::impact; // a placed flipper has no switch to wait for: a ball's blow sets it off
};

constexpr PartKey kKeys[] = {
    kKindKey,
    kNameKey,
    {"position", "required", "[x, y] m: the hinge"},
    {"angle", "-30", "the bat's direction from the hinge at rest, degrees (a right flipper's mirror: 210)"},
    {"side", "left", "left | right: a left flipper swings up counter-clockwise, a right one clockwise"},
    {"length", "1", "from the hinge to the tip, m"},
    {"swing", "60", "how far it swings up from rest, degrees"},
    {"speed", "12", "the motor's speed, rad/s (the tip moves at speed x length)"},
    {"torque", "600", "the most torque the motor gives, N m"},
    {"trigger", "impact", "impact | switch: impact also swings it up when a ball strikes the bat"}};

// +1 when it swings up counter-clockwise, -1 clockwise.
double upwards(const FlipperParams& p) { return p.side == Side::left ? 1.0 : -1.0; }
// The motor driving the bat up (or, `up` false, back down against its rest).
JointMotor motorOf(const FlipperParams& p, bool up) { return {(up ? 1.0 : -1.0) * upwards(p) * p.speed, p.torque}; }

// Whether its motor drives it up now (it rests, or is going down, otherwise).
bool drivenUp(const World& world, const ItemState& state, const FlipperParams& p) {
    return !state.joints.empty() && !state.joints.front().isNull() &&
           world.joint(state.joints.front()).def.motor.speed * upwards(p) > 0.0;
}

// The tapered bat's outline: round about the hinge (kHubRadius), round about the tip (kBatRadius),
// straight between, as drawn for the bat at `angle`.
void batOutline(Vec2 hinge, double angle, double length, double hub, double tip, std::vector<render::Point>& out) {
    constexpr int kArc = 10;
    const double pi = std::numbers::pi;
    const Vec2 end = hinge + Vec2::fromAngle(angle) * length;
    out.clear();
    for (int k = 0; k <= kArc; ++k) out.push_back(pt(end + Vec2::fromAngle(angle - 0.5 * pi + pi * k / kArc) * tip));
    for (int k = 0; k <= kArc; ++k) out.push_back(pt(hinge + Vec2::fromAngle(angle + 0.5 * pi + pi * k / kArc) * hub));
}

class FlipperKind final : public PartKind {
public:
    std::string_view name() const override { return "flipper"; }
    int order() const override { return 73; }
    std::string_view summary() const override {
        return "a 1.5 kg pinball bat, bounciness 0.5, on a hinge: swings up fast when struck or switched, strikes "
               "what lies on it";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; }
    bool plays(PartRole role) const override { return role == PartRole::toggle || role == PartRole::triggered; }
    ItemDesc make(Vec2 position) const override {
        ItemDesc item = made(position, FlipperParams{});
        item.angle = radians(-30.0);
        return item;
    }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        FlipperParams& p = item.params.as<FlipperParams>();
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto s = table.choice("side", kSideNames)) p.side = static_cast<Side>(*s);
        if (const auto l = table.number("length", NumberRange{0.0, 10.0, true})) p.length = *l;
        if (const auto s = table.number("swing", NumberRange{0.0, 180.0, true})) p.swing = *s;
        if (const auto v = table.number("speed", NumberRange{0.0, 60.0, true})) p.speed = *v;
        if (const auto t = table.number("torque", NumberRange{0.0, 1e5, true})) p.torque = *t;
        if (const auto t = table.choice("trigger", kTriggerNames)) p.trigger = static_cast<Trigger>(*t);
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const FlipperParams& p = item.params.as<FlipperParams>();
        ItemBodies bodies;
        RigidBodyDef bat;
        bat.shape = BodyShape::capsule;
        bat.position = item.position + Vec2::fromAngle(item.angle) * (0.5 * p.length);
        bat.angle = item.angle;
        bat.halfExtents = {0.5 * p.length, kBatRadius};
        bat.mass = kBatMass;
        bat.material = bouncy(kBounciness);
        bodies.rigidBodies.push_back(bat);
        // Joint 0, the hinge at the bat's end: its angle is the bat's turn from rest (the reference
        // angle), limited to [0, swing] up counter-clockwise or [-swing, 0] clockwise; the motor
        // presses it down on its rest, so gravity or a ball's weight never lifts it untriggered.
        ItemJoint hinge;
        hinge.def.kind = JointKind::revolute;
        hinge.def.localAnchorA = item.position; // the world's frame
        hinge.def.localAnchorB = {-0.5 * p.length, 0.0};
        hinge.def.referenceAngle = item.angle;
        const double swing = upwards(p) * radians(p.swing);
        hinge.def.limits = {true, std::min(0.0, swing), std::max(0.0, swing)};
        hinge.def.motor = motorOf(p, false);
        hinge.b = {ItemJointEnd::To::body, 0, {}};
        bodies.joints.push_back(hinge);
        return bodies;
    }
    /// Picked on the hinge or anywhere on the bat as it rests (as placed), `tolerance` around them.
    bool picked(const ItemDesc& item, Vec2 at, Vec2 cursor, double tolerance) const override {
        (void)at; // the editor passes the hinge, a run the bat's middle: the item says both
        const FlipperParams& p = item.params.as<FlipperParams>();
        const Vec2 x = Vec2::fromAngle(item.angle), d = cursor - item.position;
        const double along = std::clamp(d.dot(x), 0.0, p.length);
        return d.distance(x * along) <= std::max(kHubRadius, kBatRadius) + tolerance;
    }
    double speedGiven(const ItemDesc& item, double lightest, double g, double seconds) const override {
        (void)lightest, (void)g, (void)seconds;
        // The bat's fastest point, its tip's far side, moves at omega (L + r); a ball at rest struck
        // by it leaves at up to (1 + C) times that <= 2 omega (L + r) (lecture 3).
        const FlipperParams& p = item.params.as<FlipperParams>();
        return 2.0 * p.speed * (p.length + kBatRadius);
    }
    // With trigger = "impact": the first ball to strike the bat swings it up (once; after that only
    // switches, clicks and scripts move it).
    void hit(LevelRun& run, int item, Vec2 point, const std::string& by) const override {
        (void)point, (void)by;
        const ItemDesc& desc = run.items()[static_cast<std::size_t>(item)];
        if (desc.params.as<FlipperParams>().trigger != Trigger::impact ||
            run.states()[static_cast<std::size_t>(item)].fired)
            return;
        run.partState(item).fired = true;
        trigger(run, item);
    }
    // Up if it rests or is going down, down if it is up or going up.
    void trigger(LevelRun& run, int item) const override {
        ItemState& state = run.partState(item);
        if (state.joints.empty() || state.joints.front().isNull()) return;
        state.fired = true; // a switched flipper no longer waits for a ball's blow
        const FlipperParams& p = run.items()[static_cast<std::size_t>(item)].params.as<FlipperParams>();
        World& world = run.partWorld();
        world.setJointMotor(state.joints.front(), motorOf(p, !drivenUp(world, state, p)));
    }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    // The capsule is drawn with the bodies; over it the tapered bat as it stands now, its round hinge
    // (lit while driven up), and a thin arc where its tip swings.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const ItemState& state = stateOf(d);
        const FlipperParams& p = item.params.as<FlipperParams>();
        if (state.body.isNull()) return;
        const double angle = d.run.world().body(state.body).angle;
        const bool up = drivenUp(d.run.world(), state, p);
        constexpr int kArc = 12;
        render::Point arc[kArc + 1];
        for (int k = 0; k <= kArc; ++k)
            arc[k] = pt(item.position + Vec2::fromAngle(item.angle + upwards(p) * radians(p.swing) * k / kArc) *
                                            (p.length + kBatRadius));
        d.list.polyline(arc, 1.0f, render::Palette::greybox()["spoke"]);
        std::vector<render::Point> outline;
        batOutline(item.position, angle, p.length, kHubRadius, kBatRadius, outline);
        d.list.polygon(outline, style("box", "box_outline"));
        d.list.circle(pt(item.position), 0.5f * static_cast<float>(kHubRadius),
                      style(up ? "highlight" : "ground", "ground_outline"));
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        render::Style bat = style("box", "box_outline");
        if (!available) bat.fill = bat.fill.withAlpha(0x60);
        const double r = 0.5 * size;
        const Vec2 hinge = centre + Vec2{-0.6 * r, 0.2 * r};
        std::vector<render::Point> outline;
        batOutline(hinge, radians(-20.0), 1.2 * r, 0.25 * r, 0.14 * r, outline);
        list.polygon(outline, bat);
        list.circle(pt(hinge), static_cast<float>(0.12 * r), style("ground", "ground_outline"));
    }
};

} // namespace
RUBE_PART(flipper, FlipperKind)
} // namespace rube::game::parts
