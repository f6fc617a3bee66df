// The fan: a housing that blows a column of air along its angle; a ball whose centre is in the column
// feels drag relative to the moving air. A switch, click or script turns it off and on.
#include "part_common.hpp"

#include "script_file.hpp"

#include <algorithm>
#include <cmath>

namespace rube::game::parts {
namespace {

constexpr double kFanDrag = 3.0;     // drag per metre of a ball's width, N s/m^2
constexpr double kWindSpacing = 0.8; // m between the drawn arrows, along and across the column
constexpr double kWindArrow = 0.35;  // m: each arrow's length

struct FanParams {
    double width = 1.2;  // m
    double speed = 10.0; // air speed, m/s
    double reach = 5.0;  // length of its air column, m
    bool on = true;      // blowing from the start
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             {"position", "required", "[x, y] m: the housing's centre"},
                             {"angle", "0", "the way it blows, degrees"},
                             {"width", "1.2", "m"},
                             {"speed", "10", "air speed, m/s"},
                             {"reach", "5", "length of the air column, m"},
                             {"on", "true", "blowing from the start (a switch flips it)"}};

// The housing: a board across its face, `width` wide, turned to blow along its angle.
std::pair<Vec2, Vec2> housing(const ItemDesc& item) {
    const Vec2 across = Vec2::fromAngle(item.angle).perpendicular() * (0.5 * item.params.as<FanParams>().width);
    return {item.position - across, item.position + across};
}

// The air as rows of arrows drifting along the column at the air's speed, so a still frame shows
// where it blows and a sequence shows that it moves. The drift is a function of world time only.
void drawWind(const Wind& wind, double time, render::DrawList& list) {
    const render::Color color = render::Palette::greybox()["wind"];
    const Vec2 across = wind.direction.perpendicular();
    const int rows = std::max(1, static_cast<int>(wind.width / (0.6 * kWindSpacing)));
    const double drift = std::fmod(time * wind.speed, kWindSpacing);
    for (int row = 0; row < rows; ++row) {
        const double offset = (row + 0.5) * wind.width / rows - 0.5 * wind.width;
        for (double along = drift; along + kWindArrow <= wind.length; along += kWindSpacing) {
            const Vec2 tail = wind.origin + across * offset + wind.direction * along;
            list.arrow(pt(tail), pt(tail + wind.direction * kWindArrow), 2.0f, color);
        }
    }
}

class FanKind final : public PartKind {
public:
    std::string_view name() const override { return "fan"; }
    int order() const override { return 13; }
    int referenceOrder() const override { return 5; }
    std::string_view summary() const override { return "a fixed housing, bounciness 0.3, blowing a column of air"; }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; }
    bool plays(PartRole role) const override { return role == PartRole::toggle || role == PartRole::triggered; }
    ItemDesc make(Vec2 position) const override { return made(position, FanParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        FanParams& p = item.params.as<FanParams>();
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto w = table.number("width", kSizeRange)) p.width = *w;
        if (const auto s = table.number("speed", NumberRange{0.0, 100.0, true})) p.speed = *s;
        if (const auto r = table.number("reach", kSizeRange)) p.reach = *r;
        if (const auto on = table.boolean("on")) p.on = *on;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const FanParams& p = item.params.as<FanParams>();
        const auto [a, b] = housing(item);
        ItemBodies bodies;
        bodies.segments.push_back({a, b, kBoardRadius, bouncy(0.3), -1});
        // The air column starts at the housing's face, so a ball resting on the housing is not blown through it.
        Wind wind;
        wind.direction = Vec2::fromAngle(item.angle);
        wind.origin = item.position + wind.direction * kBoardRadius;
        wind.length = p.reach;
        wind.width = p.width;
        wind.speed = p.speed;
        wind.drag = kFanDrag;
        wind.on = p.on;
        bodies.wind = wind;
        return bodies;
    }
    // A click anywhere on its housing's box picks it.
    bool picked(const ItemDesc& item, Vec2 at, Vec2 cursor, double tolerance) const override {
        (void)at, (void)tolerance;
        return extent(item).contains(cursor);
    }
    double speedGiven(const ItemDesc& item, double lightest, double g, double seconds) const override {
        (void)lightest, (void)g, (void)seconds;
        return item.params.as<FanParams>().speed;
    }
    void trigger(LevelRun& run, int item) const override {
        run.partWorld()
            .fields()
            .winds[static_cast<std::size_t>(run.states()[static_cast<std::size_t>(item)].field)]
            .on ^= true;
    }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const World& world = d.run.world();
        const Wind& wind = world.fields().winds[static_cast<std::size_t>(stateOf(d).field)];
        // The motor sits behind the housing (drawn with the segments), on the side the air comes from.
        const Vec2 back = item.position - wind.direction * 0.2;
        d.list.box(pt(back), {0.2f, static_cast<float>(0.25 * item.params.as<FanParams>().width)},
                   static_cast<float>(item.angle), style(wind.on ? "box" : "ground", "box_outline"));
        if (wind.on) drawWind(wind, world.time(), d.list);
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const float r = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        list.box({c.x - 0.5f * r, c.y}, {0.25f * r, 0.8f * r}, 0.0f, style("box", "box_outline"));
        list.arrow({c.x - 0.1f * r, c.y}, {c.x + r, c.y}, 2.0f, render::Palette::greybox()["arrow"]);
    }
};

} // namespace
RUBE_PART(fan, FanKind)
} // namespace rube::game::parts
