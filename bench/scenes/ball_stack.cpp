// ball-stack: a column of 5 balls of radius 0.5 m resting on a floor and on each other (C = 0).
// It should stay still: the error is the largest drift of any ball from where it started.

#include "measure.hpp"
#include "scene.hpp"

#include <algorithm>
#include <array>

namespace bench {
namespace {

constexpr double kRadius = 0.5;
constexpr int kBalls = 5;
const std::array<LineSpec, 1> kFloor{{{.a = {-5, 0}, .b = {5, 0}}}};

Vec2 start(int i) { return {0.0, kRadius + 2.0 * kRadius * i}; }

class BallStackProbe final : public Probe {
public:
    void observe(const Sim& sim, int, double) override {
        for (int i = 0; i < sim.ballCount(); ++i) drift_ = std::max(drift_, sim.ball(i).position.distance(start(i)));
        overlap_ = std::max(overlap_, largestOverlap(sim, kRadius, kFloor));
    }
    Metrics finish(const Sim&) override {
        Metrics m;
        m.error = drift_;
        m.overlap = overlap_;
        return m;
    }

private:
    double drift_ = 0.0, overlap_ = 0.0;
};

[[maybe_unused]] const bool registered = registerScene({
    .name = "ball-stack",
    .errorName = "largest_drift_m",
    .error2Name = "",
    .logError = true,
    .gravity = {0.0, -9.81},
    .duration = [](const SceneSize& size) { return size.quick ? 1.0 : 5.0; },
    .boundsMin = {-20, -5},
    .boundsMax = {20, 30},
    .build =
        [](Sim& sim, const SceneSize&) {
            sim.addLine(kFloor[0]);
            // Centres one diameter apart: each ball just touches the one below.
            for (int i = 0; i < kBalls; ++i)
                sim.addBall({.position = start(i), .radius = kRadius, .mass = 1.0, .bounciness = 0.0});
        },
    .probe = [](const SceneSize&, double) { return std::make_unique<BallStackProbe>(); },
});

} // namespace
} // namespace bench
