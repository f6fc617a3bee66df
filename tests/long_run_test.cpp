// Long runs of the pile (levels/physics/pile.toml, 1000 balls, friction, solver at 60 Hz): once
// settled it must stay settled: no creep (no ball drifts over the last minutes), no explosion (no
// ball moves fast), nothing escapes, nothing becomes NaN, overlap stays within 5 mm.
// CI runs 5 simulated minutes; the hour is hidden ([.long]): ./build/tests/game_tests "[.long]".
#include "scene.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

using namespace rube;
using namespace rube::game;

namespace {

double largestOverlap(const World& world) {
    const auto circles = world.circles();
    double worst = 0.0;
    for (std::size_t i = 0; i < circles.size(); ++i)
        for (std::size_t j = i + 1; j < circles.size(); ++j) {
            const double gap = circles[i].position.distance(circles[j].position) - circles[i].radius -
                               circles[j].radius;
            worst = std::max(worst, -gap);
        }
    return worst;
}

// Runs the pile for `minutes` simulated minutes and compares the last `window` minutes.
void checkSettled(double minutes, double window) {
    const SceneLoad load = loadSceneFile(std::filesystem::path(RUBE_LEVELS_DIR) / "pile.toml");
    REQUIRE(load.ok());
    World world = buildWorld(*load.scene);
    const double dt = world.def().timeStep;
    const auto steps = static_cast<long>(std::lround(minutes * 60.0 / dt));
    const auto windowStart = static_cast<long>(std::lround((minutes - window) * 60.0 / dt));
    std::vector<Vec2> before;
    double fastest = 0.0;
    for (long step = 1; step <= steps; ++step) {
        world.step();
        if (step == windowStart) {
            for (const Circle& c : world.circles()) before.push_back(c.position);
        }
        if (step > windowStart)
            for (const Circle& c : world.circles()) fastest = std::max(fastest, c.velocity.length());
    }
    double drift = 0.0;
    for (std::size_t i = 0; i < before.size(); ++i)
        drift = std::max(drift, world.circles()[i].position.distance(before[i]));
    const double overlap = largestOverlap(world);
    WARN(minutes << " simulated minutes: largest drift over the last " << window << " min " << drift
                 << " m, fastest ball " << fastest << " m/s, largest overlap " << overlap << " m, escapes "
                 << world.stats().escapes);
    CHECK(drift < 0.001);  // no creep: 1 mm over minutes
    CHECK(fastest < 0.05); // no explosion, no jitter worth the name
    CHECK(overlap <= 0.005);
    CHECK(world.stats().escapes == 0);
    CHECK_FALSE(world.stats().nonFinite);
}

} // namespace

TEST_CASE("the pile stays settled over 5 simulated minutes", "[long-run]") { checkSettled(5.0, 3.0); }

TEST_CASE("the pile stays settled over a simulated hour", "[.long]") { checkSettled(60.0, 10.0); }
