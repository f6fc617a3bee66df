// The switch: a fixed button that, when a ball first touches it (or a click or script toggles it),
// switches what it names (`triggers`, a name or [names]: fires a cannon, sets off a bomb, flips a
// fan or magnet, lights a rocket, starts a timer, ...; cuts a [[rope]]), with a wire drawn to each.
#include "wires.hpp"

#include "script_file.hpp"

namespace rube::game::parts {
namespace {

struct SwitchParams {
    double radius = 0.2; // m
    Wires wires;         // what it switches
};

constexpr PartKey kKeys[] = {
    kKindKey, kNameKey, kPositionKey, {"radius", "0.2", "m"}, {"triggers", "required", kWiresDoc}};

class SwitchKind final : public PartKind {
public:
    std::string_view name() const override { return "switch"; }
    int order() const override { return 11; }
    int referenceOrder() const override { return 3; }
    std::string_view summary() const override {
        return "a fixed button, bounciness 0.5, that triggers what it names when first touched";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool plays(PartRole role) const override {
        return role == PartRole::toggle || role == PartRole::aimTarget || role == PartRole::hitReport;
    }
    ItemDesc make(Vec2 position) const override { return made(position, SwitchParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        SwitchParams& p = item.params.as<SwitchParams>();
        if (const auto r = table.number("radius", kSizeRange)) p.radius = *r;
        p.wires = readWires(table, Need::required);
    }
    // Checked once every item is known, so a switch may name a later cannon.
    void checkReferences(const ItemDesc& item, SceneReading& reading) const override {
        checkWires(item.params.as<SwitchParams>().wires, reading);
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        ItemBodies bodies;
        bodies.circles.push_back(roundPart(item, item.params.as<SwitchParams>().radius, 0.5));
        return bodies;
    }
    void hit(LevelRun& run, int item, Vec2 point, const std::string& by) const override {
        // Only the first touch is news, and only it flips what the switch names.
        if (firstTouch(run, item, point, by)) trigger(run, item);
    }
    void trigger(LevelRun& run, int item) const override {
        run.partState(item).pressed = true; // a click looks like a ball's press (hit() comes here too)
        switchWired(run, run.items()[static_cast<std::size_t>(item)].params.as<SwitchParams>().wires);
    }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    void draw(const PartDrawing& d) const override {
        const SwitchParams& p = itemOf(d).params.as<SwitchParams>();
        const float r = static_cast<float>(p.radius);
        const bool on = stateOf(d).hit || stateOf(d).pressed;
        drawWires(d, d.run.itemPosition(d.item), p.wires, on);
        d.list.box(pt(d.run.itemPosition(d.item)), {r, 0.6f * r}, 0.0f, style(on ? "highlight" : "box", "box_outline"));
    }
};

} // namespace
RUBE_PART(switch, SwitchKind)
} // namespace rube::game::parts
