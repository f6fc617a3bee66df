// The mirror: a placeable, turnable flat board off whose faces a laser's beam reflects by the
// reflect formula r = d - 2 (d.n) n (and off whose rounded ends it reflects about the end's normal).
// Balls bounce off it as off a plank.
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

constexpr auto kKeys = boardKeys("1");

class MirrorKind final : public BoardKind {
public:
    std::string_view name() const override { return "mirror"; }
    int order() const override { return 44; }
    std::string_view summary() const override {
        return "a fixed flat mirror, 1 m long, bounciness 0.3, that a laser's beam reflects off";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool reflects() const override { return true; }
    // The silvered face: a light stripe along the board the world draws.
    void draw(const PartDrawing& d) const override {
        const ItemDesc& item = itemOf(d);
        const Vec2 half = Vec2::fromAngle(item.angle) * (0.5 * item.params.as<BoardParams>().length);
        d.list.line(pt(item.position - half), pt(item.position + half), 2.0f, render::Palette::greybox()["ball"]);
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const Vec2 half = Vec2::fromAngle(0.25 * std::numbers::pi) * (0.4 * size);
        list.capsule(pt(centre - half), pt(centre + half), static_cast<float>(kBoardRadius * size),
                     style("ground", "ground_outline"));
        list.line(pt(centre - half), pt(centre + half), 2.0f, render::Palette::greybox()["ball"]);
    }

protected:
    double length() const override { return 1.0; }
    double bounciness() const override { return 0.3; }
};

} // namespace
RUBE_PART(mirror, MirrorKind)
} // namespace rube::game::parts
