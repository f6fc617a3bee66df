// pile-scaling-N: the pile scene type with N = 100, 500, 1000, 5000 and 20,000 balls in a box k = N / 1000
// times as wide (5k m, 20k columns of the pile's 50 rows), as tall as the pile's. Every column falls
// as far and carries the same load as in the 1000-ball pile (the sweep's point at k = 1), so a body-step
// is the same physics at every N and the cost per body-step measures the engine alone (the issue's
// target: within 1.5 x of itself from 100 to 20,000). Scaling the box both ways instead made deeper
// piles (the top of 20,000 balls fell 54 m for 3.3 s): more contacts per ball and more passes, a
// different scene rather than more of the same one.

#include "pile_type.hpp"

#include <array>
#include <cmath>
#include <string>

namespace bench {
namespace {

constexpr std::array<int, 5> kBodies{100, 500, 1000, 5000, 20000};

// 10 s, as the pile.
double duration(const SceneSize& size) { return size.quick ? 1.0 : 10.0; }

PileLayout layout(int balls) {
    const double k = balls / 1000.0;
    return {.balls = balls, .columns = static_cast<int>(std::lround(20.0 * k)), .width = 5.0 * k, .height = 20.0};
}

bool registerAll() {
    for (const int balls : kBodies) {
        const PileLayout l = layout(balls);
        registerScene({
            .name = "pile-scaling-" + std::to_string(balls),
            .errorName = "largest_overlap_last_second_m",
            .error2Name = "",
            .logError = true,
            .gravity = {0.0, -9.81},
            .duration = duration,
            .boundsMin = {-l.width - 5.0, -10},
            .boundsMax = {l.width + 5.0, 2.0 * l.height},
            .build = [l](Sim& sim, const SceneSize&) { buildPile(sim, l); },
            .probe = [l](const SceneSize& size, double timeStep) { return pileProbe(l, duration(size), timeStep); },
            .scalingBodies = balls,
        });
    }
    return true;
}

[[maybe_unused]] const bool registered = registerAll();

} // namespace
} // namespace bench
