// The timer: a fixed clock that switches what it names (`triggers`, as a switch does) `delay`
// seconds after its clock starts: at the start of the run, or (start = "switch") when a switch, a
// click or another trigger starts it. It fires once, in the step at whose end the world's time has
// reached the start + delay, so on step ceil(delay / dt) of a clock started with the run.
#include "wires.hpp"

#include "script_file.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rube::game::parts {
namespace {

constexpr double kRadius = 0.3;     // the clock face, m
constexpr double kBounciness = 0.3; // a pair's bounciness is the product of both (lecture 3)

// When its clock starts.
enum class Start : std::uint8_t { run, switched };
constexpr std::string_view kStartNames[] = {"run", "switch"};

struct TimerParams {
    double delay = 1.0;       // s from its start to its firing
    Start start = Start::run; // when its clock starts
    Wires wires;              // what it switches
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             kPositionKey,
                             {"delay", "required", "seconds from its start to switching what it names"},
                             {"start", "run", "run | switch: its clock starts with the run, or when it is switched"},
                             {"triggers", "required", kWiresDoc}};

// When the timer's clock started, if it has.
std::optional<double> startedAt(const TimerParams& p, const ItemState& state) {
    return p.start == Start::run ? std::optional<double>(0.0) : state.since;
}

class TimerKind final : public PartKind {
public:
    std::string_view name() const override { return "timer"; }
    int order() const override { return 40; }
    std::string_view summary() const override {
        return "a fixed clock, radius 0.3 m, that switches what it names a set time after it starts";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool needsName() const override { return false; }
    bool plays(PartRole role) const override { return role == PartRole::toggle || role == PartRole::triggered; }
    ItemDesc make(Vec2 position) const override { return made(position, TimerParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        TimerParams& p = item.params.as<TimerParams>();
        if (const auto d = table.number("delay", NumberRange::nonNegative(), Need::required)) p.delay = *d;
        if (const auto s = table.choice("start", kStartNames)) p.start = static_cast<Start>(*s);
        p.wires = readWires(table, Need::required);
    }
    void checkReferences(const ItemDesc& item, SceneReading& reading) const override {
        checkWires(item.params.as<TimerParams>().wires, reading);
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        ItemBodies bodies;
        bodies.circles.push_back(roundPart(item, kRadius, kBounciness));
        return bodies;
    }
    void afterStep(LevelRun& run, int item) const override {
        const TimerParams& p = run.items()[static_cast<std::size_t>(item)].params.as<TimerParams>();
        ItemState& state = run.partState(item);
        const auto start = startedAt(p, state);
        if (state.fired || !start || !timeReached(run.world(), *start + p.delay)) return;
        state.fired = true;
        switchWired(run, p.wires);
    }
    bool waits(const ItemDesc& item, const ItemState& state) const override {
        return !state.fired && startedAt(item.params.as<TimerParams>(), state).has_value();
    }
    // Switched: a timer that waits for a switch starts its clock (once); one running from the start
    // ignores it.
    void trigger(LevelRun& run, int item) const override {
        ItemState& state = run.partState(item);
        if (run.items()[static_cast<std::size_t>(item)].params.as<TimerParams>().start == Start::switched &&
            !state.since)
            state.since = run.world().time();
    }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    std::string spent(const ItemDesc& item, const ItemState& state) const override {
        if (state.fired) return item.name + " has gone off already";
        if (startedAt(item.params.as<TimerParams>(), state)) return item.name + " is running already";
        return "";
    }
    // A clock face whose hand sweeps once around from twelve o'clock to the firing, with a filled
    // wedge of the time gone; wires to what it switches.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const ItemState& state = stateOf(d);
        const TimerParams& p = item.params.as<TimerParams>();
        const Vec2 at = d.run.itemPosition(d.item);
        drawWires(d, at, p.wires, state.fired);
        d.list.circle(pt(at), static_cast<float>(kRadius),
                      style(state.fired ? "highlight" : "ball", "ball_outline", 2.0f));
        const auto start = startedAt(p, state);
        const double share = state.fired              ? 1.0
                             : start && p.delay > 0.0 ? std::clamp((d.run.world().time() - *start) / p.delay, 0.0, 1.0)
                                                      : 0.0;
        drawDial(at, kRadius, share, d.list);
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const double r = 0.4 * size;
        list.circle(pt(centre), static_cast<float>(r), style("ball", "ball_outline", 2.0f));
        drawDial(centre, r, 0.25, list);
    }

private:
    // The time gone as a wedge of the face and a hand at its edge (clockwise from twelve).
    static void drawDial(Vec2 at, double r, double share, render::DrawList& list) {
        const double start = 0.5 * std::numbers::pi;
        const double end = start - 2.0 * std::numbers::pi * share;
        if (share > 0.0) {
            std::vector<render::Point> wedge{pt(at)};
            const int n = std::max(2, static_cast<int>(std::ceil(24 * share)) + 1);
            for (int i = 0; i < n; ++i)
                wedge.push_back(pt(at + Vec2::fromAngle(start + (end - start) * i / (n - 1)) * (0.8 * r)));
            list.polygon(wedge, style("ground", "ground", 0.0f));
        }
        list.line(pt(at), pt(at + Vec2::fromAngle(end) * (0.85 * r)), 2.0f, render::Palette::greybox()["spoke"]);
        list.circle(pt(at), static_cast<float>(0.12 * r), style("spoke", "spoke"));
    }
};

} // namespace
RUBE_PART(timer, TimerKind)
} // namespace rube::game::parts
