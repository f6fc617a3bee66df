// The basketball: a regulation size 7 ball, 0.609 kg, radius 0.1218 m, bounciness 0.766.
// FIBA's Official Basketball Rules, Basketball Equipment (2020), section 2: a size 7 ball has a
// circumference of 749 to 780 mm and weighs 567 to 650 g (the middles: r = 765 / 2 pi = 121.8 mm,
// m = 0.609 kg), and is inflated so that dropped onto the floor from 1800 mm (measured to the bottom
// of the ball) it rebounds to 1200 to 1400 mm measured to the TOP of the ball. The bottom then
// climbs 1300 - 243.5 = 1056.5 mm, so C = sqrt(h_bounce / h_drop) = sqrt(1056.5 / 1800) = 0.766
// (the floor taken as C = 1; the same figures read both to the bottom would give 0.850).
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

class BasketballKind final : public BallKind {
public:
    std::string_view name() const override { return "basketball"; }
    int order() const override { return 18; }
    std::string_view summary() const override {
        return "a size 7 ball with its ribs, 0.609 kg, radius 0.1218 m, bounciness 0.766";
    }
    std::span<const PartKey> keys() const override { return kKeys; }

protected:
    double radius() const override { return 0.1218; }
    double mass() const override { return 0.609; }
    double bounciness() const override { return 0.766; }
    render::Style look() const override { return style("arrow", "ball_outline"); }
    // Its ribs: one line through the middle and two curved ones beside it, turning with the ball.
    void decorateFront(const Circle& c, render::DrawList& list) const override {
        const render::Color rib = render::Palette::greybox()["ball_outline"];
        const Vec2 along = Vec2::fromAngle(c.angle);
        list.line(pt(c.position - along * c.radius), pt(c.position + along * c.radius), 1.0f, rib);
        for (const double side : {-1.0, 1.0}) {
            std::array<render::Point, 7> arc{};
            for (std::size_t i = 0; i < arc.size(); ++i) {
                const double t = (static_cast<double>(i) / (arc.size() - 1) - 0.5) * 1.4;
                const Vec2 centre = c.position + along.perpendicular() * (side * 1.6 * c.radius);
                arc[i] = pt(centre + Vec2::fromAngle(c.angle + (side > 0 ? -0.5 : 0.5) * std::numbers::pi + t) *
                                         (1.25 * c.radius));
            }
            list.polyline(arc, 1.0f, rib);
        }
    }

private:
    static constexpr auto kKeys = ballKeys("0.1218");
};

} // namespace
RUBE_PART(basketball, BasketballKind)
} // namespace rube::game::parts
