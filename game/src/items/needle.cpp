// The needle: a fixed steel spike the player places and turns, whose point pops a balloon that touches
// it. Its point is a tiny fixed circle at its position and its shaft a thin board behind it, along its
// angle (the way it points). A balloon that strikes the point is gone on that step: its circle leaves
// the World (World::remove), as a bomb's casing does when it goes off; anything else bounces off it,
// and a balloon that meets the shaft only bounces too.
#include "part_common.hpp"

#include <cmath>
#include <limits>

namespace rube::game::parts {
namespace {

constexpr double kPointRadius = 0.02; // m
constexpr double kShaftRadius = 0.015;
constexpr double kBounciness = 0.5;

struct NeedleParams {
    double length = 0.5; // m, from the point to the end of the shaft
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             {"position", "required", "[x, y] m: its point"},
                             {"angle", "0", "the way it points, degrees (0: right, 90: up)"},
                             {"length", "0.5", "m, from its point to the shaft's end"}};

class NeedleKind final : public PartKind {
public:
    std::string_view name() const override { return "needle"; }
    int order() const override { return 22; }
    std::string_view summary() const override {
        return "a fixed spike, 0.5 m long, bounciness 0.5, whose point pops a balloon that touches it";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; }
    ItemDesc make(Vec2 position) const override { return made(position, NeedleParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto l = table.number("length", NumberRange{2.0 * kPointRadius, kMaxItemSize, true}))
            item.params.as<NeedleParams>().length = *l;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const Vec2 back = Vec2::fromAngle(item.angle) * -1.0;
        ItemBodies bodies;
        bodies.circles.push_back(roundPart(item, kPointRadius, kBounciness));
        // The shaft's end cap at the point lies inside the point's circle (0.015 < 0.02 m), so what
        // strikes the point meets the circle.
        bodies.segments.push_back({item.position, item.position + back * item.params.as<NeedleParams>().length,
                                   kShaftRadius, bouncy(kBounciness), -1});
        return bodies;
    }
    // Something struck the point at `point`: the balloon whose surface is there pops (found by where it
    // is, not by its slot, which an earlier pop in the same step may have renumbered).
    void hit(LevelRun& run, int item, Vec2 point, const std::string& by) const override {
        (void)item, (void)by;
        int popped = -1;
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < run.items().size(); ++i) {
            const ItemState& state = run.states()[i];
            if (run.items()[i].kind->name() != "balloon" || state.circle.isNull()) continue;
            const Circle& c = run.world().circle(state.circle);
            // It struck the point this step and may have moved on since, at no more than its speed now
            // plus what gravity gave it in the step (a = |g| |gravity scale|), for at most a step.
            const double dt = run.world().def().timeStep;
            const double a = run.world().def().gravity.length() * std::abs(c.gravityScale);
            const double gap = std::abs(c.position.distance(point) - c.radius);
            const double reach = (c.velocity.length() + a * dt) * dt + 1e-9;
            if (gap <= reach && gap < nearest) {
                nearest = gap;
                popped = static_cast<int>(i);
            }
        }
        if (popped < 0) return;
        ItemState& balloon = run.partState(popped);
        run.partWorld().remove(balloon.circle);
        balloon.circle = {};
    }
    // A steel spike: the shaft is the world's board; a dark point and a band where it is held.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const Vec2 along = Vec2::fromAngle(item.angle);
        const double length = item.params.as<NeedleParams>().length;
        d.list.circle(pt(item.position), static_cast<float>(kPointRadius), style("ground_outline", "ground_outline"));
        const Vec2 band = item.position - along * (0.8 * length);
        d.list.capsule(pt(band - along * (0.05 * length)), pt(band + along * (0.05 * length)),
                       static_cast<float>(2.5 * kShaftRadius), style("kinematic", "ground_outline"));
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const float r = static_cast<float>(0.4 * size);
        const render::Point c = pt(centre);
        const std::array<render::Point, 3> spike{render::Point{c.x - r, c.y + 0.08f * r},
                                                 render::Point{c.x - r, c.y - 0.08f * r}, render::Point{c.x + r, c.y}};
        list.polygon(spike, style("kinematic", "ground_outline"));
    }
};

} // namespace
RUBE_PART(needle, NeedleKind)
} // namespace rube::game::parts
