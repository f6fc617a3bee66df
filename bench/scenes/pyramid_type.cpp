// The pyramids' layout and probe (see pyramid_type.hpp).
#include "pyramid_type.hpp"

#include <algorithm>
#include <vector>

namespace bench {

namespace {

double width(const PyramidLayout& l) { return l.base * 2.0 * kPyramidHalf; }
double span(const PyramidLayout& l) { return l.pyramids * width(l) + (l.pyramids - 1) * l.gap; }

// Box k's place as built: the ground first (index 0), then each pyramid's rows bottom up.
std::vector<Vec2> builtPositions(const PyramidLayout& l) {
    std::vector<Vec2> at;
    const double h = kPyramidHalf;
    const double left = -0.5 * span(l);
    for (int p = 0; p < l.pyramids; ++p) {
        const double centre = left + p * (width(l) + l.gap) + 0.5 * width(l);
        for (int row = 0; row < l.base; ++row) {
            const int n = l.base - row;
            for (int i = 0; i < n; ++i) at.push_back({centre + (i - 0.5 * (n - 1)) * 2.0 * h, h + 2.0 * h * row});
        }
    }
    return at;
}

class PyramidProbe final : public Probe {
public:
    explicit PyramidProbe(const PyramidLayout& layout)
        : built_(builtPositions(layout)), top_(layout.base * (layout.base + 1) / 2 - 1) {}
    void observe(const Sim& sim, int, double) override {
        for (int k = 0; k < static_cast<int>(built_.size()); ++k)
            moved_ = std::max(moved_, sim.box(k + 1).position.distance(built_[static_cast<std::size_t>(k)]));
    }
    Metrics finish(const Sim& sim) override {
        Metrics m;
        m.error = moved_;
        m.error2 = built_[static_cast<std::size_t>(top_)].y - sim.box(top_ + 1).position.y;
        return m;
    }

private:
    std::vector<Vec2> built_;
    int top_; // the first pyramid's top box, among the built boxes
    double moved_ = 0.0;
};

} // namespace

void buildPyramids(Sim& sim, const PyramidLayout& layout) {
    const double groundHalfWidth = 0.5 * span(layout) + 20.0;
    sim.addBox({.position = {0.0, -1.0}, .halfExtents = {groundHalfWidth, 1.0}, .fixed = true});
    for (const Vec2 p : builtPositions(layout)) sim.addBox({.position = p, .halfExtents = {kPyramidHalf, kPyramidHalf}});
}

std::unique_ptr<Probe> pyramidProbe(const PyramidLayout& layout) { return std::make_unique<PyramidProbe>(layout); }

} // namespace bench
