// The scissors: a fixed pair of blades that cut the [[rope]] they name (`cuts`) the first time a ball
// strikes them, or when a switch that names them (or a click) triggers them: the rope is cut on the step
// of the strike (LevelRun::cutRope, after the World's step, before the next).
#include "part_common.hpp"

#include <numbers>

namespace rube::game::parts {
namespace {

struct ScissorsParams {
    double radius = 0.2; // m: the round body a ball strikes
    std::string cuts;    // the [[rope]] they cut
    SourcePlace at;      // where the file wrote `cuts`
    bool given = false;
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             kPositionKey,
                             {"radius", "0.2", "m: what a ball must strike"},
                             {"cuts", "required", "the name of the [[rope]] they cut"}};

class ScissorsKind final : public PartKind {
public:
    std::string_view name() const override { return "scissors"; }
    int order() const override { return 23; }
    int referenceOrder() const override { return 8; } // after the rocket in "cannon, ..., rocket or rope"
    std::string_view summary() const override {
        return "a fixed pair of blades, radius 0.2 m, bounciness 0.3, that cut the rope they name when struck";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool plays(PartRole role) const override { return role == PartRole::triggered; }
    ItemDesc make(Vec2 position) const override { return made(position, ScissorsParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        ScissorsParams& p = item.params.as<ScissorsParams>();
        if (const auto r = table.number("radius", kSizeRange)) p.radius = *r;
        p.cuts = table.string("cuts", Need::required).value_or("");
        p.at = table.valuePlace("cuts");
        p.given = table.find("cuts") != nullptr;
    }
    void checkReferences(const ItemDesc& item, SceneReading& reading) const override {
        const ScissorsParams& p = item.params.as<ScissorsParams>();
        if (!p.given || reading.scene.findRope(p.cuts) >= 0) return;
        std::string known;
        for (const std::string& rope : reading.scene.ropeNames)
            if (!rope.empty()) known += (known.empty() ? "" : ", ") + rope;
        reading.diag.error(
            p.at, "unknown rope '" + p.cuts + "' (" +
                      (known.empty() ? std::string("the level has no named rope") : "the level has: " + known) + ")");
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        ItemBodies bodies;
        bodies.circles.push_back(roundPart(item, item.params.as<ScissorsParams>().radius, 0.3));
        return bodies;
    }
    void hit(LevelRun& run, int item, Vec2 point, const std::string& by) const override {
        if (firstTouch(run, item, point, by)) trigger(run, item);
    }
    void trigger(LevelRun& run, int item) const override {
        ItemState& state = run.partState(item);
        if (state.pressed) return; // they cut once
        state.pressed = true;
        run.cutRope(run.items()[static_cast<std::size_t>(item)].params.as<ScissorsParams>().cuts);
    }
    // Two blades crossed at a pivot, open until they have cut, then closed; a ring for each handle.
    void draw(const PartDrawing& d) const override {
        drawBlades(d.run.itemPosition(d.item), itemOf(d).params.as<ScissorsParams>().radius, !stateOf(d).pressed,
                   d.list);
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        drawBlades(centre, 0.4 * size, true, list);
    }

private:
    static void drawBlades(Vec2 at, double r, bool open, render::DrawList& list) {
        const render::Color steel = render::Palette::greybox()["ground_outline"];
        const double spread = open ? 0.45 : 0.08; // radians either side of the blades' line
        for (const double side : {-1.0, 1.0}) {
            const Vec2 blade = Vec2::fromAngle(side * spread);
            const Vec2 handle = Vec2::fromAngle(std::numbers::pi - side * spread);
            list.line(pt(at), pt(at + blade * r), 2.5f, steel);
            list.line(pt(at), pt(at + handle * (0.55 * r)), 2.0f, steel);
            list.ring(pt(at + handle * (0.75 * r)), static_cast<float>(0.2 * r), 2.0f, steel);
        }
        list.circle(pt(at), static_cast<float>(0.08 * r), style("ground_outline", "ground_outline"));
    }
};

} // namespace
RUBE_PART(scissors, ScissorsKind)
} // namespace rube::game::parts
