// The pendulum, a wrecking ball: a heavy round bob on a light rigid rod of length L, hung from a
// fixed pivot (one revolute from the world to the bob, its anchor L from the bob's centre). It
// starts held aside at its angle theta0 from straight down, let go when the run starts or, latched
// (the revolute's motor at speed 0), when a switch, click or script releases it, and swings down
// through the bottom of its arc to strike what stands there. Energy: the bob falls
// h = L (1 - cos theta0), so at the bottom (1/2) I omega^2 = m g h, with I = m (L^2 + r^2 / 2) about
// the pivot (a solid disc of radius r turning with its rod, parallel-axis theorem):
// v = omega L = sqrt(2 g L (1 - cos theta0)) x L / sqrt(L^2 + r^2 / 2), the point-mass law within
// 0.4 % for r <= L / 8. Small swings take T = 2 pi sqrt(I / (m g L)), the simple pendulum's
// 2 pi sqrt(L / g) by the same factor. Unlike the hammer (a handle welded to a box head, whose
// centre of mass and inertia are the handle's and head's together), the rod here is massless and
// the bob round, so the speed follows the bob's own fall.
#include "part_common.hpp"

#include "script_file.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rube::game::parts {
namespace {

constexpr double kLatch = 1e5;      // N m: the latch's hold, over m g L sin theta0 for 100 kg on a 10 m rod
constexpr double kBounciness = 0.3; // the bob's iron on a rebound
constexpr double kRodRadius = 0.03; // m: the rod as drawn (it is a joint, not a body: nothing meets it)
constexpr double kPinRadius = 0.07; // m: the pivot's pin as drawn
constexpr double kCatch = 0.18;     // m: how far the latch's catch reaches past the bob as drawn
constexpr double kMaxMass = 100.0;  // kg: the heaviest bob the latch holds on the longest rod
constexpr double kMaxLength = 10.0; // m

struct PendulumParams {
    double length = 2.0; // m from the pivot to the bob's centre
    double mass = 10.0;  // the bob's, kg
    double radius = 0.3; // the bob's, m
    // A placed pendulum has no switch to wait for (and `rube solve` clicks only a level's own parts):
    // it swings when the run starts, as a part held aside in the editor is let go.
    bool latched = false;
};

constexpr PartKey kKeys[] = {
    kKindKey,
    kNameKey,
    {"position", "required", "[x, y] m: the pivot the rod hangs from"},
    {"angle", "45", "the rod's start angle from straight down, degrees (positive: the bob held out to the right)"},
    {"length", "2", "the rod, from the pivot to the bob's centre, m"},
    {"mass", "10", "the bob's, kg"},
    {"radius", "0.3", "the bob's, m"},
    {"latched", "false", "true: held aside until a switch, click or script releases it; false: let go at the start"}};

// The bob's centre at the start: L from the pivot along the rod, theta0 from straight down.
Vec2 bobAt(const ItemDesc& item, double length) {
    return item.position + Vec2{std::sin(item.angle), -std::cos(item.angle)} * length;
}

class PendulumKind final : public PartKind {
public:
    std::string_view name() const override { return "pendulum"; }
    int order() const override { return 75; }
    std::string_view summary() const override {
        return "a wrecking ball: a 10 kg bob, radius 0.3 m, on a light rod from a pivot, held aside until released "
               "(latched) or as the run starts";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; }
    bool plays(PartRole role) const override { return role == PartRole::toggle || role == PartRole::triggered; }
    ItemDesc make(Vec2 position) const override {
        ItemDesc item = made(position, PendulumParams{});
        item.angle = radians(45.0);
        return item;
    }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        PendulumParams& p = item.params.as<PendulumParams>();
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto r = table.number("radius", NumberRange{0.0, 1.0, true})) p.radius = *r;
        // The rod reaches past the bob's edge, so the pivot is never inside the bob.
        if (const auto l = table.number("length", NumberRange{0.0, kMaxLength, true})) {
            if (*l <= p.radius)
                table.error(table.valuePlace("length"), "length " + scriptNumber(*l) +
                                                            " m must be longer than the bob's radius, " +
                                                            scriptNumber(p.radius) + " m");
            else p.length = *l;
        }
        if (const auto m = table.number("mass", NumberRange{0.0, kMaxMass, true})) p.mass = *m;
        if (const auto l = table.boolean("latched")) p.latched = *l;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const PendulumParams& p = item.params.as<PendulumParams>();
        ItemBodies bodies;
        CircleDef bob;
        bob.position = bobAt(item, p.length);
        bob.radius = p.radius;
        bob.mass = p.mass;
        bob.material = bouncy(kBounciness);
        bodies.circles.push_back(bob);
        // Joint 0, the rod: a revolute from the pivot (the world's frame) to the point L above the
        // bob's centre in the bob's frame (the bob starts unturned), latched by its motor if asked.
        ItemJoint rod;
        rod.def.kind = JointKind::revolute;
        rod.def.localAnchorA = item.position;
        rod.def.localAnchorB = item.position - bob.position;
        rod.def.referenceAngle = 0.0;
        if (p.latched) rod.def.motor = {0.0, kLatch};
        rod.b = {ItemJointEnd::To::circle, 0, {}};
        bodies.joints.push_back(rod);
        return bodies;
    }
    Aabb extent(const ItemDesc& item) const override {
        // The bob and the pivot's pin, which may stand above the bob.
        const PendulumParams& p = item.params.as<PendulumParams>();
        const Vec2 bob = bobAt(item, p.length);
        return Aabb{Vec2{std::min(bob.x - p.radius, item.position.x - kPinRadius),
                         std::min(bob.y - p.radius, item.position.y - kPinRadius)},
                    Vec2{std::max(bob.x + p.radius, item.position.x + kPinRadius),
                         std::max(bob.y + p.radius, item.position.y + kPinRadius)}};
    }
    /// Picked on the bob where it is now (`at`) or on the pivot's pin, `tolerance` around them.
    bool picked(const ItemDesc& item, Vec2 at, Vec2 cursor, double tolerance) const override {
        const PendulumParams& p = item.params.as<PendulumParams>();
        return cursor.distance(at) <= p.radius + tolerance || cursor.distance(item.position) <= kPinRadius + tolerance;
    }
    double speedGiven(const ItemDesc& item, double lightest, double g, double seconds) const override {
        (void)lightest, (void)seconds;
        // The bob's fastest: falling 2 L from straight up, v = sqrt(2 g 2 L); a ball at rest struck by
        // it leaves at up to twice that.
        return 2.0 * std::sqrt(4.0 * std::abs(g) * item.params.as<PendulumParams>().length);
    }
    // Releases the latch (once: a released pendulum swings free).
    void trigger(LevelRun& run, int item) const override { releaseLatch(run, item); }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    // The bracket the rod hangs from, the rod, the bob, and while latched the catch that holds it.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const ItemState& state = stateOf(d);
        if (state.circle.isNull()) return;
        const Circle& bob = d.run.world().circle(state.circle);
        const bool latched = firstMotorOn(d);
        d.list.box(pt(item.position + Vec2{0.0, 0.12}), {0.22f, 0.06f}, 0.0f, style("ground", "ground_outline"));
        d.list.capsule(pt(item.position), pt(bob.position), static_cast<float>(kRodRadius),
                       style("box", "box_outline"));
        d.list.circleWithSpoke(pt(bob.position), static_cast<float>(bob.radius),
                               static_cast<float>(bob.angle - std::numbers::pi / 2.0),
                               style("heavy_ball", "ball_outline"));
        d.list.circle(pt(item.position), static_cast<float>(kPinRadius),
                      style(latched ? "highlight" : "ground", "ground_outline"));
        if (latched) {
            // The catch: a hook from the bob's far side, the way it would swing on up, to a post.
            const Vec2 along = (bob.position - item.position).normalized();
            const Vec2 out = item.angle >= 0.0 ? along.perpendicular() : -along.perpendicular();
            const Vec2 from = bob.position + out * bob.radius;
            const Vec2 to = from + out * kCatch;
            d.list.capsule(pt(from), pt(to), 0.04f, style("highlight", "ground_outline"));
            d.list.box(pt(to), {0.06f, 0.06f}, 0.0f, style("ground", "ground_outline"));
        }
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        render::Style rod = style("box", "box_outline");
        render::Style bob = style("heavy_ball", "ball_outline");
        if (!available) rod.fill = rod.fill.withAlpha(0x60), bob.fill = bob.fill.withAlpha(0x60);
        const float r = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        const render::Point pivot{c.x - 0.2f * r, c.y + 0.8f * r}, end{c.x + 0.35f * r, c.y - 0.3f * r};
        list.capsule(pivot, end, 0.05f * r, rod);
        list.circle(end, 0.45f * r, bob);
        list.circle(pivot, 0.1f * r, style("ground", "ground_outline"));
    }
};

} // namespace
RUBE_PART(pendulum, PendulumKind)
} // namespace rube::game::parts
