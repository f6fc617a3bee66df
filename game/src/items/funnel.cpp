// The funnel: two fixed walls that narrow from `width` at the top to an `opening` at the bottom (the gap
// between the walls' faces), `height` tall, its position the middle of the opening. A ball narrower than
// the opening (radius < opening / 2) drops through; a wider one rests in it.
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

constexpr double kWallRadius = 0.04; // m

struct FunnelParams {
    double width = 1.6;   // m, between the walls' faces at the top
    double opening = 0.3; // m, between the walls' faces at the bottom
    double height = 1.0;  // m
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             {"position", "required", "[x, y] m: the middle of its opening"},
                             {"angle", "0", "turn, degrees (0: opening downwards)"},
                             {"width", "1.6", "m, between the walls at the top"},
                             {"opening", "0.3", "m, between the walls at the bottom: balls narrower pass"},
                             {"height", "1", "m"}};

class FunnelKind final : public PartKind {
public:
    std::string_view name() const override { return "funnel"; }
    int order() const override { return 25; }
    std::string_view summary() const override {
        return "two fixed walls, bounciness 0.3, narrowing to an opening of 0.3 m: only balls under it pass";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; }
    ItemDesc make(Vec2 position) const override { return made(position, FunnelParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        FunnelParams& p = item.params.as<FunnelParams>();
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto w = table.number("width", kSizeRange)) p.width = *w;
        if (const auto o = table.number("opening", kSizeRange)) p.opening = *o;
        if (const auto h = table.number("height", kSizeRange)) p.height = *h;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const FunnelParams& p = item.params.as<FunnelParams>();
        const Vec2 x = Vec2::fromAngle(item.angle), y = x.perpendicular();
        ItemBodies bodies;
        for (const double side : {-1.0, 1.0}) {
            // Segment centres a wall radius outside the faces, so the faces are `opening` and `width` apart.
            const Vec2 bottom = item.position + x * (side * (0.5 * p.opening + kWallRadius));
            const Vec2 top = item.position + x * (side * (0.5 * p.width + kWallRadius)) + y * p.height;
            bodies.segments.push_back({bottom, top, kWallRadius, bouncy(0.3), -1});
        }
        return bodies;
    }
    void draw(const PartDrawing& d) const override { (void)d; } // its walls are the world's boards
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const double s = 0.4 * size;
        const render::Color ink = render::Palette::greybox()["ground_outline"];
        list.line(pt(centre + Vec2{-s, s}), pt(centre + Vec2{-0.2 * s, -s}), 3.0f, ink);
        list.line(pt(centre + Vec2{s, s}), pt(centre + Vec2{0.2 * s, -s}), 3.0f, ink);
    }
};

} // namespace
RUBE_PART(funnel, FunnelKind)
} // namespace rube::game::parts
