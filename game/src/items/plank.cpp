// The plank: a lively board the player lays and turns.
#include "part_common.hpp"

namespace rube::game::parts {
namespace {

class PlankKind final : public BoardKind {
public:
    std::string_view name() const override { return "plank"; }
    int order() const override { return 4; }
    std::string_view summary() const override {
        return "a fixed board, 2 m long, bounciness 0.5, centred on its position";
    }
    std::span<const PartKey> keys() const override { return kKeys; }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        (void)available;
        const float r = static_cast<float>(0.5 * size);
        const render::Point c = pt(centre);
        list.capsule({c.x - r, c.y}, {c.x + r, c.y}, 0.12f * r, style("ground", "ground_outline"));
    }

protected:
    double length() const override { return 2.0; }
    double bounciness() const override { return 0.5; }

private:
    static constexpr auto kKeys = boardKeys("2");
};

} // namespace
RUBE_PART(plank, PlankKind)
} // namespace rube::game::parts
