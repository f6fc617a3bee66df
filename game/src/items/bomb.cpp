// The bomb: a fixed round charge that pushes every body near it away once, set off by a touch, a
// timer, a switch, a click or a script.
#include "part_common.hpp"

#include "script_file.hpp"

#include "rube/physics/explosion.hpp"

#include <cmath>

namespace rube::game::parts {
namespace {

constexpr double kRingSeconds = 0.5; // an explosion's ring grows to the blast radius in this time
constexpr double kRingStart = 0.3;   // ... from this share of it, so the first frame shows a ring, not a dot

// How a bomb goes off.
enum class Trigger : std::uint8_t { timer, impact, switchHit };
constexpr std::string_view kTriggerNames[] = {"timer", "impact", "switch"};

struct BombParams {
    double radius = 0.25;              // m
    double blastRadius = 2.0;          // bodies whose centre is closer are pushed, m
    double strength = 6.0;             // impulse at the centre, N s
    Trigger trigger = Trigger::impact; // a placed bomb has no fuse or switch to wait for: it goes off when hit
    double fuse = 0.0;                 // with a timer: seconds from the start
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             kPositionKey,
                             {"radius", "0.25", "m"},
                             {"blast_radius", "2", "bodies whose centre is closer are pushed, m"},
                             {"strength", "6", "impulse at the centre, N s"},
                             {"trigger", "impact", "timer | impact | switch: what sets it off"},
                             {"fuse", "none", "with trigger = \"timer\": seconds from the start (required then)"}};

class BombKind final : public PartKind {
public:
    std::string_view name() const override { return "bomb"; }
    int order() const override { return 8; }
    int referenceOrder() const override { return 2; }
    std::string_view summary() const override { return "a fixed round charge, bounciness 0.5, that goes off once"; }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool plays(PartRole role) const override {
        return role == PartRole::detonate || role == PartRole::aimTarget || role == PartRole::triggered;
    }
    ItemDesc make(Vec2 position) const override { return made(position, BombParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        BombParams& p = item.params.as<BombParams>();
        if (const auto r = table.number("radius", kSizeRange)) p.radius = *r;
        if (const auto r = table.number("blast_radius", kSizeRange)) p.blastRadius = *r;
        if (const auto s = table.number("strength", NumberRange{0.0, 10000.0, true})) p.strength = *s;
        const auto trigger = table.choice("trigger", kTriggerNames);
        if (trigger) p.trigger = static_cast<Trigger>(*trigger);
        const auto fuse = table.number("fuse", NumberRange::nonNegative());
        if (fuse) p.fuse = *fuse;
        // A timer with no fuse would go off at an arbitrary default time the author never chose.
        if (p.trigger == Trigger::timer && !fuse && trigger)
            table.error(table.valuePlace("trigger"), "a bomb with trigger 'timer' needs fuse = seconds");
        else if (fuse && p.trigger != Trigger::timer)
            table.error(table.valuePlace("fuse"), "fuse is only for trigger = \"timer\"");
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        ItemBodies bodies;
        bodies.circles.push_back(roundPart(item, item.params.as<BombParams>().radius, 0.5));
        return bodies;
    }
    double speedGiven(const ItemDesc& item, double lightest, double g, double seconds) const override {
        (void)g, (void)seconds;
        return item.params.as<BombParams>().strength / lightest;
    }
    void afterStep(LevelRun& run, int item) const override {
        const BombParams& p = run.items()[static_cast<std::size_t>(item)].params.as<BombParams>();
        if (p.trigger == Trigger::timer && timeReached(run.world(), p.fuse)) trigger(run, item);
    }
    bool waits(const ItemDesc& item, const ItemState& state) const override {
        return item.params.as<BombParams>().trigger == Trigger::timer && !state.detonatedAt;
    }
    void hit(LevelRun& run, int item, Vec2 point, const std::string& by) const override {
        (void)point, (void)by;
        if (run.items()[static_cast<std::size_t>(item)].params.as<BombParams>().trigger == Trigger::impact)
            trigger(run, item);
    }
    // Goes off: once, now.
    void trigger(LevelRun& run, int item) const override {
        ItemState& state = run.partState(item);
        if (state.detonatedAt) return; // a bomb goes off once
        const ItemDesc& desc = run.items()[static_cast<std::size_t>(item)];
        const BombParams& p = desc.params.as<BombParams>();
        World& world = run.partWorld();
        state.detonatedAt = world.time();
        Explosion explosion;
        explosion.centre = desc.position;
        explosion.radius = p.blastRadius;
        explosion.strength = p.strength;
        const ExplosionPushed pushed = applyExplosion(world, explosion);
        // The casing is gone with the blast.
        world.remove(state.circle);
        state.circle = {};
        run.report({EventKind::explosion, run.steps(), world.time(), desc.name, desc.position,
                    static_cast<int>(pushed.size()), ""});
    }
    std::optional<ActionKind> clickAction() const override { return ActionKind::detonate; }
    std::string spent(const ItemDesc& item, const ItemState& state) const override {
        return state.detonatedAt ? item.name + " went off already" : "";
    }
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const ItemState& state = stateOf(d);
        const BombParams& p = item.params.as<BombParams>();
        const render::Palette& palette = render::Palette::greybox();
        const Vec2 at = d.run.itemPosition(d.item);
        if (state.detonatedAt) {
            const double age = d.run.world().time() - *state.detonatedAt;
            if (age < kRingSeconds) {
                // The blast's whole reach from the step it goes off (every body inside was pushed on
                // that step), fading as a ring runs out to its edge: seen at once, not a dot.
                const double fade = 1.0 - age / kRingSeconds;
                const render::Color colour = palette["explosion"];
                const auto alpha = [&](double a) { return static_cast<std::uint8_t>(std::lround(a * fade)); };
                d.list.circle(pt(item.position), static_cast<float>(p.blastRadius),
                              {colour.withAlpha(alpha(0x70)), colour.withAlpha(alpha(0xff)), 2.0f});
                d.list.ring(pt(item.position),
                            static_cast<float>(p.blastRadius * (kRingStart + (1.0 - kRingStart) * age / kRingSeconds)),
                            4.0f, colour);
            }
        } else {
            d.list.circle(pt(at), static_cast<float>(p.radius), style("ground_outline", "ball_outline"));
            d.list.line(pt(at + Vec2{0.0, p.radius}), pt(at + Vec2{0.4 * p.radius, 1.5 * p.radius}), 3.0f,
                        palette["explosion"]);
        }
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const float r = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        list.circle(c, 0.7f * r, style("ground_outline", "ball_outline"));
        list.line({c.x, c.y + 0.7f * r}, {c.x + 0.3f * r, c.y + r}, 2.0f, render::Palette::greybox()["explosion"]);
    }
};

} // namespace
RUBE_PART(bomb, BombKind)
} // namespace rube::game::parts
