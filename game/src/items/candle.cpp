// The candle: a fixed candle whose flame burns through the [[rope]] it names (`burns`) `burn_time`
// seconds after it is lit: at the start of the run (lit = true, the default), or (lit = false) when
// a switch, a click or another trigger lights it. The rope is cut once, on the step at whose end
// the world's time has reached the lighting + burn_time. It has no body: balls pass it by.
#include "part_common.hpp"

#include "script_file.hpp"

#include <algorithm>
#include <cmath>

namespace rube::game::parts {
namespace {

constexpr double kHeight = 0.6;    // the wax when new, m
constexpr double kStub = 0.15;     // the wax left when the rope is cut, m
constexpr double kHalfWidth = 0.1; // m
constexpr double kFlame = 0.18;    // the flame's height, m

struct CandleParams {
    std::string burns;     // the [[rope]] it burns through
    SourcePlace at;        // where the file wrote `burns`
    double burnTime = 2.0; // s from lighting to the cut
    bool lit = true;       // burning from the start
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             {"position", "required", "[x, y] m: the middle of its foot"},
                             {"burns", "required", "the name of the [[rope]] its flame burns through"},
                             {"burn_time", "2", "seconds from lighting to the rope's cut"},
                             {"lit", "true", "burning from the start; false: a switch, click or trigger lights it"}};

// When the candle was lit, if it has been.
std::optional<double> litAt(const CandleParams& p, const ItemState& state) {
    return p.lit ? std::optional<double>(0.0) : state.since;
}

// The share of the burn done at `time`: 0 when lit (or unlit), 1 when the rope is cut.
double burnt(const CandleParams& p, const ItemState& state, double time) {
    if (state.fired) return 1.0;
    const auto lit = litAt(p, state);
    return lit && p.burnTime > 0.0 ? std::clamp((time - *lit) / p.burnTime, 0.0, 1.0) : 0.0;
}

class CandleKind final : public PartKind {
public:
    std::string_view name() const override { return "candle"; }
    int order() const override { return 42; }
    std::string_view summary() const override {
        return "a fixed candle whose flame burns through the rope it names a set time after it is lit";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool plays(PartRole role) const override { return role == PartRole::toggle || role == PartRole::triggered; }
    ItemDesc make(Vec2 position) const override { return made(position, CandleParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        CandleParams& p = item.params.as<CandleParams>();
        p.burns = table.string("burns", Need::required).value_or("");
        p.at = table.valuePlace("burns");
        if (const auto t = table.number("burn_time", NumberRange::nonNegative())) p.burnTime = *t;
        if (const auto lit = table.boolean("lit")) p.lit = *lit;
    }
    void checkReferences(const ItemDesc& item, SceneReading& reading) const override {
        const CandleParams& p = item.params.as<CandleParams>();
        if (p.burns.empty() || reading.scene.findRope(p.burns) >= 0) return;
        std::vector<std::string_view> ropes;
        for (const std::string& rope : reading.scene.ropeNames)
            if (!rope.empty()) ropes.push_back(rope);
        reading.diag.error(p.at, "unknown rope '" + p.burns + "'" +
                                     unknownNameHint(p.burns, ropes, "the level has", "the level has no named rope"));
    }
    ItemBodies bodies(const ItemDesc& item) const override { return (void)item, ItemBodies{}; }
    // No body, but its room: a part may not be placed over it.
    ItemBodies room(const ItemDesc& item) const override {
        ItemBodies wax;
        wax.segments.push_back({item.position + Vec2{0.0, kHalfWidth}, item.position + Vec2{0.0, kHeight - kHalfWidth},
                                kHalfWidth, Material{}, -1});
        return wax;
    }
    Aabb extent(const ItemDesc& item) const override {
        return {item.position - Vec2{kHalfWidth, 0.0}, item.position + Vec2{kHalfWidth, kHeight + kFlame}};
    }
    bool picked(const ItemDesc& item, Vec2 at, Vec2 cursor, double tolerance) const override {
        (void)at, (void)tolerance;
        return extent(item).contains(cursor);
    }
    void afterStep(LevelRun& run, int item) const override {
        const ItemDesc& desc = run.items()[static_cast<std::size_t>(item)];
        const CandleParams& p = desc.params.as<CandleParams>();
        ItemState& state = run.partState(item);
        const auto lit = litAt(p, state);
        if (state.fired || !lit || !timeReached(run.world(), *lit + p.burnTime)) return;
        state.fired = true;
        run.cutRope(p.burns);
    }
    bool waits(const ItemDesc& item, const ItemState& state) const override {
        return !state.fired && litAt(item.params.as<CandleParams>(), state).has_value();
    }
    // Lit by a switch: once; a candle lit from the start ignores it.
    void trigger(LevelRun& run, int item) const override {
        ItemState& state = run.partState(item);
        if (!run.items()[static_cast<std::size_t>(item)].params.as<CandleParams>().lit && !state.since)
            state.since = run.world().time();
    }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    std::string spent(const ItemDesc& item, const ItemState& state) const override {
        if (state.fired) return item.name + " has burnt through its rope";
        if (litAt(item.params.as<CandleParams>(), state)) return item.name + " is lit already";
        return "";
    }
    // The wax shortens from its full height to a stub as it burns; the flame burns on its top until
    // the rope is cut, and shrinks with the wax.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const ItemState& state = stateOf(d);
        const CandleParams& p = item.params.as<CandleParams>();
        const double share = burnt(p, state, d.run.world().time());
        const bool burning = !state.fired && litAt(p, state).has_value();
        drawCandle(item.position, 1.0, kHeight - (kHeight - kStub) * share, burning ? 1.0 - 0.5 * share : 0.0, d.list);
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const double scale = 0.8 * size / (kHeight + kFlame);
        drawCandle(centre - Vec2{0.0, 0.4 * size}, scale, kHeight, 1.0, list);
    }

private:
    // A candle of wax `height` (unscaled, m) at `foot`, drawn `scale` times its size, with a flame
    // of `flame` of its full size (none at 0).
    static void drawCandle(Vec2 foot, double scale, double height, double flame, render::DrawList& list) {
        const double w = kHalfWidth * scale, h = height * scale;
        list.box(pt(foot + Vec2{0.0, 0.5 * h}), {static_cast<float>(w), static_cast<float>(0.5 * h)}, 0.0f,
                 style("ball", "ball_outline"));
        const Vec2 top = foot + Vec2{0.0, h};
        list.line(pt(top), pt(top + Vec2{0.0, 0.05 * scale}), 2.0f, render::Palette::greybox()["spoke"]);
        if (flame <= 0.0) return;
        const double f = kFlame * scale * flame;
        const std::array<render::Point, 4> drop{pt(top + Vec2{0.0, 0.02 * scale}), pt(top + Vec2{0.45 * w, 0.4 * f}),
                                                pt(top + Vec2{0.0, f}), pt(top + Vec2{-0.45 * w, 0.4 * f})};
        const render::Color colour = render::Palette::greybox()["flame"];
        list.polygon(drop, {colour, render::Palette::greybox()["explosion"], 1.0f});
    }
};

} // namespace
RUBE_PART(candle, CandleKind)
} // namespace rube::game::parts
