// The car: a wind-up toy car, a box body on two wheels joined to it by revolute joints whose motors
// (its spring) drive both wheels at omega = speed / r, with at most `torque` each. Rolling without
// slipping it runs at the rim speed v = omega r; it gets there at a = 2 tau / (r (M + m_w)) (two
// driven discs, I = 1/2 m_w r^2 each, M the whole car's mass) unless friction allows less: the floor
// pushes at most mu N, so a <= mu g on a level floor, and on a ramp of angle theta it climbs only
// while mu cos(theta) > sin(theta). After `run` seconds the spring has run down: its gearbox only
// drags the wheels (a small torque towards rest) and the car coasts to rest. It runs from the start,
// or (on = false) waits until a switch, click or script winds it up (once).
#include "part_common.hpp"

#include "script_file.hpp"

#include <cmath>
#include <limits>

namespace rube::game::parts {
namespace {

constexpr Vec2 kBodyHalf{0.3, 0.1};      // the body, 0.6 m by 0.2 m
constexpr double kWheelRadius = 0.15;    // m
constexpr double kWheelMass = 0.25;      // each, kg
constexpr double kAxleX = 0.2;           // each axle this far ahead of or behind the body's centre, m
constexpr double kAxleY = -0.09;         // just above the body's bottom edge: the wheels stand 0.24 m below its centre
constexpr double kBodyBounciness = 0.2;  // a pair's bounciness is the product of both (lecture 3)
constexpr double kWheelBounciness = 0.1; // rubber tyres barely bounce
// A run-down spring's gearbox: the wheels are dragged towards rest by this torque each, N m, so a car
// at v stops in about v (M + m_w) r / (2 x this) seconds (0.65 s from 1.5 m/s at the defaults).
constexpr double kGearDrag = 0.2;

// Which way it drives.
enum class Facing : std::uint8_t { right, left };
constexpr std::string_view kFacingNames[] = {"right", "left"};
constexpr std::string_view kForever[] = {"forever"};

struct CarParams {
    Facing facing = Facing::right;
    double speed = 1.5;    // m/s at the rim
    double torque = 0.5;   // the spring's most torque on each wheel, N m
    double run = 6.0;      // s the spring drives once started; infinity: forever
    double mass = 1.0;     // the body's, kg
    double friction = 1.0; // the tyres' Coulomb mu
    bool on = true;        // running from the start
};

constexpr PartKey kKeys[] = {
    kKindKey,
    kNameKey,
    {"position", "required",
     "[x, y] m: the body's centre; the wheels' bottoms are 0.24 m below it (5 cm grid: 1 cm above a floor)"},
    {"angle", "0", "tilt, degrees (to start it on a ramp)"},
    {"facing", "right", "right | left: the way it drives"},
    {"speed", "1.5", "its rim speed, m/s: the speed it drives at rolling without slipping"},
    {"torque", "0.5", "the spring's most torque on each wheel, N m"},
    {"run", "6", "seconds the spring drives once started, or \"forever\"; then it coasts to rest"},
    {"mass", "1", "the body's mass, kg (each wheel adds 0.25)"},
    {"friction", "1", "the tyres' Coulomb mu; a pair's mu is the product of both"},
    {"on", "true", "running from the start; false: a switch, click or toggle winds it up (once)"}};

// The wheels' motor while the spring drives: omega = v / r, clockwise (negative) to drive right.
JointMotor driving(const CarParams& p) {
    const double omega = (p.facing == Facing::right ? -1.0 : 1.0) * p.speed / kWheelRadius;
    return {omega, p.torque};
}

// When its spring started, if it has.
std::optional<double> startedAt(const CarParams& p, const ItemState& state) {
    return p.on ? std::optional<double>(0.0) : state.since;
}

void setMotors(LevelRun& run, int item, const JointMotor& motor) {
    for (const JointId joint : run.states()[static_cast<std::size_t>(item)].joints)
        if (!joint.isNull()) run.partWorld().setJointMotor(joint, motor);
}

// A wheel: its tyre, four spokes turning with it and a hub.
void drawCarWheel(Vec2 at, double angle, double r, render::DrawList& list) {
    list.circle(pt(at), static_cast<float>(r), style("ball", "ball_outline"));
    const render::Color spoke = render::Palette::greybox()["spoke"];
    for (int k = 0; k < 4; ++k)
        list.line(pt(at), pt(at + Vec2::fromAngle(angle + 0.5 * std::numbers::pi * k) * (0.85 * r)), 1.5f, spoke);
    list.circle(pt(at), static_cast<float>(0.2 * r), style("spoke", "spoke"));
}

// Over the body (drawn with the world's bodies): a cabin, and on its roof the winding key, turning
// (by world time, never the clock) while the spring drives.
void drawCabinAndKey(Vec2 centre, double angle, double keyAngle, bool driving, bool facesRight,
                     render::DrawList& list) {
    const Vec2 x = Vec2::fromAngle(angle), y = x.perpendicular();
    const double s = facesRight ? 1.0 : -1.0; // the cabin sits towards the back
    const Vec2 cabin = centre + x * (-0.06 * s) + y * (kBodyHalf.y + 0.07);
    list.box(pt(cabin), {0.15f, 0.07f}, static_cast<float>(angle), style("box", "box_outline"));
    const render::Color ink = render::Palette::greybox()[driving ? "highlight" : "spoke"];
    const Vec2 stem = cabin + y * 0.07, top = stem + y * 0.1;
    list.line(pt(stem), pt(top), 2.0f, ink);
    const Vec2 wing = Vec2::fromAngle(angle) * (0.09 * std::cos(keyAngle));
    list.line(pt(top - wing), pt(top + wing), 3.0f, ink);
}

class CarKind final : public PartKind {
public:
    std::string_view name() const override { return "car"; }
    int order() const override { return 74; }
    std::string_view summary() const override {
        return "a wind-up toy car: a 1 kg body on two 0.25 kg wheels, radius 0.15 m, driven at its rim speed";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool plays(PartRole role) const override {
        return role == PartRole::toggle || role == PartRole::triggered || role == PartRole::goalMover;
    }
    ItemDesc make(Vec2 position) const override { return made(position, CarParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        CarParams& p = item.params.as<CarParams>();
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto f = table.choice("facing", kFacingNames)) p.facing = static_cast<Facing>(*f);
        if (const auto v = table.number("speed", NumberRange{0.0, 20.0})) p.speed = *v;
        if (const auto t = table.number("torque", NumberRange{0.0, 1000.0, true})) p.torque = *t;
        // A number of seconds, or the word "forever" (a spring that never runs down).
        if (const toml::node* run = table.find("run"); run && run->is_string()) {
            if (table.choice("run", kForever)) p.run = std::numeric_limits<double>::infinity();
        } else if (const auto t = table.number("run", NumberRange{0.0, 1e4, true})) {
            p.run = *t;
        }
        if (const auto m = table.number("mass", NumberRange{0.0, 1000.0, true})) p.mass = *m;
        if (const auto mu = table.number("friction", NumberRange{0.0, 10.0})) p.friction = *mu;
        if (const auto on = table.boolean("on")) p.on = *on;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const CarParams& p = item.params.as<CarParams>();
        ItemBodies bodies;
        RigidBodyDef body;
        body.shape = BodyShape::box;
        body.position = item.position;
        body.angle = item.angle;
        body.halfExtents = kBodyHalf;
        body.mass = p.mass;
        body.material = bouncy(kBodyBounciness);
        body.material.friction = 0.3;
        bodies.rigidBodies.push_back(body);
        for (int k = 0; k < 2; ++k) {
            const Vec2 axle{k == 0 ? -kAxleX : kAxleX, kAxleY};
            CircleDef wheel;
            wheel.position = item.position + axle.rotated(item.angle);
            wheel.radius = kWheelRadius;
            wheel.mass = kWheelMass;
            wheel.material = bouncy(kWheelBounciness);
            wheel.material.friction = p.friction;
            bodies.circles.push_back(wheel);
            ItemJoint joint;
            joint.def.kind = JointKind::revolute;
            joint.def.localAnchorA = axle;          // the body's frame
            joint.def.referenceAngle = -item.angle; // the wheel starts at angle 0, the body at the item's
            joint.def.motor = p.on ? driving(p) : JointMotor{};
            joint.a = {ItemJointEnd::To::body, 0, {}};
            joint.b = {ItemJointEnd::To::circle, k, {}};
            bodies.joints.push_back(joint);
        }
        return bodies;
    }
    double speedGiven(const ItemDesc& item, double lightest, double g, double seconds) const override {
        (void)lightest, (void)g, (void)seconds;
        // Its body moves at most at the rim speed; what it strikes leaves at up to (1 + C) of that (lecture 3).
        return 2.0 * item.params.as<CarParams>().speed;
    }
    void afterStep(LevelRun& run, int item) const override {
        const CarParams& p = run.items()[static_cast<std::size_t>(item)].params.as<CarParams>();
        ItemState& state = run.partState(item);
        const auto start = startedAt(p, state);
        if (state.fired || !start || !timeReached(run.world(), *start + p.run)) return;
        state.fired = true;
        setMotors(run, item, {0.0, kGearDrag});
    }
    bool waits(const ItemDesc& item, const ItemState& state) const override {
        return !state.fired && startedAt(item.params.as<CarParams>(), state).has_value();
    }
    // Wound up by a switch, click or script: a car that waits starts its run now (once).
    void trigger(LevelRun& run, int item) const override {
        const CarParams& p = run.items()[static_cast<std::size_t>(item)].params.as<CarParams>();
        ItemState& state = run.partState(item);
        if (startedAt(p, state)) return;
        state.since = run.world().time();
        setMotors(run, item, driving(p));
    }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    std::string spent(const ItemDesc& item, const ItemState& state) const override {
        if (state.fired) return item.name + " has run down already";
        if (startedAt(item.params.as<CarParams>(), state)) return item.name + " is running already";
        return "";
    }
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const ItemState& state = stateOf(d);
        const CarParams& p = item.params.as<CarParams>();
        const World& world = d.run.world();
        for (const JointId joint : state.joints) {
            if (joint.isNull()) continue;
            const int slot = world.joint(joint).circleB;
            if (slot < 0) continue;
            const Circle& wheel = world.circles()[static_cast<std::size_t>(slot)];
            drawCarWheel(wheel.position, wheel.angle, wheel.radius, d.list);
        }
        if (state.body.isNull()) return;
        const RigidBody& b = world.body(state.body);
        const auto start = startedAt(p, state);
        const bool driving = start.has_value() && !state.fired;
        const double wound = driving ? 4.0 * (world.time() - *start) : 0.0;
        drawCabinAndKey(b.position, b.angle, wound, driving, p.facing == Facing::right, d.list);
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        // The car at rest scaled into the icon's square: 0.6 m wide in a box `size` across.
        const double k = 0.75 * size / (2.0 * kBodyHalf.x);
        render::Style look = style("box", "box_outline");
        if (!available) look.fill = look.fill.withAlpha(0x60);
        const Vec2 body = centre + Vec2{0.0, 0.05 * size};
        list.box(pt(body), {static_cast<float>(k * kBodyHalf.x), static_cast<float>(k * kBodyHalf.y)}, 0.0f, look);
        list.box(pt(body + Vec2{-0.06 * k, (kBodyHalf.y + 0.07) * k}),
                 {static_cast<float>(0.15 * k), static_cast<float>(0.07 * k)}, 0.0f, look);
        for (const double x : {-kAxleX, kAxleX}) drawCarWheel(body + Vec2{x, kAxleY} * k, 0.3, kWheelRadius * k, list);
    }
};

} // namespace
RUBE_PART(car, CarKind)
} // namespace rube::game::parts
