// The detector: a fixed round sensor that switches what it names (`triggers`, a name or [names]) the
// first time a laser's beam reaches it, and reports it as a hit by the laser. Balls bounce off it.
#include "wires.hpp"

namespace rube::game::parts {
namespace {

struct DetectorParams {
    double radius = 0.25; // m
    Wires wires;          // what it switches
};

constexpr PartKey kKeys[] = {
    kKindKey, kNameKey, kPositionKey, {"radius", "0.25", "m"}, {"triggers", "required", kWiresDoc}};

class DetectorKind final : public PartKind {
public:
    std::string_view name() const override { return "detector"; }
    int order() const override { return 45; }
    std::string_view summary() const override {
        return "a fixed round sensor, bounciness 0.3, that switches what it names when a laser's beam reaches it";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool plays(PartRole role) const override { return role == PartRole::hitReport; }
    ItemDesc make(Vec2 position) const override { return made(position, DetectorParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        DetectorParams& p = item.params.as<DetectorParams>();
        if (const auto r = table.number("radius", kSizeRange)) p.radius = *r;
        p.wires = readWires(table, Need::required);
    }
    void checkReferences(const ItemDesc& item, SceneReading& reading) const override {
        checkWires(item.params.as<DetectorParams>().wires, reading);
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        ItemBodies bodies;
        bodies.circles.push_back(roundPart(item, item.params.as<DetectorParams>().radius, 0.3));
        return bodies;
    }
    // Only the first beam is news: it is reported as a hit where the beam met it, and switches.
    void beamReached(LevelRun& run, int item, Vec2 point, const std::string& by) const override {
        ItemState& state = run.partState(item);
        if (state.fired) return;
        state.fired = true;
        state.hit = true;
        const ItemDesc& desc = run.items()[static_cast<std::size_t>(item)];
        run.report({EventKind::hit, run.steps(), run.world().time(), desc.name, point, 0, by});
        switchWired(run, desc.params.as<DetectorParams>().wires);
    }
    // A dark lens in a ring, lit once the beam has reached it; its wires.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const ItemState& state = stateOf(d);
        const DetectorParams& p = item.params.as<DetectorParams>();
        const Vec2 at = d.run.itemPosition(d.item);
        drawWires(d, at, p.wires, state.fired);
        d.list.circle(pt(at), static_cast<float>(p.radius), style("box", "box_outline", 2.0f));
        d.list.circle(pt(at), static_cast<float>(0.55 * p.radius),
                      style(state.fired ? "laser" : "ground_outline", "ball_outline"));
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const float r = static_cast<float>(0.35 * size);
        list.circle(pt(centre), r, style("box", "box_outline", 2.0f));
        list.circle(pt(centre), 0.55f * r, style("ground_outline", "ball_outline"));
    }
};

} // namespace
RUBE_PART(detector, DetectorKind)
} // namespace rube::game::parts
