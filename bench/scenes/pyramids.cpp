// The pyramids (issue 26): Box2D v3's benchmark scenes, run like for like at 60 Hz with sleeping off
// in every engine that moves boxes that turn. pyramid-40: base 40 (820 boxes), 5 s. large-pyramid:
// Box2D's large_pyramid, base 100 (5050 boxes), 500 steps. many-pyramids: 20 pyramids of base 10
// (55 boxes each, 1100 in all), 5 s. --quick: base 10, and 2 small pyramids. large-pyramid is the last
// point of the boxes' scaling sweep (pyramid_scaling.cpp), so it runs with the sweep: rube's solver and the peers.
#include "pyramid_type.hpp"

namespace bench {
namespace {

Scene pyramidScene(std::string name, PyramidLayout full, PyramidLayout quick, double seconds, double limit,
                   int scalingBodies = 0) {
    const auto layout = [=](const SceneSize& size) { return size.quick ? quick : full; };
    return {
        .name = std::move(name),
        .errorName = "largest_box_move_m",
        .error2Name = "top_box_sink_m",
        .logError = true,
        .gravity = {0.0, -10.0},
        .duration = [=](const SceneSize& size) { return size.quick ? 0.5 : seconds; },
        .boundsMin = {-1000, -50},
        .boundsMax = {1000, 500},
        .build = [=](Sim& sim, const SceneSize& size) { buildPyramids(sim, layout(size)); },
        .probe = [=](const SceneSize& size, double) { return pyramidProbe(layout(size)); },
        .boxes = true,
        .runTimeLimit = limit,
        .scalingBodies = scalingBodies,
    };
}

[[maybe_unused]] const bool registered = registerScene(
                                             pyramidScene("pyramid-40", {.base = 40}, {.base = 10}, 5.0, 60.0)) &&
                                         registerScene(pyramidScene("large-pyramid", {.base = 100}, {.base = 10},
                                                                    500.0 / 60.0, 240.0, 5050)) &&
                                         registerScene(pyramidScene("many-pyramids", {.base = 10, .pyramids = 20},
                                                                    {.base = 5, .pyramids = 2}, 5.0, 60.0));

} // namespace
} // namespace bench
