// The motor: a wheel whose axle is a revolute motor. While powered it drives the disc towards its
// speed with at most its torque, so its angular acceleration is at most torque / I (I the disc's
// 1/2 m r^2 plus its paddles'). On from the start, or off until a switch, click or script powers it
// (a second trigger switches it off again).
#include "wheel_common.hpp"

#include "script_file.hpp"

namespace rube::game::parts {
namespace {

struct MotorParams {
    WheelParams wheel{0.4, 2.0, 0, kPaddleLength};
    double speed = 3.0;   // rad/s, counter-clockwise when positive
    double torque = 20.0; // the most the motor gives, N m
    bool on = true;       // powered from the start
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             {"position", "required", "[x, y] m: the axle"},
                             kWheelAngleKey,
                             {"radius", "0.4", "the disc's, m"},
                             kWheelMassKey,
                             kWheelPaddlesKey,
                             kWheelPaddleKey,
                             {"speed", "3", "the speed it drives the disc to, rad/s (counter-clockwise when positive)"},
                             {"torque", "20", "the most torque it gives, N m"},
                             {"on", "true", "powered from the start (a switch flips it)"}};

JointMotor motorOf(const MotorParams& p, bool on) { return on ? JointMotor{p.speed, p.torque} : JointMotor{}; }

class MotorKind final : public PartKind {
public:
    std::string_view name() const override { return "motor"; }
    int order() const override { return 60; }
    std::string_view summary() const override {
        return "a wheel on a driven axle: turns at its speed with at most its torque while powered";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; } // the paddles' direction
    bool plays(PartRole role) const override {
        return role == PartRole::toggle || role == PartRole::triggered || role == PartRole::wheel;
    }
    ItemDesc make(Vec2 position) const override { return made(position, MotorParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        MotorParams& p = item.params.as<MotorParams>();
        readWheel(table, item, p.wheel);
        if (const auto s = table.number("speed", NumberRange{-100.0, 100.0})) p.speed = *s;
        if (const auto t = table.number("torque", NumberRange{0.0, 1e4, true})) p.torque = *t;
        if (const auto on = table.boolean("on")) p.on = *on;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const MotorParams& p = item.params.as<MotorParams>();
        return wheelBodies(item, p.wheel, motorOf(p, p.on), 0.3);
    }
    double speedGiven(const ItemDesc& item, double lightest, double g, double seconds) const override {
        (void)lightest, (void)g, (void)seconds;
        // A paddle moving at u sends a ball at rest off at up to (1 + C) u <= 2 u (lecture 3).
        const MotorParams& p = item.params.as<MotorParams>();
        return 2.0 * tipSpeed(p.wheel, p.speed);
    }
    void trigger(LevelRun& run, int item) const override {
        const ItemState& state = run.states()[static_cast<std::size_t>(item)];
        if (state.joints.empty() || state.joints.front().isNull()) return;
        World& world = run.partWorld();
        const bool on = world.joint(state.joints.front()).def.motor.on();
        world.setJointMotor(state.joints.front(),
                            motorOf(run.items()[static_cast<std::size_t>(item)].params.as<MotorParams>(), !on));
    }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    void draw(const PartDrawing& d) const override {
        const bool on = firstMotorOn(d);
        drawWheel(d, style("box", "box_outline"), on ? "highlight" : "ground");
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        drawWheelIcon(centre, size, available, "highlight", list);
    }
};

} // namespace
RUBE_PART(motor, MotorKind)
} // namespace rube::game::parts
