// The bouncy ball: a white 0.5 kg ball with a ring, radius 0.25 m, bounciness 0.95: lively on a lively surface.
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

class BouncyKind final : public BallKind {
public:
    std::string_view name() const override { return "bouncy"; }
    int order() const override { return 1; }
    std::string_view summary() const override {
        return "a white 0.5 kg ball with a ring, radius 0.25 m, bounciness 0.95: lively on a lively surface";
    }
    std::span<const PartKey> keys() const override { return kKeys; }

protected:
    double radius() const override { return 0.25; }
    double mass() const override { return 0.5; }
    double bounciness() const override { return 0.95; }
    void decorateFront(const Circle& c, render::DrawList& list) const override {
        list.ring(pt(c.position), 0.6f * static_cast<float>(c.radius), 1.5f, render::Palette::greybox()["arrow"]);
    }

private:
    static constexpr auto kKeys = ballKeys("0.25");
};

} // namespace
RUBE_PART(bouncy, BouncyKind)
} // namespace rube::game::parts
