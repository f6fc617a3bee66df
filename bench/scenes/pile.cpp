// pile: 1000 balls of radius 0.1 m dropped into a box 5 m wide and 20 m tall, 10 s (600 steps
// at 60 Hz). The error is the largest overlap in the last simulated second, once the pile has
// settled; escapes (balls leaving the box's bounds) are counted by the runner.

#include "measure.hpp"
#include "scene.hpp"

#include <algorithm>
#include <array>

namespace bench {
namespace {

constexpr double kRadius = 0.1;
const std::array<LineSpec, 3> kBox{{
    {.a = {-2.5, 0}, .b = {2.5, 0}},
    {.a = {-2.5, 0}, .b = {-2.5, 20}},
    {.a = {2.5, 0}, .b = {2.5, 20}},
}};

double duration(const SceneSize& size) { return size.quick ? 1.0 : 10.0; }

class PileProbe final : public Probe {
public:
    PileProbe(const SceneSize& size, double timeStep) : firstMeasured_(static_cast<int>((duration(size) - 1.0) / timeStep)) {}

    void observe(const Sim& sim, int step, double) override {
        if (step <= firstMeasured_) return; // the last simulated second only: the pile has settled
        overlap_ = std::max(overlap_, largestOverlap(sim, kRadius, kBox));
    }
    Metrics finish(const Sim&) override {
        Metrics m;
        m.error = overlap_;
        m.overlap = overlap_;
        return m;
    }

private:
    int firstMeasured_;
    double overlap_ = 0.0;
};

[[maybe_unused]] const bool registered = registerScene({
    .name = "pile",
    .errorName = "largest_overlap_last_second_m",
    .error2Name = "",
    .logError = true,
    .gravity = {0.0, -9.81},
    .duration = duration,
    .boundsMin = {-10, -10},
    .boundsMax = {10, 40},
    .build =
        [](Sim& sim, const SceneSize& size) {
            for (const LineSpec& line : kBox) sim.addLine(line);
            // 20 columns x 50 rows, 4 cm apart, every other row shifted 6 cm so that the columns do
            // not fall straight onto each other (as levels/physics/pile.toml); --quick: 10 x 10.
            const int columns = size.quick ? 10 : 20, rows = size.quick ? 10 : 50;
            for (int row = 0; row < rows; ++row) {
                const double shift = row % 2 == 1 ? 0.06 : 0.0;
                for (int column = 0; column < columns; ++column)
                    sim.addBall({.position = {-2.28 + column * 0.24 + shift, 0.5 + row * 0.24},
                                 .radius = kRadius, .mass = 0.1, .bounciness = 0.3, .friction = 0.4});
            }
        },
    .probe = [](const SceneSize& size, double timeStep) { return std::make_unique<PileProbe>(size, timeStep); },
});

} // namespace
} // namespace bench
