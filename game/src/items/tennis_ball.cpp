// The tennis ball: a regulation ball, 57.7 g, radius 0.0335 m, bounciness 0.745.
// The ITF's Rules of Tennis, Appendix I (type 2 ball): mass 56.0 to 59.4 g, diameter 6.541 to
// 6.858 cm, and dropped from 254 cm onto concrete it must rebound 135 to 147 cm. The middles of
// those ranges give m = 57.7 g, r = 0.0335 m, and C = sqrt(h_bounce / h_drop) = sqrt(141 / 254) =
// 0.745 (a drop of h returns at C sqrt(2 g h), which climbs C^2 h; concrete is taken as C = 1).
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

class TennisBallKind final : public BallKind {
public:
    std::string_view name() const override { return "tennis-ball"; }
    int order() const override { return 17; }
    std::string_view summary() const override {
        return "a felt ball with a seam, 0.0577 kg, radius 0.0335 m, bounciness 0.745: small and lively";
    }
    std::span<const PartKey> keys() const override { return kKeys; }

protected:
    double radius() const override { return 0.0335; }
    double mass() const override { return 0.0577; }
    double bounciness() const override { return 0.745; }
    render::Style look() const override { return style("flame", "ball_outline"); }
    // Its seam: two arcs facing away from each other, turning with the ball.
    void decorateFront(const Circle& c, render::DrawList& list) const override {
        const render::Color seam = render::Palette::greybox()["ball"];
        for (const double side : {-1.0, 1.0}) {
            std::array<render::Point, 7> arc{};
            for (std::size_t i = 0; i < arc.size(); ++i) {
                const double t = (static_cast<double>(i) / (arc.size() - 1) - 0.5) *
                                 1.6; // radians about the arc's centre
                const Vec2 centre = c.position + Vec2::fromAngle(c.angle) * (side * 1.3 * c.radius);
                arc[i] = pt(centre +
                            Vec2::fromAngle(c.angle + (side > 0 ? std::numbers::pi : 0.0) + t) * (0.85 * c.radius));
            }
            list.polyline(arc, 1.0f, seam);
        }
    }

private:
    static constexpr auto kKeys = ballKeys("0.0335");
};

} // namespace
RUBE_PART(tennis_ball, TennisBallKind)
} // namespace rube::game::parts
