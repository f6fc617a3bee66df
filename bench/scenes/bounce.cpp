// bounce: a ball of radius 0.5 m dropped from a centre height of 10 m onto a floor with C = 1.
// No energy may be lost or gained, so every apex is 10 m and y + v^2/2g stays 10 m throughout.

#include "measure.hpp"
#include "scene.hpp"

#include <algorithm>
#include <cmath>

namespace bench {
namespace {

constexpr double kGravity = 9.81;
constexpr double kDropHeight = 10.0;
constexpr double kRadius = 0.5;

class BounceProbe final : public Probe {
public:
    void observe(const Sim& sim, int, double) override {
        const BallState b = sim.ball(0);
        // Energy as a height: E / (m g) = y + v^2 / 2g must stay at the drop height (lecture 3, C = 1).
        worstEnergy_ = std::max(worstEnergy_, std::fabs(energyHeight(b, kGravity) - kDropHeight));
        // An apex is where the ball turns from rising to falling; the highest sample stands for it.
        if (b.velocity.y > 0.0) {
            rising_ = true;
            highest_ = std::max(highest_, b.position.y);
        } else if (rising_) {
            rising_ = false;
            highest_ = std::max(highest_, b.position.y);
            worstApex_ = std::max(worstApex_, std::fabs(highest_ - kDropHeight) / kDropHeight);
            highest_ = 0.0;
        }
    }
    Metrics finish(const Sim&) override {
        Metrics m;
        m.error = worstEnergy_;
        m.error2 = worstApex_;
        return m;
    }

private:
    double worstEnergy_ = 0.0, worstApex_ = 0.0, highest_ = 0.0;
    bool rising_ = false;
};

[[maybe_unused]] const bool registered = registerScene({
    .name = "bounce",
    .errorName = "energy_error_m",
    .error2Name = "apex_error_rel",
    .logError = true,
    .gravity = {0.0, -kGravity},
    // 20 s is the span for the energy target; --quick needs only the first bounce.
    .duration = [](const SceneSize& size) { return size.quick ? 3.0 : 20.0; },
    .boundsMin = {-20, -5},
    .boundsMax = {20, 30},
    .build =
        [](Sim& sim, const SceneSize&) {
            sim.addLine({.a = {-5, 0}, .b = {5, 0}});
            sim.addBall({.position = {0, kDropHeight}, .radius = kRadius, .mass = 1.0, .bounciness = 1.0});
        },
    .probe = [](const SceneSize&, double) { return std::make_unique<BounceProbe>(); },
});

} // namespace
} // namespace bench
