// rolling-disc: a solid disc (I = m r^2 / 2) released at rest on a 20-degree incline, friction 0.8
// on both. Rolling without slipping, m a = m g sin(theta) - F and I alpha = F r with a = alpha r give
// a = g sin(theta) / (1 + I / (m r^2)) = (2/3) g sin(theta), so the distance down the slope is
// s(t) = (2/3) g sin(theta) t^2 / 2. The error is the largest distance from that; the second error
// is the slip speed at the end, |v . down + omega r|, which rolling keeps at 0.
// Only the solver among rube's methods solves friction; the others let the disc slide at
// g sin(theta), so they measure a known limit (see bench/README.md), not a bug.

#include "scene.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bench {
namespace {

constexpr double kGravity = 9.81;
constexpr double kRadius = 0.5;
constexpr double kFriction =
    0.8; // the pair's 0.64 (rube, Chipmunk) or 0.8 (Box2D) is far above tan(20 deg) / 3 = 0.12: no slip
const double kTheta = 20.0 * std::numbers::pi / 180.0;
const Vec2 kDown{std::cos(kTheta), -std::sin(kTheta)}; // along the slope, downhill to the right
const Vec2 kNormal{std::sin(kTheta), std::cos(kTheta)};
const Vec2 kStart = kNormal * kRadius; // touching the incline where it passes through the origin

class RollingProbe final : public Probe {
public:
    void observe(const Sim& sim, int, double t) override {
        // s(t) = (2/3) g sin(theta) t^2 / 2 for a solid disc rolling without slipping.
        const double analytic = (2.0 / 3.0) * kGravity * std::sin(kTheta) * t * t / 2.0;
        worst_ = std::max(worst_, std::fabs((sim.ball(0).position - kStart).dot(kDown) - analytic));
    }
    Metrics finish(const Sim& sim) override {
        const BallState b = sim.ball(0);
        Metrics m;
        m.error = worst_;
        // The contact point's speed: v + omega x (-r n) along the slope = v . down + omega r.
        m.error2 = std::fabs(b.velocity.dot(kDown) + b.angularVelocity * kRadius);
        return m;
    }

private:
    double worst_ = 0.0;
};

[[maybe_unused]] const bool registered = registerScene({
    .name = "rolling-disc",
    .errorName = "distance_error_m",
    .error2Name = "slip_speed_m_per_s",
    .logError = true,
    .gravity = {0.0, -kGravity},
    // 3 s: about 10 m down the slope rolling, 15 m sliding; the incline is 30 m long.
    .duration = [](const SceneSize& size) { return size.quick ? 1.0 : 3.0; },
    .boundsMin = {-20, -20},
    .boundsMax = {40, 20},
    .build =
        [](Sim& sim, const SceneSize&) {
            sim.addLine({.a = kDown * -2.0, .b = kDown * 30.0, .bounciness = 0.0, .friction = kFriction});
            sim.addBall({.position = kStart, .radius = kRadius, .mass = 1.0, .bounciness = 0.0, .friction = kFriction});
        },
    .probe = [](const SceneSize&, double) { return std::make_unique<RollingProbe>(); },
});

} // namespace
} // namespace bench
