// The gate: a board (a box) on a hinge at one end, a revolute to the world whose angle limits let it
// swing only `opens` degrees from shut, one way: a hanging gate opening counter-clockwise lets a
// ball through from the left and stops one from the right against its limit. Latched, a motor at
// speed 0 holds it shut until a switch, click or script releases it (once).
#include "part_common.hpp"

#include "script_file.hpp"

#include <algorithm>
#include <cmath>

namespace rube::game::parts {
namespace {

constexpr double kHalfThickness = 0.08; // m: half the board's thickness
constexpr double kLatch = 1e4;          // N m: the latch's hold (the hinge's motor at speed 0)
constexpr double kPinRadius = 0.08;     // m: the hinge's pin as drawn

struct GateParams {
    double length = 1.2; // m
    double mass = 1.0;   // kg
    double opens = 90.0; // degrees from shut, counter-clockwise when positive
    bool latched = false;
};

constexpr PartKey kKeys[] = {
    kKindKey,
    kNameKey,
    {"position", "required", "[x, y] m: the hinge"},
    {"angle", "-90", "the board's direction from the hinge when shut, degrees (-90: hanging down)"},
    {"length", "1.2", "the board's, m"},
    {"mass", "1", "the board's, kg"},
    {"opens", "90", "how far it swings from shut, degrees, counter-clockwise when positive (one way only)"},
    {"latched", "false", "held shut until a switch, click or script releases it"}};

class GateKind final : public PartKind {
public:
    std::string_view name() const override { return "gate"; }
    int order() const override { return 71; }
    std::string_view summary() const override {
        return "a board on a hinge at one end that swings only one way, as far as it opens; latched, shut until "
               "switched";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; }
    bool plays(PartRole role) const override { return role == PartRole::toggle || role == PartRole::triggered; }
    ItemDesc make(Vec2 position) const override {
        ItemDesc item = made(position, GateParams{});
        item.angle = radians(-90.0);
        return item;
    }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        GateParams& p = item.params.as<GateParams>();
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto l = table.number("length", kSizeRange)) p.length = *l;
        if (const auto m = table.number("mass", NumberRange{0.0, 1e4, true})) p.mass = *m;
        if (const auto o = table.number("opens", NumberRange{-180.0, 180.0})) p.opens = *o;
        if (const auto l = table.boolean("latched")) p.latched = *l;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const GateParams& p = item.params.as<GateParams>();
        ItemBodies bodies;
        RigidBodyDef board;
        board.position = item.position + Vec2::fromAngle(item.angle) * (0.5 * p.length);
        board.angle = item.angle;
        board.halfExtents = {0.5 * p.length, kHalfThickness};
        board.mass = p.mass;
        board.material = bouncy(0.2);
        bodies.rigidBodies.push_back(board);
        // The hinge at the board's end; its angle is the board's turn from shut (reference angle),
        // limited to [0, opens] (or [opens, 0]).
        ItemJoint hinge;
        hinge.def.kind = JointKind::revolute;
        hinge.def.localAnchorA = item.position; // the world's frame
        hinge.def.localAnchorB = {-0.5 * p.length, 0.0};
        hinge.def.referenceAngle = item.angle;
        hinge.def.limits = {true, radians(std::min(0.0, p.opens)), radians(std::max(0.0, p.opens))};
        if (p.latched) hinge.def.motor = {0.0, kLatch};
        hinge.b = {ItemJointEnd::To::body, 0, {}};
        bodies.joints.push_back(hinge);
        return bodies;
    }
    /// Picked on the hinge's pin, or anywhere on the board as it is shut (as placed, before it
    /// swings), `tolerance` around them.
    bool picked(const ItemDesc& item, Vec2 at, Vec2 cursor, double tolerance) const override {
        (void)at; // the editor passes the hinge, a run the board's middle: the item says both
        const GateParams& p = item.params.as<GateParams>();
        const Vec2 x = Vec2::fromAngle(item.angle), d = cursor - (item.position + x * (0.5 * p.length));
        if (cursor.distance(item.position) <= kPinRadius + tolerance) return true;
        return std::abs(d.dot(x)) <= 0.5 * p.length + tolerance &&
               std::abs(d.dot(x.perpendicular())) <= kHalfThickness + tolerance;
    }
    // Releases the latch (once: a released gate stays free).
    void trigger(LevelRun& run, int item) const override { releaseLatch(run, item); }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    // The board is drawn with the bodies; here the hinge's post, lit while latched, and an arc
    // showing the way it opens and how far.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const GateParams& p = item.params.as<GateParams>();
        const bool latched = firstMotorOn(d);
        constexpr int kArc = 12;
        render::Point arc[kArc + 1];
        for (int k = 0; k <= kArc; ++k)
            arc[k] = pt(item.position + Vec2::fromAngle(item.angle + radians(p.opens) * k / kArc) * (0.35 * p.length));
        d.list.polyline(arc, 1.5f, render::Palette::greybox()["spoke"]);
        d.list.circle(pt(item.position), static_cast<float>(kPinRadius),
                      style(latched ? "highlight" : "ground", "ground_outline"));
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        render::Style board = style("box", "box_outline");
        if (!available) board.fill = board.fill.withAlpha(0x60);
        const float r = static_cast<float>(0.5 * size);
        const render::Point hinge{static_cast<float>(centre.x) - 0.3f * r, static_cast<float>(centre.y) + 0.7f * r};
        list.box({hinge.x + 0.25f * r, hinge.y - 0.7f * r}, {0.75f * r, 0.08f * r}, -1.2f, board);
        list.circle(hinge, 0.15f * r, style("ground", "ground_outline"));
    }
};

} // namespace
RUBE_PART(gate, GateKind)
} // namespace rube::game::parts
