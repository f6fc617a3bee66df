// The peg: a small fixed round pin, lively enough to kick a ball aside (a pin bumper). Fixed in a
// level, not placed: a row of them turns a drop into a chain of deflections.
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

constexpr double kBounciness = 0.8; // a pair's bounciness is the product of both (lecture 3)

struct PegParams {
    double radius = 0.12; // m
};

constexpr PartKey kKeys[] = {kKindKey, kNameKey, kPositionKey, {"radius", "0.12", "m"}};

class PegKind final : public PartKind {
public:
    std::string_view name() const override { return "peg"; }
    int order() const override { return 15; }
    std::string_view summary() const override { return "a small fixed round pin, radius 0.12 m, bounciness 0.8"; }
    std::span<const PartKey> keys() const override { return kKeys; }
    ItemDesc make(Vec2 position) const override { return made(position, PegParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        if (const auto r = table.number("radius", kSizeRange)) item.params.as<PegParams>().radius = *r;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        ItemBodies bodies;
        bodies.circles.push_back(roundPart(item, item.params.as<PegParams>().radius, kBounciness));
        return bodies;
    }
    // A brass pin: a light head with a dark rim, and a dot where it is fixed.
    void draw(const PartDrawing& d) const override {
        const Vec2 at = d.run.itemPosition(d.item);
        const float r = static_cast<float>(itemOf(d).params.as<PegParams>().radius);
        d.list.circle(pt(at), r, style("highlight", "ground_outline", 2.0f));
        d.list.circle(pt(at), 0.3f * r, style("ground_outline", "ground_outline"));
    }
};

} // namespace
RUBE_PART(peg, PegKind)
} // namespace rube::game::parts
