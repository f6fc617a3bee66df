// The magnet: a fixed round part whose field pulls steel balls, F = strength / d^2 (held at its value
// at the magnet's radius, none past its reach); a switch, click or script turns it off and on.
#include "part_common.hpp"

#include "script_file.hpp"

#include <cmath>

namespace rube::game::parts {
namespace {

struct MagnetParams {
    double radius = 0.25; // m
    // Pull at 1 m, N m^2: holds a 4 kg steel ball against gravity from about 1.4 m.
    double strength = 80.0;
    double reach = 3.0; // no pull this far or farther, m
    bool on = true;     // pulling from the start
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             kPositionKey,
                             {"radius", "0.25", "m"},
                             {"strength", "80", "pull at 1 m, N m^2"},
                             {"reach", "3", "no pull this far or farther, m"},
                             {"on", "true", "pulling from the start (a switch flips it)"}};

class MagnetKind final : public PartKind {
public:
    std::string_view name() const override { return "magnet"; }
    int order() const override { return 12; }
    int referenceOrder() const override { return 6; }
    std::string_view summary() const override { return "a fixed round magnet, bounciness 0.3, that pulls steel balls"; }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool plays(PartRole role) const override { return role == PartRole::toggle || role == PartRole::triggered; }
    ItemDesc make(Vec2 position) const override { return made(position, MagnetParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        MagnetParams& p = item.params.as<MagnetParams>();
        if (const auto r = table.number("radius", kSizeRange)) p.radius = *r;
        if (const auto s = table.number("strength", NumberRange{0.0, 10000.0, true})) p.strength = *s;
        if (const auto r = table.number("reach", kSizeRange)) p.reach = *r;
        if (const auto on = table.boolean("on")) p.on = *on;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const MagnetParams& p = item.params.as<MagnetParams>();
        ItemBodies bodies;
        bodies.magnet = Magnet{item.position, p.strength, p.radius, p.reach, p.on};
        bodies.circles.push_back(roundPart(item, p.radius, 0.3));
        return bodies;
    }
    // Its pull from afar to its radius, E = s / r, given to the lightest ball.
    double speedGiven(const ItemDesc& item, double lightest, double g, double seconds) const override {
        (void)g, (void)seconds;
        const MagnetParams& p = item.params.as<MagnetParams>();
        return std::sqrt(2.0 * p.strength / (lightest * p.radius));
    }
    void trigger(LevelRun& run, int item) const override {
        run.partWorld()
            .fields()
            .magnets[static_cast<std::size_t>(run.states()[static_cast<std::size_t>(item)].field)]
            .on ^= true;
    }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    void draw(const PartDrawing& d) const override {
        // Red when pulling, grey when switched off; the faint ring is how far it reaches.
        const MagnetParams& p = itemOf(d).params.as<MagnetParams>();
        const Vec2 at = d.run.itemPosition(d.item);
        const float r = static_cast<float>(p.radius);
        const bool on = d.run.world().fields().magnets[static_cast<std::size_t>(stateOf(d).field)].on;
        if (on && std::isfinite(p.reach))
            d.list.ring(pt(at), static_cast<float>(p.reach), 1.5f,
                        render::Palette::greybox()["magnet"].withAlpha(0x50));
        d.list.circle(pt(at), r, style(on ? "magnet" : "box", "ball_outline"));
        d.list.box(pt(at - Vec2{0.0, 0.5 * p.radius}), {0.6f * r, 0.2f * r}, 0.0f, style("ball", "ball_outline"));
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        list.circle(pt(centre), 0.8f * static_cast<float>(0.5 * size), style("magnet", "ball_outline"));
    }
};

} // namespace
RUBE_PART(magnet, MagnetKind)
} // namespace rube::game::parts
