// The heavy ball: a dark 8 kg ball, radius 0.3 m, bounciness 0.2: dull on anything.
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

class HeavyKind final : public BallKind {
public:
    std::string_view name() const override { return "heavy"; }
    int order() const override { return 0; }
    std::string_view summary() const override {
        return "a dark 8 kg ball, radius 0.3 m, bounciness 0.2: dull on anything";
    }
    std::span<const PartKey> keys() const override { return kKeys; }

protected:
    double radius() const override { return 0.3; }
    double mass() const override { return 8.0; }
    double bounciness() const override { return 0.2; }
    render::Style look() const override { return style("heavy_ball", "ball_outline"); }

private:
    static constexpr auto kKeys = ballKeys("0.3");
};

} // namespace
RUBE_PART(heavy, HeavyKind)
} // namespace rube::game::parts
