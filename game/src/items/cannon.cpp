// The cannon: scenery that shoots a ball of its ammo kind from its pivot, at its aim and muzzle
// speed, when a switch, a click, a script or its fire_at time says so.
#include "part_common.hpp"

#include "script_file.hpp"

#include "rube/physics/aim.hpp"

namespace rube::game::parts {
namespace {

// The barrel's length, m: what the cannon takes of the room, how near a click picks it, and how it is drawn.
constexpr double kBarrelLength = 0.6;
constexpr double kBarrelHalfWidth = 0.1; // m
constexpr float kArcWidth = 2.0f;        // pixels: the predicted arc
constexpr double kArcSeconds = 3.0;      // how far ahead the predicted arc looks
constexpr int kArcPoints = 60;

struct CannonParams {
    double speed = 8.0;           // muzzle speed, m/s
    ItemKind ammo = nullptr;      // the ball kind it shoots
    std::optional<double> fireAt; // fires by itself at this time, s
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             kPositionKey,
                             {"angle", "0", "aim, degrees"},
                             {"speed", "8", "muzzle speed, m/s"},
                             {"ammo", "heavy", "the ball kind it shoots"},
                             {"fire_at", "none", "fires by itself at this time, s"}};

std::vector<std::string_view> ballNames() {
    std::vector<std::string_view> names;
    for (ItemKind kind : allPartKinds())
        if (kind->isBall()) names.push_back(kind->name());
    return names;
}

class CannonKind final : public PartKind {
public:
    std::string_view name() const override { return "cannon"; }
    int order() const override { return 7; }
    int referenceOrder() const override { return 0; }
    std::string_view summary() const override {
        return "a fixed cannon (no body: its shots must not hit its own barrel); needs a name";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool needsName() const override { return true; }
    bool plays(PartRole role) const override { return role == PartRole::fire || role == PartRole::triggered; }
    ItemDesc make(Vec2 position) const override {
        return made(position, CannonParams{8.0, partKind("heavy"), std::nullopt});
    }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        CannonParams& p = item.params.as<CannonParams>();
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto s = table.number("speed", NumberRange{0.0, 1000.0, true})) p.speed = *s;
        const auto names = ballNames();
        if (const auto ammo = table.choice("ammo", names)) p.ammo = partKind(names[*ammo]);
        if (const auto t = table.number("fire_at", NumberRange::nonNegative())) p.fireAt = *t;
    }
    ItemBodies bodies(const ItemDesc& item) const override { return (void)item, ItemBodies{}; }
    ItemBodies room(const ItemDesc& item) const override {
        ItemBodies barrel;
        CircleDef reach;
        reach.position = item.position;
        reach.radius = kBarrelLength;
        barrel.circles.push_back(reach);
        return barrel;
    }
    std::optional<CircleDef> shot(const ItemDesc& item) const override {
        const ItemKind ammo = item.params.as<CannonParams>().ammo;
        return ammo->shot(ammo->make(item.position));
    }
    double muzzleSpeed(const ItemDesc& item) const override { return item.params.as<CannonParams>().speed; }
    double speedGiven(const ItemDesc& item, double lightest, double g, double seconds) const override {
        (void)lightest, (void)g, (void)seconds;
        return muzzleSpeed(item);
    }
    void afterStep(LevelRun& run, int item) const override {
        const auto& fireAt = run.items()[static_cast<std::size_t>(item)].params.as<CannonParams>().fireAt;
        if (fireAt && !run.states()[static_cast<std::size_t>(item)].fired && timeReached(run.world(), *fireAt))
            run.fire(item);
    }
    bool waits(const ItemDesc& item, const ItemState& state) const override {
        return (item.params.as<CannonParams>().fireAt && !state.fired) || state.timedShot.has_value();
    }
    void trigger(LevelRun& run, int item) const override { run.fire(item); }
    std::optional<ActionKind> clickAction() const override { return ActionKind::fire; }
    std::string spent(const ItemDesc& item, const ItemState& state) const override {
        return state.fired ? item.name + " has fired already" : "";
    }
    void draw(const PartDrawing& d) const override {
        // The barrel turns to the aim; before the shot, the arc it would fly is drawn.
        const ItemDesc& item = itemOf(d);
        const ItemState& state = stateOf(d);
        const World& world = d.run.world();
        const render::Palette& palette = render::Palette::greybox();
        const Vec2 dir = Vec2::fromAngle(state.aim);
        if (!state.fired) {
            const auto arc = predictedArc(item.position, d.run.launchVelocity(d.item), world.def().gravity, kArcSeconds,
                                          kArcPoints, world.def().bounds);
            std::vector<render::Point> points;
            for (Vec2 p : arc) points.push_back(pt(p));
            if (points.size() >= 2) d.list.polyline(points, kArcWidth, palette["arrow"], palette["arrow"].withAlpha(0));
        }
        d.list.box(pt(item.position + dir * (0.5 * kBarrelLength)),
                   {static_cast<float>(0.5 * kBarrelLength), static_cast<float>(kBarrelHalfWidth)},
                   static_cast<float>(state.aim), style("box", "box_outline"));
        d.list.circle(pt(item.position), 0.25f, style("ground", "ground_outline"));
    }
};

} // namespace
RUBE_PART(cannon, CannonKind)
} // namespace rube::game::parts
