// The balloon: a light blue ball on a string that rises.
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

// A balloon rises at g: gravity acts on it with scale -1 (its lift is 2 |g| against gravity's |g|).
constexpr double kBalloonGravityScale = -1.0;

class BalloonKind final : public BallKind {
public:
    std::string_view name() const override { return "balloon"; }
    int order() const override { return 3; }
    std::string_view summary() const override {
        return "a blue 0.1 kg ball on a string, radius 0.35 m, bounciness 0.5, lifted by 2 |g|: it rises at g";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    double speedGiven(const ItemDesc& item, double lightest, double g, double seconds) const override {
        (void)item, (void)lightest;
        return (1.0 - kBalloonGravityScale) * g * seconds; // its lift, 2 g, against gravity's g
    }

protected:
    double radius() const override { return 0.35; }
    double mass() const override { return 0.1; }
    double gravityScale() const override { return kBalloonGravityScale; }
    double bounciness() const override { return 0.5; }
    render::Style look() const override { return style("highlight", "ball_outline"); }
    void decorateBehind(const Circle& c, render::DrawList& list) const override {
        list.line(pt(c.position - Vec2{0.0, c.radius}), pt(c.position - Vec2{0.0, 2.5 * c.radius}), 1.5f,
                  render::Palette::greybox()["ball_outline"]);
    }

private:
    static constexpr auto kKeys = ballKeys("0.35");
};

} // namespace
RUBE_PART(balloon, BalloonKind)
} // namespace rube::game::parts
