// dominoes (issue 26): a domino run of 1000 dominoes, 40 lanes of 25 on shelves 3 m apart, each
// domino 0.2 m x 1 m (density 1, friction 0.6), 0.6 m apart; the first of each lane starts tipped 20
// degrees towards the second, and the wave runs down every lane in 10 s. The error is the share of
// dominoes still standing (tilted under 10 degrees) at the end: 0 when every domino fell in turn.
// --quick: 2 lanes of 10.
#include "scene.hpp"

#include <cmath>
#include <numbers>

namespace bench {
namespace {

struct Run {
    int lanes = 40;
    int perLane = 25;
};

constexpr Vec2 kHalf{0.1, 0.5};
constexpr double kSpacing = 0.6;
constexpr double kLaneGap = 3.0;
constexpr double kFirstTilt = 20.0 * std::numbers::pi / 180.0;
constexpr double kStandingTilt = 10.0 * std::numbers::pi / 180.0;

Run run(const SceneSize& size) { return size.quick ? Run{2, 10} : Run{}; }

void build(Sim& sim, const Run& r) {
    const double length = r.perLane * kSpacing + 2.0;
    for (int lane = 0; lane < r.lanes; ++lane) {
        const double floor = lane * kLaneGap;
        sim.addBox(
            {.position = {0.5 * length - 1.0, floor - 0.25}, .halfExtents = {0.5 * length, 0.25}, .fixed = true});
    }
    for (int lane = 0; lane < r.lanes; ++lane) {
        const double floor = lane * kLaneGap;
        for (int i = 0; i < r.perLane; ++i) {
            // The first leans towards the run, its bottom corner on the shelf: centre at the corner
            // plus the half extents turned by the tilt (clockwise).
            const double tilt = i == 0 ? kFirstTilt : 0.0;
            const Vec2 corner{i * kSpacing + kHalf.x, floor};
            const Vec2 centre{corner.x - kHalf.x * std::cos(tilt) + kHalf.y * std::sin(tilt),
                              corner.y + kHalf.x * std::sin(tilt) + kHalf.y * std::cos(tilt)};
            sim.addBox({.position = centre, .angle = -tilt, .halfExtents = kHalf});
        }
    }
}

class DominoProbe final : public Probe {
public:
    explicit DominoProbe(const Run& r) : run_(r) {}
    void observe(const Sim&, int, double) override {}
    Metrics finish(const Sim& sim) override {
        int standing = 0;
        const int dominoes = run_.lanes * run_.perLane;
        for (int k = 0; k < dominoes; ++k)
            if (std::abs(std::remainder(sim.box(run_.lanes + k).angle, 2.0 * std::numbers::pi)) < kStandingTilt)
                ++standing;
        Metrics m;
        m.error = static_cast<double>(standing) / dominoes;
        return m;
    }

private:
    Run run_;
};

[[maybe_unused]] const bool registered = registerScene({
    .name = "dominoes",
    .errorName = "standing_fraction",
    .error2Name = "",
    .logError = false,
    .gravity = {0.0, -9.81},
    .duration = [](const SceneSize& size) { return size.quick ? 3.0 : 10.0; },
    .boundsMin = {-50, -50},
    .boundsMax = {100, 200},
    .build = [](Sim& sim, const SceneSize& size) { build(sim, run(size)); },
    .probe = [](const SceneSize& size, double) { return std::make_unique<DominoProbe>(run(size)); },
    .boxes = true,
    .runTimeLimit = 60.0,
});

} // namespace
} // namespace bench
