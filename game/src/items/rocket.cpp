// The rocket: a 1 kg ball with a thruster, a constant force `thrust` along its angle for `burn`
// seconds from the start, or from the moment a switch, click or script lights it (once).
#include "part_common.hpp"

#include "script_file.hpp"

#include <cmath>
#include <limits>

namespace rube::game::parts {
namespace {

constexpr double kMass = 1.0; // kg
constexpr double kBounciness = 0.3;
constexpr double kFlameLength = 1.6;  // its flame, in its radii beyond the body ...
constexpr double kFlameFlicker = 0.4; // ... give or take this much ...
constexpr double kFlameRate = 37.0;   // ... at this many radians per second of world time

struct RocketParams {
    double radius = 0.25; // m
    Vec2 velocity;        // initial velocity, m/s
    // 15 N on its 1 kg lifts it against gravity at about 5 m/s^2, for 2 s.
    double thrust = 15.0; // N
    double burn = 2.0;    // s
    bool on = true;       // lit at the start (else a switch or click lights it)
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             kPositionKey,
                             {"radius", "0.25", "m"},
                             {"velocity", "[0, 0]", "initial velocity, m/s"},
                             {"angle", "0", "the way it pushes, degrees"},
                             {"thrust", "15", "the thruster's constant force, N"},
                             {"burn", "2", "how long it burns once lit, s"},
                             {"on", "true", "lit at the start; false: a switch, click or toggle lights it once"}};

// Its flame while it burns: a triangle from the back of its body, pointing against the thrust,
// flickering in length with the world time (never the wall clock) so frames stay reproducible.
void drawFlame(Vec2 centre, double radius, Vec2 direction, double time, render::DrawList& list) {
    const double length = radius * (kFlameLength + kFlameFlicker * std::sin(kFlameRate * time));
    const Vec2 back = centre - direction * (0.6 * radius), across = direction.perpendicular() * (0.55 * radius);
    const render::Point flame[] = {pt(back + across), pt(back - direction * (0.4 * radius + length)),
                                   pt(back - across)};
    const render::Palette& p = render::Palette::greybox();
    list.polygon(flame, {p["flame"], p["explosion"], 1.0f});
}

class RocketKind final : public PartKind {
public:
    std::string_view name() const override { return "rocket"; }
    int order() const override { return 14; }
    int referenceOrder() const override { return 7; }
    std::string_view summary() const override { return "a 1 kg ball, bounciness 0.3, with a thruster along its angle"; }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; }
    bool plays(PartRole role) const override {
        return role == PartRole::toggle || role == PartRole::triggered || role == PartRole::goalMover;
    }
    ItemDesc make(Vec2 position) const override { return made(position, RocketParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        RocketParams& p = item.params.as<RocketParams>();
        if (const auto r = table.number("radius", kSizeRange)) p.radius = *r;
        if (const auto v = table.vec2("velocity")) p.velocity = *v;
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto f = table.number("thrust", NumberRange{0.0, 10000.0, true})) p.thrust = *f;
        if (const auto t = table.number("burn", NumberRange{0.0, 1000.0, true})) p.burn = *t;
        if (const auto on = table.boolean("on")) p.on = *on;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const RocketParams& p = item.params.as<RocketParams>();
        CircleDef body;
        body.position = item.position;
        body.velocity = p.velocity;
        body.radius = p.radius;
        body.mass = kMass;
        body.material = bouncy(kBounciness);
        ItemBodies bodies;
        bodies.circles.push_back(body);
        // Lit at the start it burns [0, burn); unlit, it waits (start and end at infinity) for a switch or click.
        Thruster thruster;
        thruster.force = Vec2::fromAngle(item.angle) * p.thrust;
        thruster.start = p.on ? 0.0 : std::numeric_limits<double>::infinity();
        thruster.end = p.on ? p.burn : std::numeric_limits<double>::infinity();
        bodies.thruster = thruster;
        return bodies;
    }
    double speedGiven(const ItemDesc& item, double lightest, double g, double seconds) const override {
        (void)g, (void)seconds;
        const RocketParams& p = item.params.as<RocketParams>();
        return p.thrust * p.burn / lightest;
    }
    // A rocket lights once, now, and burns its full time; lit or burnt out, it cannot be lit again.
    void trigger(LevelRun& run, int item) const override {
        World& world = run.partWorld();
        Thruster& thruster =
            world.fields().thrusters[static_cast<std::size_t>(run.states()[static_cast<std::size_t>(item)].field)];
        if (std::isinf(thruster.start)) {
            thruster.start = world.time();
            thruster.end = world.time() + run.items()[static_cast<std::size_t>(item)].params.as<RocketParams>().burn;
        }
    }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const ItemState& state = stateOf(d);
        const World& world = d.run.world();
        const Circle& c = world.circle(state.circle);
        const Thruster& thruster = world.fields().thrusters[static_cast<std::size_t>(state.field)];
        const Vec2 direction = Vec2::fromAngle(item.angle);
        const double t = world.time();
        if (t >= thruster.start && t < thruster.end) drawFlame(c.position, c.radius, direction, t, d.list);
        // Its body with an arrow through it: the way the thrust pushes, lit or not.
        d.list.circle(pt(c.position), static_cast<float>(c.radius), style("box", "ball_outline"));
        d.list.arrow(pt(c.position - direction * (0.7 * c.radius)), pt(c.position + direction * (0.9 * c.radius)), 2.5f,
                     render::Palette::greybox()["explosion"]);
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const float r = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        list.circle(c, 0.7f * r, style("box", "ball_outline"));
        list.arrow({c.x - 0.5f * r, c.y}, {c.x + r, c.y}, 2.0f, render::Palette::greybox()["explosion"]);
    }
};

} // namespace
RUBE_PART(rocket, RocketKind)
} // namespace rube::game::parts
