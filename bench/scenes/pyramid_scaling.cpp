// pyramid-scaling-N (issue 26): Box2D's pyramid of unit boxes with base 20, 40 and 70 (N = 210, 820
// and 2485 boxes), 3 s each (180 steps at 60 Hz), rube's solver and the peers; large-pyramid (base 100,
// 5050 boxes, pyramids.cpp) is the sweep's last point. The target
// is a flat cost per box-step from 210 to 5050 boxes: pairs must cost what touches, not n^2. The
// pyramid's rows carry more weight as it grows, so the contact solve itself is the same per box
// only to within the iterations the taller stack needs; the chart shows what it costs.
#include "pyramid_type.hpp"

#include <array>
#include <string>

namespace bench {
namespace {

constexpr std::array<int, 3> kBases{20, 40, 70};

bool registerAll() {
    for (const int base : kBases) {
        const PyramidLayout l{.base = base};
        const int boxes = base * (base + 1) / 2;
        registerScene({
            .name = "pyramid-scaling-" + std::to_string(boxes),
            .errorName = "largest_box_move_m",
            .error2Name = "top_box_sink_m",
            .logError = true,
            .gravity = {0.0, -10.0},
            .duration = [](const SceneSize& size) { return size.quick ? 0.5 : 3.0; },
            .boundsMin = {-1000, -50},
            .boundsMax = {1000, 500},
            .build = [l](Sim& sim, const SceneSize&) { buildPyramids(sim, l); },
            .probe = [l](const SceneSize&, double) { return pyramidProbe(l); },
            .boxes = true,
            .runTimeLimit = 120.0,
            .scalingBodies = boxes,
        });
    }
    return true;
}

[[maybe_unused]] const bool registered = registerAll();

} // namespace
} // namespace bench
