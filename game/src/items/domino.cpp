// The domino: a tall thin block the player stands up in rows, a rigid body that tips when pushed past
// its tipping angle atan(thickness / height) and knocks the next one over (solved by `auto`). A giant
// wooden domino in a standard domino's proportions (48 x 24 x 7.5 mm) scaled to `height` (0.5 m):
// thickness 7.5/48 of its height (0.078 m), depth half of it, pine at 500 kg/m^3, so
// m = 500 x h x (h / 2) x (7.5 h / 48) (4.88 kg at 0.5 m); tipping angle atan(7.5 / 48) = 8.88 degrees.
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

constexpr double kThicknessPerHeight = 7.5 / 48.0; // a standard domino's proportions
constexpr double kDepthPerHeight = 24.0 / 48.0;
constexpr double kDensity = 500.0; // kg/m^3, pine

LooseBoxParams dominoOf(double height) {
    LooseBoxParams p;
    p.size = {kThicknessPerHeight * height, height};
    p.mass = kDensity * height * (kDepthPerHeight * height) * (kThicknessPerHeight * height);
    p.material.bounciness = 0.2;
    p.material.friction = 0.4; // dry wood on wood, as the crate
    return p;
}

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             kPositionKey,
                             {"angle", "0", "tilt from upright, degrees"},
                             {"height", "0.5", "m; thickness 7.5/48 of it, mass 500 kg/m^3 x h x h/2 x 7.5h/48"},
                             {"velocity", "[0, 0]", "initial velocity, m/s"}};

class DominoKind final : public LooseBoxKind {
public:
    std::string_view name() const override { return "domino"; }
    int order() const override { return 21; }
    std::string_view summary() const override {
        return "a giant wooden domino, 0.5 m tall and 0.078 m thick, 4.88 kg, that tips past 8.88 degrees";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        readPose(table, item);
        if (const auto h = table.number("height", kSizeRange)) {
            const Vec2 velocity = item.params.as<LooseBoxParams>().velocity;
            item.params.as<LooseBoxParams>() = dominoOf(*h);
            item.params.as<LooseBoxParams>().velocity = velocity;
        }
    }
    // Its face: a line across the middle and a pip in each half, turning with it.
    void draw(const PartDrawing& d) const override {
        const RigidBody& b = bodyOf(d);
        drawFace(b.position, b.halfExtents, b.angle, d.list);
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        render::Style look = style("box", "box_outline");
        if (!available) look.fill = look.fill.withAlpha(0x60);
        const Vec2 half{0.2 * size, 0.4 * size}; // wider than it is, so the face shows
        list.box(pt(centre), pt(half), 0.0f, look);
        drawFace(centre, half, 0.0, list);
    }

protected:
    LooseBoxParams defaults() const override { return dominoOf(0.5); }

private:
    static void drawFace(Vec2 centre, Vec2 half, double angle, render::DrawList& list) {
        const render::Color ink = render::Palette::greybox()["box_outline"];
        const Vec2 x = Vec2::fromAngle(angle), y = x.perpendicular();
        list.line(pt(centre - x * (0.7 * half.x)), pt(centre + x * (0.7 * half.x)), 1.0f, ink);
        const render::Style pip = style("box_outline", "box_outline", 0.0f);
        for (const double side : {-0.5, 0.5})
            list.circle(pt(centre + y * (side * half.y)), 0.45f * static_cast<float>(half.x), pip);
    }
};

} // namespace
RUBE_PART(domino, DominoKind)
} // namespace rube::game::parts
