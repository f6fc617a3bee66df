// The pile scene type: the box, the balls' starting grid and the last-second overlap probe.

#include "pile_type.hpp"

#include "measure.hpp"

#include <algorithm>

namespace bench {
namespace {

constexpr double kSpacing = 0.24; // 4 cm between balls of 0.2 m: none starts in contact

class PileProbe final : public Probe {
public:
    PileProbe(const PileLayout& layout, double duration, double timeStep)
        : box_(pileBox(layout)), firstMeasured_(static_cast<int>((duration - 1.0) / timeStep)) {}

    void observe(const Sim& sim, int step, double) override {
        if (step <= firstMeasured_) return; // the last simulated second only: the pile has settled
        overlap_ = std::max(overlap_, largestOverlap(sim, kPileRadius, box_));
    }
    Metrics finish(const Sim&) override {
        Metrics m;
        m.error = overlap_;
        m.overlap = overlap_;
        return m;
    }

private:
    std::array<LineSpec, 3> box_;
    int firstMeasured_;
    double overlap_ = 0.0;
};

} // namespace

std::array<LineSpec, 3> pileBox(const PileLayout& layout) {
    const double half = layout.width / 2.0;
    return {{
        {.a = {-half, 0}, .b = {half, 0}},
        {.a = {-half, 0}, .b = {-half, layout.height}},
        {.a = {half, 0}, .b = {half, layout.height}},
    }};
}

void buildPile(Sim& sim, const PileLayout& layout) {
    for (const LineSpec& line : pileBox(layout)) sim.addLine(line);
    // Centred columns: for 20 columns the first sits at x = -2.28 m, as the pile level's does.
    const double first = -0.5 * (layout.columns - 1) * kSpacing;
    for (int i = 0; i < layout.balls; ++i) {
        const int row = i / layout.columns, column = i % layout.columns;
        const double shift = row % 2 == 1 ? 0.06 : 0.0; // so the columns do not fall straight onto each other
        sim.addBall({.position = {first + column * kSpacing + shift, 0.5 + row * kSpacing},
                     .radius = kPileRadius,
                     .mass = 0.1,
                     .bounciness = 0.3,
                     .friction = 0.4});
    }
}

std::unique_ptr<Probe> pileProbe(const PileLayout& layout, double duration, double timeStep) {
    return std::make_unique<PileProbe>(layout, duration, timeStep);
}

} // namespace bench
