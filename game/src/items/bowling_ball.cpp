// The bowling ball: a regulation ten-pin ball, 7.257 kg, radius 0.1086 m, bounciness 0.2: it thuds.
// Sizes are the USBC's specification for ten-pin balls: at most 16 lb (7.257 kg), diameter 8.500 to
// 8.595 in (21.59 to 21.83 cm), so radius 0.1086 m at the middle of that range. No rule gives a
// bowling ball a drop test; a hard resin ball on a wooden floor barely comes back, so it takes the
// heavy ball's C = 0.2 (a choice, not a measurement: h1/h0 = C^2 = 0.04).
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

class BowlingBallKind final : public BallKind {
public:
    std::string_view name() const override { return "bowling-ball"; }
    int order() const override { return 16; }
    std::string_view summary() const override {
        return "a ten-pin ball with finger holes, 7.257 kg, radius 0.1086 m, bounciness 0.2: it thuds";
    }
    std::span<const PartKey> keys() const override { return kKeys; }

protected:
    double radius() const override { return 0.1086; }
    double mass() const override { return 7.257; }
    double bounciness() const override { return 0.2; }
    render::Style look() const override { return style("heavy_ball", "ball_outline"); }
    // Three finger holes that turn with the ball, so its roll shows.
    void decorateFront(const Circle& c, render::DrawList& list) const override {
        const render::Style hole = style("ball_outline", "ball_outline", 0.0f);
        constexpr double kSpread[] = {-0.45, 0.0, 0.45}; // radians either side of the thumb's line
        for (int i = 0; i < 3; ++i) {
            const double along = i == 1 ? 0.55 : 0.35; // the thumb hole sits further out
            const Vec2 at = c.position +
                            Vec2::fromAngle(c.angle + 0.5 * std::numbers::pi + kSpread[i]) * (along * c.radius);
            list.circle(pt(at), 0.14f * static_cast<float>(c.radius), hole);
        }
    }

private:
    static constexpr auto kKeys = ballKeys("0.1086");
};

} // namespace
RUBE_PART(bowling_ball, BowlingBallKind)
} // namespace rube::game::parts
