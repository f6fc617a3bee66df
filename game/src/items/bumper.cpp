// The bumper: a fixed round part with bounciness 1, so a ball leaves it as lively as its own bounciness.
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

struct BumperParams {
    double radius = 0.4; // m
};

constexpr PartKey kKeys[] = {kKindKey, kNameKey, kPositionKey, {"radius", "0.4", "m"}};

class BumperKind final : public PartKind {
public:
    std::string_view name() const override { return "bumper"; }
    int order() const override { return 6; }
    std::string_view summary() const override { return "a fixed round part, radius 0.4 m, bounciness 1"; }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    ItemDesc make(Vec2 position) const override { return made(position, BumperParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        if (const auto r = table.number("radius", kSizeRange)) item.params.as<BumperParams>().radius = *r;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        ItemBodies bodies;
        bodies.circles.push_back(roundPart(item, item.params.as<BumperParams>().radius, 1.0));
        return bodies;
    }
    void draw(const PartDrawing& d) const override {
        const float r = static_cast<float>(itemOf(d).params.as<BumperParams>().radius);
        d.list.circle(pt(d.run.itemPosition(d.item)), r, style("box", "arrow", 3.0f));
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        list.circle(pt(centre), 0.8f * static_cast<float>(0.5 * size), style("box", "arrow", 3.0f));
    }
};

} // namespace
RUBE_PART(bumper, BumperKind)
} // namespace rube::game::parts
