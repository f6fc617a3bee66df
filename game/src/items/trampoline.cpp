// The trampoline: a springy bed on two legs that the player lays and turns. What its C means: the bed
// is a surface of bounciness C_bed (key `bounciness`, default 1: the bed's springs give back all they
// store), and, as for every pair (lecture 3), a ball of bounciness C_ball leaves it with
// C = C_bed x C_ball of its speed along the bed's normal, v_n' = -C v_n; along the bed (frictionless)
// its speed is kept. So a trampoline returns C_bed x C_ball of the impact speed: a tennis ball dropped
// on the default bed climbs back to C_ball^2 of its drop, a bowling ball hardly at all.
// Its legs (bounciness 0.3) splay down from the bed's ends, on the side its angle leaves below.
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

constexpr double kLegBounciness = 0.3;
constexpr double kLegLength = 0.4;   // m, from the bed's end to the foot
constexpr double kLegSplay = 0.15;   // m, how far each foot stands out beyond its end of the bed
constexpr double kBedRadius = 0.04;  // m, half the bed's thickness
constexpr double kLegRadius = 0.025; // m
constexpr int kSprings = 6;          // zigzag springs drawn under the bed

struct TrampolineParams {
    double length = 1.5;     // m, between the bed's end caps' centres
    double bounciness = 1.0; // C_bed
};

constexpr PartKey kKeys[] = {kKindKey,
                             kNameKey,
                             kPositionKey,
                             {"angle", "0", "tilt of the bed, degrees; its legs stand on the side below"},
                             {"length", "1.5", "m, the bed between its end caps' centres"},
                             {"bounciness", "1", "C_bed: a ball leaves at C_bed x C_ball of its normal speed"}};

// The bed's two ends and the way "down" from it (its legs' side), for a trampoline at its angle.
struct Bed {
    Vec2 a, b, down;
};
Bed bedOf(const ItemDesc& item) {
    const Vec2 along = Vec2::fromAngle(item.angle);
    const Vec2 half = along * (0.5 * item.params.as<TrampolineParams>().length);
    return {item.position - half, item.position + half, -along.perpendicular()};
}

class TrampolineKind final : public PartKind {
public:
    std::string_view name() const override { return "trampoline"; }
    int order() const override { return 19; }
    std::string_view summary() const override {
        return "a springy bed on legs, 1.5 m long, bounciness 1: a ball leaves at C_bed x C_ball of its normal speed";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    bool placeable() const override { return true; }
    bool turns() const override { return true; }
    double turnPeriod() const override { return 360.0; } // its legs stand on one side
    ItemDesc make(Vec2 position) const override { return made(position, TrampolineParams{}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        TrampolineParams& p = item.params.as<TrampolineParams>();
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto l = table.number("length", kSizeRange)) p.length = *l;
        if (const auto c = table.number("bounciness", NumberRange::unit())) p.bounciness = *c;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const Bed bed = bedOf(item);
        const Vec2 along = (bed.b - bed.a).normalized();
        ItemBodies bodies;
        bodies.segments.push_back(
            {bed.a, bed.b, kBedRadius, bouncy(item.params.as<TrampolineParams>().bounciness), -1});
        bodies.segments.push_back(
            {bed.a, bed.a + bed.down * kLegLength - along * kLegSplay, kLegRadius, bouncy(kLegBounciness), -1});
        bodies.segments.push_back(
            {bed.b, bed.b + bed.down * kLegLength + along * kLegSplay, kLegRadius, bouncy(kLegBounciness), -1});
        return bodies;
    }
    // The bed and legs are drawn with the world's segments; under the bed, a row of zigzag springs
    // from the bed to a rail between the legs, so it reads as a trampoline and not a plank.
    void draw(const PartDrawing& d) const override { drawSprings(bedOf(itemOf(d)), d.list); }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const double r = 0.4 * size;
        const Bed bed{centre + Vec2{-r, 0.25 * r}, centre + Vec2{r, 0.25 * r}, {0.0, -1.0}};
        const render::Style frame = style("ground", "ground_outline");
        list.capsule(pt(bed.a), pt(bed.b), 0.06f * static_cast<float>(r), frame);
        list.line(pt(bed.a), pt(bed.a + Vec2{-0.15 * r, -0.6 * r}), 2.0f, render::Palette::greybox()["ground_outline"]);
        list.line(pt(bed.b), pt(bed.b + Vec2{0.15 * r, -0.6 * r}), 2.0f, render::Palette::greybox()["ground_outline"]);
        drawSprings(bed, list, 0.25 * r / kLegLength);
    }

private:
    // Springs hang from the bed to a rail `drop` below it (scaled with the icon).
    static void drawSprings(const Bed& bed, render::DrawList& list, double scale = 1.0) {
        const render::Color ink = render::Palette::greybox()["ground_outline"];
        const Vec2 drop = bed.down * (0.5 * kLegLength * scale);
        const Vec2 step = (bed.b - bed.a) / static_cast<double>(kSprings + 1);
        const Vec2 side = step * 0.2;
        list.line(pt(bed.a + drop + step * 0.5), pt(bed.b + drop - step * 0.5), 1.5f, ink);
        for (int i = 1; i <= kSprings; ++i) {
            const Vec2 top = bed.a + step * static_cast<double>(i);
            std::array<render::Point, 6> zigzag{};
            for (std::size_t k = 0; k < zigzag.size(); ++k) {
                const double t = static_cast<double>(k) / (zigzag.size() - 1);
                const double wiggle = (k == 0 || k + 1 == zigzag.size()) ? 0.0 : (k % 2 ? 1.0 : -1.0);
                zigzag[k] = pt(top + drop * t + side * wiggle);
            }
            list.polyline(zigzag, 1.0f, ink);
        }
    }
};

} // namespace
RUBE_PART(trampoline, TrampolineKind)
} // namespace rube::game::parts
