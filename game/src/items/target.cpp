// The target: a fixed round mark, or one that follows a kinematic [[path]], that reports the first
// touch of a ball; goals count it.
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

struct TargetParams {
    double radius = 0.3; // m
    int path = -1;       // index of the [[path]] it follows, or -1 (still)
};

constexpr PartKey kKeys[] = {
    kKindKey, kNameKey, kPositionKey, {"radius", "0.3", "m"}, {"path", "none", "the [[path]] it follows"}};

class TargetKind final : public PartKind {
public:
    std::string_view name() const override { return "target"; }
    int order() const override { return 9; }
    int referenceOrder() const override { return 1; }
    std::string_view summary() const override {
        return "a round mark, bounciness 0.5, that reports a ball's first touch; needs a name";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool needsName() const override { return true; }
    bool plays(PartRole role) const override {
        return role == PartRole::aimTarget || role == PartRole::hitReport || role == PartRole::goalTarget;
    }
    ItemDesc make(Vec2 position) const override { return made(position, TargetParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        TargetParams& p = item.params.as<TargetParams>();
        if (const auto r = table.number("radius", kSizeRange)) p.radius = *r;
        if (const auto path = readPathReference(table, reading)) p.path = *path;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const TargetParams& p = item.params.as<TargetParams>();
        ItemBodies bodies;
        bodies.circles.push_back(roundPart(item, p.radius, 0.5, p.path));
        return bodies;
    }
    int path(const ItemDesc& item) const override { return item.params.as<TargetParams>().path; }
    void hit(LevelRun& run, int item, Vec2 point, const std::string& by) const override {
        // Only the first touch is news: a ball resting on a target would report it every step.
        ItemState& state = run.partState(item);
        if (state.hit) return;
        state.hit = true;
        run.report({EventKind::hit, run.steps(), run.world().time(), run.items()[static_cast<std::size_t>(item)].name,
                    point, 0, by});
    }
    void draw(const PartDrawing& d) const override {
        const Vec2 at = d.run.itemPosition(d.item);
        const float r = static_cast<float>(itemOf(d).params.as<TargetParams>().radius);
        d.list.circle(pt(at), r, style(stateOf(d).hit ? "highlight" : "goal", "ground_outline"));
        d.list.ring(pt(at), 0.55f * r, 2.0f, render::Palette::greybox()["background"]);
    }
};

} // namespace
RUBE_PART(target, TargetKind)
} // namespace rube::game::parts
