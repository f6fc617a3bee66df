// pile: 1000 balls of radius 0.1 m dropped into a box 5 m wide and 20 m tall, 10 s (600 steps
// at 60 Hz). The error is the largest overlap in the last simulated second, once the pile has
// settled; escapes (balls leaving the box's bounds) are counted by the runner.

#include "pile_type.hpp"

namespace bench {
namespace {

double duration(const SceneSize& size) { return size.quick ? 1.0 : 10.0; }

// 20 columns x 50 rows; --quick: 10 x 10 in the same box.
PileLayout layout(const SceneSize& size) {
    return size.quick ? PileLayout{.balls = 100, .columns = 10} : PileLayout{.balls = 1000, .columns = 20};
}

[[maybe_unused]] const bool registered = registerScene({
    .name = "pile",
    .errorName = "largest_overlap_last_second_m",
    .error2Name = "",
    .logError = true,
    .gravity = {0.0, -9.81},
    .duration = duration,
    .boundsMin = {-10, -10},
    .boundsMax = {10, 40},
    .build = [](Sim& sim, const SceneSize& size) { buildPile(sim, layout(size)); },
    .probe = [](const SceneSize& size, double timeStep) { return pileProbe(layout(size), duration(size), timeStep); },
});

} // namespace
} // namespace bench
