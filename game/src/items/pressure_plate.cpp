// The pressure plate: a fixed, dead (bounciness 0) plate that switches what it names (`triggers`,
// as a switch does) once weight rests on it: balls of together at least `min_mass` kg touching its
// top for `hold` seconds without a break. A light ball rests on it and nothing happens. It switches
// once, on the step at whose end `hold` has passed since the load came on (the impact's own time
// when a ball's arrival brought it, so the firing is within one step of contact + hold).
#include "wires.hpp"

#include <algorithm>
#include <cmath>

namespace rube::game::parts {
namespace {

constexpr double kThickness = 0.08; // half the plate's thickness (its segment's radius), m
constexpr double kTouch = 0.01;     // a ball this close to the plate's surface rests on it, m
constexpr double kSettling = 0.3;   // a ball coming down faster than this is falling onto it, not resting, m/s
constexpr double kSink = 0.04;      // how far the plate is drawn pressed down when loaded, m

struct PlateParams {
    double width = 1.0;   // m, between its end caps' centres
    double minMass = 2.0; // kg resting on it that presses it
    double hold = 0.2;    // s the weight must rest
    Wires wires;          // what it switches
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             {"position", "required", "[x, y] m: the plate's centre (its top is 0.08 m above)"},
                             {"width", "1", "m"},
                             {"min_mass", "2", "kg resting on it (balls together) that presses it"},
                             {"hold", "0.2", "seconds the weight must rest on it without a break"},
                             {"triggers", "required", kWiresDoc}};

// The plate's segment: level, centred on its position.
std::pair<Vec2, Vec2> plateEnds(const ItemDesc& item) {
    const double half = 0.5 * item.params.as<PlateParams>().width;
    return {item.position - Vec2{half, 0.0}, item.position + Vec2{half, 0.0}};
}

// True when dynamic circle `c` rests on the plate: above it (its centre over the plate's span) and
// touching its top within kTouch, and not coming down onto it.
bool restsOn(const ItemDesc& item, const Circle& c) {
    const auto [a, b] = plateEnds(item);
    if (c.motion != Motion::dynamic || c.position.x < a.x || c.position.x > b.x) return false;
    // Not one still falling onto it: a ball about to strike is not yet weight on the plate.
    const double gap = c.position.y - item.position.y - kThickness - c.radius;
    return gap > -kThickness && gap <= kTouch && c.velocity.y >= -kSettling;
}

class PressurePlateKind final : public PartKind {
public:
    std::string_view name() const override { return "pressure-plate"; }
    int order() const override { return 41; }
    std::string_view summary() const override {
        return "a fixed dead plate, 1 m wide, that switches what it names when enough weight rests on it";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    ItemDesc make(Vec2 position) const override { return made(position, PlateParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        PlateParams& p = item.params.as<PlateParams>();
        if (const auto w = table.number("width", kSizeRange)) p.width = *w;
        if (const auto m = table.number("min_mass", NumberRange::nonNegative())) p.minMass = *m;
        if (const auto h = table.number("hold", NumberRange::nonNegative())) p.hold = *h;
        p.wires = readWires(table, Need::required);
    }
    void checkReferences(const ItemDesc& item, SceneReading& reading) const override {
        checkWires(item.params.as<PlateParams>().wires, reading);
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const auto [a, b] = plateEnds(item);
        ItemBodies bodies;
        bodies.segments.push_back({a, b, kThickness, bouncy(0.0), -1});
        return bodies;
    }
    bool picked(const ItemDesc& item, Vec2 at, Vec2 cursor, double tolerance) const override {
        (void)at, (void)tolerance;
        return extent(item).contains(cursor);
    }
    void afterStep(LevelRun& run, int item) const override {
        ItemState& state = run.partState(item);
        if (state.fired) return;
        const ItemDesc& desc = run.items()[static_cast<std::size_t>(item)];
        const PlateParams& p = desc.params.as<PlateParams>();
        const World& world = run.world();
        const auto circles = world.circles();
        double load = 0.0;
        for (const Circle& c : circles)
            if (restsOn(desc, c) && c.inverseMass > 0.0) load += 1.0 / c.inverseMass;
        if (load < p.minMass || load == 0.0) {
            state.since.reset(); // a break in the weight starts the hold again
            return;
        }
        if (!state.since) {
            // The load came on in this step: at the earliest impact on the plate's top in it, if a
            // ball's arrival brought it, else at the step's end.
            double since = world.time();
            for (const Impact& impact : world.lastImpacts())
                if (impact.otherKind == Other::segment && impact.circle >= 0 &&
                    restsOn(desc, circles[static_cast<std::size_t>(impact.circle)]) &&
                    std::abs(impact.pointOfImpact.y - desc.position.y - kThickness) <= kTouch)
                    since = std::min(since, impact.time);
            state.since = since;
        }
        if (!timeReached(world, *state.since + p.hold)) return;
        state.fired = true;
        switchWired(run, p.wires);
    }
    bool waits(const ItemDesc& item, const ItemState& state) const override {
        (void)item;
        return !state.fired && state.since.has_value();
    }
    // The plate over a dark base, pressed down once it has switched; its wires.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const ItemState& state = stateOf(d);
        const PlateParams& p = item.params.as<PlateParams>();
        drawWires(d, item.position, p.wires, state.fired);
        const float half = static_cast<float>(0.5 * p.width + kThickness);
        const render::Point base = pt(item.position - Vec2{0.0, kThickness});
        d.list.box(base, {half, 0.5f * static_cast<float>(kThickness)}, 0.0f, style("ground", "ground_outline"));
        const double sink = state.fired ? kSink : state.since ? 0.5 * kSink : 0.0;
        d.list.box(pt(item.position - Vec2{0.0, sink}), {half - 0.05f, static_cast<float>(kThickness)}, 0.0f,
                   style(state.fired ? "highlight" : "box", "box_outline"));
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const float r = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        list.box({c.x, c.y - 0.2f * r}, {0.9f * r, 0.1f * r}, 0.0f, style("ground", "ground_outline"));
        list.box({c.x, c.y}, {0.75f * r, 0.12f * r}, 0.0f, style("box", "box_outline"));
        list.arrow({c.x, c.y + 0.8f * r}, {c.x, c.y + 0.2f * r}, 2.0f, render::Palette::greybox()["arrow"]);
    }
};

} // namespace
RUBE_PART(pressure_plate, PressurePlateKind)
} // namespace rube::game::parts
