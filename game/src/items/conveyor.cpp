// The conveyor: a fixed straight belt between two rollers whose top surface runs along it at `speed`
// (a segment with a surface speed, felt through friction: World's belt velocity). A body set on it at
// rest slides against the belt, so kinetic friction accelerates it at a = mu g on a level belt, and at
// a = g (mu cos theta - sin theta) up one tilted by theta, until it moves with the belt (after
// v / a s and v^2 / (2 a) m), then rides at the belt's speed. Only what has friction is carried: the
// crate and the domino (0.4 each, 0.4 on the default belt), and a level's [[circle]] given a friction;
// the ball parts are frictionless and slide over it. Running from the start, or still until a switch,
// click or script starts it (a second trigger stops it again).
#include "part_common.hpp"

#include "script_file.hpp"

#include <cmath>

namespace rube::game::parts {
namespace {

constexpr double kBeltRadius = 0.1;     // half the band's thickness, and its rollers' radius, m
constexpr double kBeltBounciness = 0.2; // rubber: dull
constexpr double kRollerInset = 0.8;    // the rollers drawn inside the band's rounded ends, as a share of its radius

struct ConveyorParams {
    double length = 2.0;   // m, between the rollers' centres
    double speed = 1.5;    // m/s along a -> b (towards its right end at angle 0)
    double friction = 1.0; // rubber: a crate's 0.4 on it gives the pair mu = 0.4
    bool on = true;        // running from the start
};

constexpr PartKey kKeys[] = {
    kKindKey,
    kNameKey,
    {"position", "required", "[x, y] m: the belt's centre"},
    {"angle", "0", "tilt, degrees; a positive speed carries towards its right end, up the tilt"},
    {"length", "2", "m, between its rollers' centres"},
    {"speed", "1.5", "the top surface's speed, m/s: positive towards its right end, negative to the left"},
    {"friction", "1", "the belt's Coulomb mu; a pair's mu is the product of both (a crate's on it: 0.4)"},
    {"on", "true", "running from the start (a switch flips it)"}};

// Running now: as the file says, flipped by each trigger (ItemState::pressed holds the parity).
bool running(const ItemDesc& item, const ItemState& state) {
    return item.params.as<ConveyorParams>().on != state.pressed;
}

// The band: a segment from its left roller to its right, its surface running at `speed` along a -> b
// while it runs and still otherwise.
SegmentDef band(const ItemDesc& item, bool run) {
    const ConveyorParams& p = item.params.as<ConveyorParams>();
    const Vec2 half = Vec2::fromAngle(item.angle) * (0.5 * p.length);
    SegmentDef belt;
    belt.a = item.position - half;
    belt.b = item.position + half;
    belt.radius = kBeltRadius;
    belt.material.bounciness = kBeltBounciness;
    belt.material.friction = p.friction;
    belt.surfaceSpeed = run ? p.speed : 0.0;
    return belt;
}

class ConveyorKind final : public PartKind {
public:
    std::string_view name() const override { return "conveyor"; }
    int order() const override { return 47; }
    std::string_view summary() const override {
        return "a fixed belt, 2 m long, friction 1, whose top runs at 1.5 m/s: carries crates and dominoes (balls "
               "have no friction and slide)";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; } // turned half round it carries the other way: a whole turn
    bool plays(PartRole role) const override { return role == PartRole::toggle || role == PartRole::triggered; }
    ItemDesc make(Vec2 position) const override { return made(position, ConveyorParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        ConveyorParams& p = item.params.as<ConveyorParams>();
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto l = table.number("length", kSizeRange)) p.length = *l;
        if (const auto s = table.number("speed", NumberRange{-100.0, 100.0})) p.speed = *s;
        if (const auto mu = table.number("friction", NumberRange{0.0, 10.0})) p.friction = *mu;
        if (const auto on = table.boolean("on")) p.on = *on;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        ItemBodies bodies;
        bodies.segments.push_back(band(item, item.params.as<ConveyorParams>().on));
        return bodies;
    }
    // Friction brings a body at most to the belt's speed; as for moving walls, a bounce off it gains at
    // most twice that (the random-level tests' bound).
    double speedGiven(const ItemDesc& item, double lightest, double g, double seconds) const override {
        (void)lightest, (void)g, (void)seconds;
        return 2.0 * std::abs(item.params.as<ConveyorParams>().speed);
    }
    // Switched: the band's surface runs at `speed` or stands still (World::setSurfaceSpeed wakes what
    // sleeps on it).
    void trigger(LevelRun& run, int item) const override {
        ItemState& state = run.partState(item);
        if (state.segments.empty()) return;
        state.pressed = !state.pressed;
        const ItemDesc& desc = run.items()[static_cast<std::size_t>(item)];
        run.partWorld().setSurfaceSpeed(state.segments.front(),
                                        running(desc, state) ? desc.params.as<ConveyorParams>().speed : 0.0);
    }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    // The band and its chevrons are drawn with the world's segments (moving_marks.cpp, while it runs);
    // here its two rollers, whose spokes turn at omega = v / r while it runs, lit as a powered motor's.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const bool on = running(item, stateOf(d));
        const SegmentDef belt = band(item, on);
        const double r = kRollerInset * kBeltRadius;
        // The top surface moving along a -> b turns the rollers clockwise (negative angle) at v / R.
        const double turned = on ? -belt.surfaceSpeed * d.run.world().time() / kBeltRadius : 0.0;
        for (const Vec2 roller : {belt.a, belt.b})
            d.list.circleWithSpoke(pt(roller), static_cast<float>(r), static_cast<float>(item.angle + turned),
                                   style(on ? "highlight" : "box", "box_outline"));
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        const float r = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        render::Style band = style("ground", "ground_outline");
        render::Style roller = style("highlight", "box_outline");
        if (!available) band.fill = band.fill.withAlpha(0x60), roller.fill = roller.fill.withAlpha(0x60);
        const float thick = 0.22f * r;
        list.capsule({c.x - 0.75f * r, c.y}, {c.x + 0.75f * r, c.y}, thick, band);
        for (const float x : {-0.75f * r, 0.75f * r}) list.circleWithSpoke({c.x + x, c.y}, 0.8f * thick, 0.0f, roller);
        // Chevrons pointing the way its top runs, as the belt shows while running.
        const render::Color arrow = render::Palette::greybox()["arrow"];
        for (const float x : {-0.15f * r, 0.3f * r}) {
            list.line({c.x + x - thick, c.y + thick}, {c.x + x, c.y}, 2.0f, arrow);
            list.line({c.x + x - thick, c.y - thick}, {c.x + x, c.y}, 2.0f, arrow);
        }
    }
};

} // namespace
RUBE_PART(conveyor, ConveyorKind)
} // namespace rube::game::parts
