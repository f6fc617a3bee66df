// The steel ball: a grey 4 kg ball, radius 0.2 m, bounciness 0.7: the one ball magnets pull.
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

class SteelKind final : public BallKind {
public:
    std::string_view name() const override { return "steel"; }
    int order() const override { return 2; }
    std::string_view summary() const override {
        return "a grey 4 kg ball, radius 0.2 m, bounciness 0.7: the one ball magnets pull";
    }
    std::span<const PartKey> keys() const override { return kKeys; }

protected:
    double radius() const override { return 0.2; }
    double mass() const override { return 4.0; }
    double bounciness() const override { return 0.7; }
    bool magnetic() const override { return true; }
    render::Style look() const override { return style("kinematic", "ball_outline"); }

private:
    static constexpr auto kKeys = ballKeys("0.2");
};

} // namespace
RUBE_PART(steel, SteelKind)
} // namespace rube::game::parts
