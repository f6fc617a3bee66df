// The crate: a wooden box the player places and turns, a rigid body that slides, tips and is knocked
// about (solved by `auto`). Made as a pine crate half a metre a side, 10 kg, bounciness 0.2 and
// friction 0.4 (dry wood on wood: engineering tables give 0.25 to 0.5); on a floor of friction mu_f
// the pair's mu is 0.4 x mu_f, so a crate sliding at v stops after v^2 / (2 mu g).
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             kPositionKey,
                             {"angle", "0", "tilt, degrees"},
                             {"size", "[0.5, 0.5]", "[width, height] m"},
                             {"mass", "10", "kg"},
                             {"friction", "0.4", "Coulomb mu; a pair's mu is the product of both"},
                             {"velocity", "[0, 0]", "initial velocity, m/s"}};

class CrateKind final : public LooseBoxKind {
public:
    std::string_view name() const override { return "crate"; }
    int order() const override { return 20; }
    std::string_view summary() const override {
        return "a wooden box 0.5 m a side, 10 kg, bounciness 0.2, friction 0.4, that slides and tips";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        readPose(table, item);
        LooseBoxParams& p = item.params.as<LooseBoxParams>();
        if (const auto size = table.vec2("size", kSizeRange)) p.size = *size;
        if (const auto m = table.number("mass", NumberRange{0.0, 1e6, true})) p.mass = *m;
        if (const auto mu = table.number("friction", NumberRange{0.0, 10.0})) p.material.friction = *mu;
    }
    // Slats: a frame inset from the box's edges and a brace across it, turning with it.
    void draw(const PartDrawing& d) const override {
        const RigidBody& b = bodyOf(d);
        drawSlats(b.position, b.halfExtents, b.angle, d.list);
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        render::Style look = style("box", "box_outline");
        if (!available) look.fill = look.fill.withAlpha(0x60);
        const Vec2 half{0.35 * size, 0.35 * size};
        list.box(pt(centre), pt(half), 0.0f, look);
        drawSlats(centre, half, 0.0, list);
    }

protected:
    LooseBoxParams defaults() const override {
        LooseBoxParams p;
        p.size = {0.5, 0.5};
        p.mass = 10.0;
        p.material.bounciness = 0.2;
        p.material.friction = 0.4;
        return p;
    }

private:
    static void drawSlats(Vec2 centre, Vec2 half, double angle, render::DrawList& list) {
        const render::Color ink = render::Palette::greybox()["box_outline"];
        const Vec2 x = Vec2::fromAngle(angle), y = x.perpendicular();
        const Vec2 inner = half * 0.8;
        const auto corner = [&](double sx, double sy) { return pt(centre + x * (sx * inner.x) + y * (sy * inner.y)); };
        const std::array<render::Point, 5> frame{corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1),
                                                 corner(-1, -1)};
        list.polyline(frame, 1.0f, ink);
        list.line(corner(-1, -1), corner(1, 1), 1.0f, ink);
    }
};

} // namespace
RUBE_PART(crate, CrateKind)
} // namespace rube::game::parts
