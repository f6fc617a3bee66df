// The boxing glove: a glove (a box) on a piston, a prismatic joint with a motor. At rest it is held
// back; a switch, click or script makes it punch out along its angle at its speed, with at most its
// force, to the end of its stroke (the joint's upper limit), and a second trigger pulls it back.
#include "part_common.hpp"

#include "script_file.hpp"

#include <cmath>

namespace rube::game::parts {
namespace {

constexpr double kGloveMass = 0.5;  // kg
constexpr double kGloveHalf = 0.15; // m: half the glove's size

struct GloveParams {
    double stroke = 0.8;  // m
    double speed = 4.0;   // m/s
    double force = 400.0; // N
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             {"position", "required", "[x, y] m: the glove's centre at rest"},
                             {"angle", "0", "the way it punches, degrees"},
                             {"stroke", "0.8", "how far it punches, m"},
                             {"speed", "4", "the piston's speed, m/s"},
                             {"force", "400", "the most the piston pushes with, N"}};

Vec2 axisOf(const ItemDesc& item) { return Vec2::fromAngle(item.angle); }

class GloveKind final : public PartKind {
public:
    std::string_view name() const override { return "glove"; }
    int order() const override { return 65; }
    std::string_view summary() const override {
        return "a boxing glove on a piston: punches out its stroke at its speed when switched, back when switched "
               "again";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; }
    bool plays(PartRole role) const override { return role == PartRole::toggle || role == PartRole::triggered; }
    ItemDesc make(Vec2 position) const override { return made(position, GloveParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        GloveParams& p = item.params.as<GloveParams>();
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto s = table.number("stroke", NumberRange{0.0, 10.0, true})) p.stroke = *s;
        if (const auto v = table.number("speed", NumberRange{0.0, 100.0, true})) p.speed = *v;
        if (const auto f = table.number("force", NumberRange{0.0, 1e5, true})) p.force = *f;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const GloveParams& p = item.params.as<GloveParams>();
        ItemBodies bodies;
        RigidBodyDef glove;
        glove.position = item.position;
        glove.angle = item.angle;
        glove.halfExtents = {kGloveHalf, kGloveHalf};
        glove.mass = kGloveMass;
        glove.material = bouncy(0.3);
        glove.gravityScale = 0.0; // the piston carries it
        bodies.rigidBodies.push_back(glove);
        // The piston: slide s = (p - position) . u from 0 (at rest) to the stroke; held at rest by its
        // motor at speed 0 until switched.
        ItemJoint piston;
        piston.def.kind = JointKind::prismatic;
        piston.def.localAnchorA = item.position;
        piston.def.localAxisA = axisOf(item);
        piston.def.referenceAngle = item.angle;
        piston.def.limits = {true, 0.0, p.stroke};
        piston.def.motor = {0.0, p.force};
        piston.b = {ItemJointEnd::To::body, 0, {}};
        bodies.joints.push_back(piston);
        return bodies;
    }
    bool picked(const ItemDesc& item, Vec2 at, Vec2 cursor, double tolerance) const override {
        (void)item;
        return std::abs(cursor.x - at.x) <= kGloveHalf + tolerance &&
               std::abs(cursor.y - at.y) <= kGloveHalf + tolerance;
    }
    double speedGiven(const ItemDesc& item, double lightest, double g, double seconds) const override {
        (void)lightest, (void)g, (void)seconds;
        return 2.0 * item.params.as<GloveParams>().speed; // a glove at u sends a ball at rest off at up to 2u
    }
    // Out if it is at rest or going back, back if it is going out.
    void trigger(LevelRun& run, int item) const override {
        const ItemState& state = run.states()[static_cast<std::size_t>(item)];
        if (state.joints.empty() || state.joints.front().isNull()) return;
        const GloveParams& p = run.items()[static_cast<std::size_t>(item)].params.as<GloveParams>();
        World& world = run.partWorld();
        const bool out = world.joint(state.joints.front()).def.motor.speed > 0.0;
        world.setJointMotor(state.joints.front(), {out ? -p.speed : p.speed, p.force});
    }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    // The glove is drawn with the bodies and the piston with the joints; here the housing at its back.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const Vec2 back = item.position - axisOf(item) * (kGloveHalf + 0.12);
        d.list.box(pt(back), {0.1f, 0.18f}, static_cast<float>(item.angle), style("ground", "ground_outline"));
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const float r = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        list.box({c.x - 0.75f * r, c.y}, {0.12f * r, 0.3f * r}, 0.0f, style("ground", "ground_outline"));
        list.line({c.x - 0.6f * r, c.y}, {c.x + 0.2f * r, c.y}, 3.0f, render::Palette::greybox()["ground_outline"]);
        list.box({c.x + 0.45f * r, c.y}, {0.3f * r, 0.3f * r}, 0.0f, style("box", "box_outline"), 0.1f * r);
    }
};

} // namespace
RUBE_PART(glove, GloveKind)
} // namespace rube::game::parts
