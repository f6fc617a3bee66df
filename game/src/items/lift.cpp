// The lift: a level platform that stands still until it is switched (by a trigger, a click or a
// script), then rides the engine's kinematic path from where it is by `travel` at `speed`, and
// stays there. As a kinematic segment it has infinite mass: what stands on it is pushed up with it
// (lecture 3's wall with a velocity: a ball on it leaves with the platform's speed, not less).
#include "part_common.hpp"

#include "script_file.hpp"

#include <cmath>

namespace rube::game::parts {
namespace {

struct LiftParams {
    double width = 1.5;    // m, between its end caps' centres
    Vec2 travel{0.0, 3.0}; // m, from where it stands to where it stops
    double speed = 1.0;    // m/s along its travel
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             {"position", "required", "[x, y] m: the platform's centre where it stands"},
                             {"width", "1.5", "m"},
                             {"travel", "[0, 3]", "[dx, dy] m: where it goes once switched, from where it stands"},
                             {"speed", "1", "m/s along its travel"}};

std::pair<Vec2, Vec2> platformEnds(const ItemDesc& item) {
    const Vec2 half{0.5 * item.params.as<LiftParams>().width, 0.0};
    return {item.position - half, item.position + half};
}

// Seconds from its start to its stop.
double rideTime(const LiftParams& p) { return p.travel.length() / p.speed; }

class LiftKind final : public PartKind {
public:
    std::string_view name() const override { return "lift"; }
    int order() const override { return 46; }
    std::string_view summary() const override {
        return "a level platform, bounciness 0.2, that rides its travel at a set speed once switched";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool plays(PartRole role) const override { return role == PartRole::toggle || role == PartRole::triggered; }
    ItemDesc make(Vec2 position) const override { return made(position, LiftParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        LiftParams& p = item.params.as<LiftParams>();
        if (const auto w = table.number("width", kSizeRange)) p.width = *w;
        if (const auto t = table.vec2("travel", NumberRange{-kMaxItemSize, kMaxItemSize})) p.travel = *t;
        if (const auto s = table.number("speed", NumberRange{0.0, 100.0, true})) p.speed = *s;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const auto [a, b] = platformEnds(item);
        ItemBodies bodies;
        bodies.segments.push_back({a, b, kBoardRadius, bouncy(0.2), -1});
        return bodies;
    }
    // A moving wall: a bounce off it gains at most twice its speed, and it lifts (adds energy).
    double speedGiven(const ItemDesc& item, double lightest, double g, double seconds) const override {
        (void)lightest, (void)g, (void)seconds;
        return 2.0 * item.params.as<LiftParams>().speed;
    }
    bool picked(const ItemDesc& item, Vec2 at, Vec2 cursor, double tolerance) const override {
        (void)at, (void)tolerance;
        return extent(item).contains(cursor);
    }
    // Switched: once. The still platform is replaced by the same segment on a path that holds it
    // until now, then moves it in a straight line by `travel` in |travel| / speed seconds.
    void trigger(LevelRun& run, int item) const override {
        ItemState& state = run.partState(item);
        if (state.since) return;
        const ItemDesc& desc = run.items()[static_cast<std::size_t>(item)];
        const LiftParams& p = desc.params.as<LiftParams>();
        World& world = run.partWorld();
        const auto [a, b] = platformEnds(desc);
        const auto segments = world.segments();
        for (std::size_t i = 0; i < segments.size(); ++i) {
            if (segments[i].a != a || segments[i].b != b || segments[i].path >= 0) continue;
            world.remove(world.segmentId(static_cast<int>(i)));
            break;
        }
        const double now = world.time();
        KinematicPath path;
        path.keys = {{now, {}, 0.0}, {now + rideTime(p), p.travel, 0.0}};
        SegmentDef platform = bodies(desc).segments.front();
        platform.path = world.addPath(std::move(path));
        world.addSegment(platform);
        state.since = now;
    }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    std::string spent(const ItemDesc& item, const ItemState& state) const override {
        return state.since ? item.name + " has been switched already" : "";
    }
    // Its travel as a faint guide with an arrow, and a post under its start; the platform itself is
    // drawn with the world's segments.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const LiftParams& p = item.params.as<LiftParams>();
        const render::Palette& palette = render::Palette::greybox();
        const Vec2 end = item.position + p.travel;
        d.list.line(pt(item.position), pt(end), 1.0f, palette["wire"]);
        const Vec2 back = p.travel.normalized() * std::min(0.3, p.travel.length());
        d.list.arrow(pt(end - back), pt(end), 2.0f, palette["arrow"]);
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const float r = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        list.capsule({c.x - 0.8f * r, c.y - 0.6f * r}, {c.x + 0.8f * r, c.y - 0.6f * r}, 0.1f * r,
                     style("kinematic", "kinematic_outline"));
        list.arrow({c.x, c.y - 0.4f * r}, {c.x, c.y + 0.8f * r}, 2.0f, render::Palette::greybox()["arrow"]);
    }
};

} // namespace
RUBE_PART(lift, LiftKind)
} // namespace rube::game::parts
