// The switch: a fixed button that, when a ball first touches it (or a click or script toggles it),
// triggers the item it names (fires a cannon, sets off a bomb, flips a fan or magnet, lights a
// rocket) or cuts the [[rope]] it names.
#include "part_common.hpp"

#include "script_file.hpp"

namespace rube::game::parts {
namespace {

struct SwitchParams {
    double radius = 0.2;  // m
    std::string triggers; // the name of what it triggers, or of the [[rope]] it cuts
    SourcePlace at;       // where the file wrote `triggers`, for the message when it names nothing that fits
    bool given = false;   // `triggers` was written (an empty name is then an error; a missing one is already)
};

constexpr PartKey kKeys[] = {
    kKindKey,
    kNameKey,
    kPositionKey,
    {"radius", "0.2", "m"},
    {"triggers", "required",
     "the name of a cannon, bomb, fan, magnet, rocket, motor, launcher or glove, or of a [[rope]] (cut)"}};

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
        p.triggers = table.string("triggers", Need::required).value_or("");
        p.at = table.valuePlace("triggers");
        p.given = table.find("triggers") != nullptr;
    }
    // Checked once every item is known, so a switch may name a later cannon.
    void checkReferences(const ItemDesc& item, SceneReading& reading) const override {
        const SwitchParams& p = item.params.as<SwitchParams>();
        if (!p.given || reading.scene.findRope(p.triggers) >= 0) return; // a switch may cut a named [[rope]]
        if (std::string message = itemReferenceError(reading.scene.level, "triggers", p.triggers, PartRole::triggered,
                                                     "", &reading.scene.ropeNames);
            !message.empty())
            reading.diag.error(p.at, std::move(message));
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        ItemBodies bodies;
        bodies.circles.push_back(roundPart(item, item.params.as<SwitchParams>().radius, 0.5));
        return bodies;
    }
    void hit(LevelRun& run, int item, Vec2 point, const std::string& by) const override {
        // Only the first touch is news, and only it flips what the switch names.
        ItemState& state = run.partState(item);
        if (state.hit) return;
        state.hit = true;
        run.report({EventKind::hit, run.steps(), run.world().time(), run.items()[static_cast<std::size_t>(item)].name,
                    point, 0, by});
        trigger(run, item);
    }
    void trigger(LevelRun& run, int item) const override {
        run.partState(item).pressed = true; // a click looks like a ball's press (hit() comes here too)
        const std::string& name = run.items()[static_cast<std::size_t>(item)].params.as<SwitchParams>().triggers;
        if (run.scene().findRope(name) >= 0) return run.cutRope(name);
        if (const int target = run.find(name); target >= 0)
            run.items()[static_cast<std::size_t>(target)].kind->trigger(run, target);
    }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    void draw(const PartDrawing& d) const override {
        const float r = static_cast<float>(itemOf(d).params.as<SwitchParams>().radius);
        d.list.box(pt(d.run.itemPosition(d.item)), {r, 0.6f * r}, 0.0f,
                   style(stateOf(d).hit || stateOf(d).pressed ? "highlight" : "box", "box_outline"));
    }
};

} // namespace
RUBE_PART(switch, SwitchKind)
} // namespace rube::game::parts
