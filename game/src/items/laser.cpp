// The laser: a fixed emitter whose beam, while it is on, runs from its muzzle along its angle and is
// cast again each step against the World's circles and segments (rayCast): off a part that reflects
// (a mirror) it leaves by the reflect formula r = d - 2 (d.n) n (lecture 3's reflection with C = 1),
// and it stops at the first anything else it meets. A part it stops on is told (a detector
// switches). On at the start (on = true, the default), or switched on by a trigger, click or script;
// each switch flips it.
#include "part_common.hpp"

#include "script_file.hpp"

#include "rube/physics/ray_cast.hpp"

#include <vector>

namespace rube::game::parts {
namespace {

constexpr double kRadius = 0.25;    // the housing, m
constexpr double kReach = 200.0;    // the longest beam, m: far past any level
constexpr int kMaxReflections = 64; // a beam caught between facing mirrors ends here

struct LaserParams {
    bool on = true; // shining from the start
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             {"position", "required", "[x, y] m: the housing's centre"},
                             {"angle", "0", "the way it shines, degrees"},
                             {"on", "true", "shining from the start; false: a switch, click or trigger turns it on"}};

// A beam's path: the muzzle, each reflection, and where it stopped (and on what).
struct Beam {
    std::vector<Vec2> points;
    std::optional<RayHit> stop; // what it stopped on, if anything within its reach
};

bool isOn(const ItemDesc& item, const ItemState& state) { return item.params.as<LaserParams>().on != state.pressed; }

// True when World segment `slot` is a reflecting part's (the parts' segments are fixed, so their ends
// are the very numbers their kind made).
bool reflects(const LevelRun& run, int slot) {
    const Segment& s = run.world().segments()[static_cast<std::size_t>(slot)];
    for (const ItemDesc& item : run.items()) {
        if (!item.kind->reflects()) continue;
        for (const SegmentDef& mirror : item.kind->bodies(item).segments)
            if (mirror.a == s.a && mirror.b == s.b) return true;
    }
    return false;
}

// The beam of laser `item` as the world is now.
Beam castBeam(const LevelRun& run, int item) {
    const ItemDesc& laser = run.items()[static_cast<std::size_t>(item)];
    Vec2 direction = Vec2::fromAngle(laser.angle);
    Vec2 from = run.itemPosition(item) + direction * kRadius;
    double left = kReach;
    Beam beam;
    beam.points.push_back(from);
    for (int i = 0; i <= kMaxReflections; ++i) {
        const auto hit = rayCast(run.world(), from, direction, left);
        if (!hit) {
            beam.points.push_back(from + direction * left);
            return beam;
        }
        beam.points.push_back(hit->point);
        if (hit->shape != RayHit::Shape::segment || !reflects(run, hit->slot)) {
            beam.stop = hit;
            return beam;
        }
        // r = d - 2 (d.n) n: the angle of incidence is the angle of reflection.
        direction = direction.reflected(hit->normal, 1.0);
        from = hit->point;
        left -= hit->distance;
    }
    return beam;
}

class LaserKind final : public PartKind {
public:
    std::string_view name() const override { return "laser"; }
    int order() const override { return 43; }
    std::string_view summary() const override {
        return "a fixed emitter whose beam reflects off mirrors and stops at anything else";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool plays(PartRole role) const override { return role == PartRole::toggle || role == PartRole::triggered; }
    ItemDesc make(Vec2 position) const override { return made(position, LaserParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto on = table.boolean("on")) item.params.as<LaserParams>().on = *on;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        ItemBodies bodies;
        bodies.circles.push_back(roundPart(item, kRadius, 0.3));
        return bodies;
    }
    // The beam is cast after the step, against the world the step left: what it stops on is told.
    void afterStep(LevelRun& run, int item) const override {
        const ItemDesc& desc = run.items()[static_cast<std::size_t>(item)];
        if (!isOn(desc, run.states()[static_cast<std::size_t>(item)])) return;
        const Beam beam = castBeam(run, item);
        if (!beam.stop || beam.stop->shape != RayHit::Shape::circle) return;
        const int reached = run.itemOf(run.world().circleId(beam.stop->slot));
        if (reached >= 0)
            run.items()[static_cast<std::size_t>(reached)].kind->beamReached(run, reached, beam.stop->point, desc.name);
    }
    void trigger(LevelRun& run, int item) const override { run.partState(item).pressed ^= true; }
    std::optional<ActionKind> clickAction() const override { return ActionKind::toggle; }
    // The housing with its barrel, and the beam through each reflection while it shines.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const bool on = isOn(item, stateOf(d));
        const Vec2 at = d.run.itemPosition(d.item);
        const Vec2 along = Vec2::fromAngle(item.angle);
        if (on) {
            const Beam beam = castBeam(d.run, d.item);
            std::vector<render::Point> points;
            for (const Vec2 p : beam.points) points.push_back(pt(p));
            d.list.polyline(points, 3.0f, render::Palette::greybox()["laser"]);
        }
        d.list.box(pt(at + along * (0.5 * kRadius)), {static_cast<float>(kRadius), 0.4f * static_cast<float>(kRadius)},
                   static_cast<float>(item.angle), style("ground_outline", "ball_outline"));
        d.list.circle(pt(at), static_cast<float>(kRadius), style(on ? "laser" : "ground", "ball_outline", 2.0f));
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const float r = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        list.line({c.x, c.y}, {c.x + r, c.y}, 3.0f, render::Palette::greybox()["laser"]);
        list.box({c.x - 0.3f * r, c.y}, {0.45f * r, 0.2f * r}, 0.0f, style("ground_outline", "ball_outline"));
        list.circle({c.x - 0.5f * r, c.y}, 0.35f * r, style("laser", "ball_outline", 2.0f));
    }
};

} // namespace
RUBE_PART(laser, LaserKind)
} // namespace rube::game::parts
