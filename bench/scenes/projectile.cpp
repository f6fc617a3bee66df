// projectile: a ball launched at 15 m/s at 36.87 degrees flies for 1.8 s without touching
// anything; its distance from the analytic arc p0 + v0 t + g t^2 / 2 is the integrator's error.

#include "scene.hpp"

#include <algorithm>

namespace bench {
namespace {

constexpr Vec2 kGravity{0.0, -9.81};
constexpr Vec2 kStart{0.0, 1.0};
constexpr Vec2 kLaunch{12.0, 9.0}; // a 3-4-5 triangle: 15 m/s at atan(9/12)

class ProjectileProbe final : public Probe {
public:
    void observe(const Sim& sim, int, double t) override {
        // The constant-acceleration arc (lecture 2): p(t) = p0 + v0 t + g t^2 / 2.
        const Vec2 arc = kStart + kLaunch * t + kGravity * (0.5 * t * t);
        worst_ = std::max(worst_, sim.ball(0).position.distance(arc));
    }
    Metrics finish(const Sim&) override {
        Metrics m;
        m.error = worst_;
        return m;
    }

private:
    double worst_ = 0.0;
};

[[maybe_unused]] const bool registered = registerScene({
    .name = "projectile",
    .errorName = "arc_distance_m",
    .error2Name = "",
    .logError = true,
    .gravity = kGravity,
    // 1.8 s: the whole flight, ending just before the landing at 1.9 s.
    .duration = [](const SceneSize&) { return 1.8; },
    .boundsMin = {-10, -5},
    .boundsMax = {50, 30},
    .build =
        [](Sim& sim, const SceneSize&) {
            sim.addLine({.a = {-2, 0}, .b = {40, 0}});
            sim.addBall({.position = kStart, .velocity = kLaunch, .radius = 0.25, .mass = 1.0, .bounciness = 0.8});
        },
    .probe = [](const SceneSize&, double) { return std::make_unique<ProjectileProbe>(); },
});

} // namespace
} // namespace bench
