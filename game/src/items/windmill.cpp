// The windmill: blades on a hub that turns on a fixed axle, turned by a fan's air. Each blade is a
// flat plate: the air pushes it along its normal n only, as the fan pushes a ball (F = 2r drag
// (u - v)), a length ds of blade taking the push a ball as wide would: dF = drag ((u - v) . n) n ds,
// with v the blade's own velocity there. About the axle, a blade along e at lever s (n = e turned
// a quarter) feels dtau = s drag (u . n - omega s) ds: the air speeds the windmill up until the
// blades in the air move with it. A windmill is a wheel (wheel_common.hpp), so a belt or a gear
// may name it and pass its turning on.
#include "wheel_common.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rube::game::parts {
namespace {

constexpr double kBounciness = 0.3;

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             {"position", "required", "[x, y] m: the axle"},
                             {"angle", "0", "the first blade's direction, degrees"},
                             {"radius", "0.25", "the hub's, m"},
                             {"mass", "1", "the hub's mass, kg"},
                             {"blades", "4", "blades round the hub (2 to 8), welded to it"},
                             {"blade", "1", "how far each blade stands out of the hub, m"}};

// Where a blade's line p(t) = a + t (b - a), t in [0, 1], is inside the air column: the t interval
// (empty when lo >= hi), by clipping against the column's four sides (Liang and Barsky).
std::pair<double, double> insideColumn(const Wind& wind, Vec2 a, Vec2 b) {
    const Vec2 across = wind.direction.perpendicular();
    // In the column's frame: along from the face, across from its middle.
    const Vec2 from{(a - wind.origin).dot(wind.direction), (a - wind.origin).dot(across)};
    const Vec2 delta{(b - a).dot(wind.direction), (b - a).dot(across)};
    double lo = 0.0, hi = 1.0;
    const auto clip = [&](double start, double rate, double min, double max) {
        // min <= start + t rate <= max
        if (rate == 0.0) {
            if (start < min || start > max) hi = lo;
            return;
        }
        double t0 = (min - start) / rate, t1 = (max - start) / rate;
        if (t0 > t1) std::swap(t0, t1);
        lo = std::max(lo, t0);
        hi = std::min(hi, t1);
    };
    clip(from.x, delta.x, 0.0, wind.length);
    clip(from.y, delta.y, -0.5 * wind.width, 0.5 * wind.width);
    return {lo, hi};
}

// The air's push on one blade over one step of `dt`, given as impulses at two points of the part
// of its line inside each column: the push per length, drag ((u - v) . n), is linear along the
// blade and its moment about the axle quadratic, which two-point Gauss-Legendre quadrature
// integrates exactly.
void blowOn(World& world, BodyId blade, Vec2 root, Vec2 tip, double dt) {
    // Its motion before any push: both nodes' pushes are of the same instant.
    const RigidBody body = world.body(blade);
    const double length = root.distance(tip);
    if (length <= 0.0) return;
    const Vec2 n = ((tip - root) * (1.0 / length)).perpendicular();
    const double gauss = 0.5 / std::sqrt(3.0); // the nodes: 1/2 -+ gauss of the interval
    for (const Wind& wind : world.fields().winds) {
        if (!wind.on) continue;
        const auto [lo, hi] = insideColumn(wind, root, tip);
        if (hi <= lo) continue;
        const double weight = 0.5 * (hi - lo) * length; // each node's share of the length inside
        for (const double node : {0.5 - gauss, 0.5 + gauss}) {
            const Vec2 p = root + (tip - root) * (lo + node * (hi - lo));
            const Vec2 v = body.velocity + (p - body.position).perpendicular() * body.angularVelocity;
            const double push = wind.drag * (wind.airVelocity() - v).dot(n) * weight;
            world.applyImpulseAt(blade, n * (push * dt), p);
        }
    }
}

class WindmillKind final : public PartKind {
public:
    std::string_view name() const override { return "windmill"; }
    int order() const override { return 81; }
    std::string_view summary() const override {
        return "blades on a hub on a fixed axle, turned by a fan's air; a belt or gear may name it";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; } // the blades' direction
    bool plays(PartRole role) const override { return role == PartRole::wheel; }
    ItemDesc make(Vec2 position) const override { return made(position, WheelParams{0.25, 1.0, 4, 1.0}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        WheelParams& p = item.params.as<WheelParams>();
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto r = table.number("radius", kSizeRange)) p.radius = *r;
        if (const auto m = table.number("mass", NumberRange{0.0, 1e4, true})) p.mass = *m;
        if (const auto n = table.integer("blades", 2, 8)) p.paddles = static_cast<int>(*n);
        if (const auto l = table.number("blade", kSizeRange)) p.paddleLength = *l;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        return wheelBodies(item, item.params.as<WheelParams>(), {}, kBounciness);
    }
    // Before the step, the air's push on each blade (joint k + 1 welds blade k to the hub), as the
    // engine gives its fields: an impulse F dt at the start of the step.
    void beforeStep(LevelRun& run, int item) const override {
        const ItemState& state = run.states()[static_cast<std::size_t>(item)];
        World& world = run.partWorld();
        if (world.fields().winds.empty() || state.joints.empty()) return;
        const double dt = world.def().timeStep;
        for (std::size_t k = 1; k < state.joints.size(); ++k) {
            const BodyId blade = world.joint(state.joints[k]).def.b.body;
            if (blade.isNull()) continue;
            const RigidBody& b = world.body(blade);
            const Vec2 half = Vec2::fromAngle(b.angle) * b.halfExtents.x;
            blowOn(world, blade, b.position - half, b.position + half, dt);
        }
    }
    void draw(const PartDrawing& d) const override { drawWheel(d, style("box", "box_outline"), "ground"); }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        render::Style look = style("box", "box_outline");
        if (!available) look.fill = look.fill.withAlpha(0x60);
        const float r = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        for (int k = 0; k < 4; ++k) {
            const Vec2 out = Vec2::fromAngle(0.4 + 0.5 * std::numbers::pi * k);
            list.capsule(pt(centre + out * (0.2 * r)), pt(centre + out * (0.85 * r)), 0.1f * r, look);
        }
        list.circle(c, 0.2f * r, look);
        list.arrow({c.x - r, c.y - 0.9f * r}, {c.x - 0.2f * r, c.y - 0.9f * r}, 2.0f,
                   render::Palette::greybox()["wind"]);
    }
};

} // namespace
RUBE_PART(windmill, WindmillKind)
} // namespace rube::game::parts
