// The ramp: a long dull board that turns a fall into a roll.
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

class RampKind final : public BoardKind {
public:
    std::string_view name() const override { return "ramp"; }
    int order() const override { return 5; }
    std::string_view summary() const override {
        return "a fixed board, 3 m long, bounciness 0.3, centred on its position";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const float r = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        list.capsule({c.x - r, c.y + 0.5f * r}, {c.x + r, c.y - 0.5f * r}, 0.12f * r,
                     style("ground", "ground_outline"));
    }

protected:
    double length() const override { return 3.0; }
    double bounciness() const override { return 0.3; }

private:
    static constexpr auto kKeys = boardKeys("3");
};

} // namespace
RUBE_PART(ramp, RampKind)
} // namespace rube::game::parts
