// newton-cradle: no gravity, 5 equal balls of radius 0.5 m in a row, C = 1: the first comes in at
// 3 m/s onto the other 4, which touch. Ideally (equal masses, C = 1, one impact at a time) the
// velocity is handed down the row, so only the last ball leaves, at 3 m/s, and the others stop.
// The error is how far the final velocities are from that outcome; momentum and energy are kept
// by it, so their drift is measured too (as levels/physics/newtons-cradle.toml, at 3 m/s).

#include "scene.hpp"

#include <algorithm>
#include <cmath>

namespace bench {
namespace {

constexpr int kBalls = 5;
constexpr double kRadius = 0.5;
constexpr double kMass = 1.0;
// 3 m/s, not 1: Box2D 2.4.1 applies no restitution below b2_velocityThreshold (1 m/s of approach),
// and the impulse handed down the row must stay above it for the peer to be measured fairly.
constexpr double kSpeed = 3.0;
// 1.53 m: the impact lands at 0.51 s, inside a step at every rate of the sweep (30..240 Hz), never
// on a step's end, where a method that only looks at the end of a step would be lucky.
constexpr double kGap = 1.53;

class CradleProbe final : public Probe {
public:
    void observe(const Sim& sim, int, double) override {
        // Momentum is kept at every step by every method, not only in the outcome: sum m v = m v0.
        Vec2 momentum{};
        for (int i = 0; i < sim.ballCount(); ++i) momentum += sim.ball(i).velocity * kMass;
        worstMomentum_ = std::max(worstMomentum_, momentum.distance({kMass * kSpeed, 0.0}) / (kMass * kSpeed));
    }
    Metrics finish(const Sim& sim) override {
        Metrics m;
        // The outcome: ball i should move at 0, the last at kSpeed; the largest miss, relative to v.
        double miss = 0.0, energy = 0.0;
        for (int i = 0; i < sim.ballCount(); ++i) {
            const Vec2 v = sim.ball(i).velocity;
            const Vec2 ideal{i == kBalls - 1 ? kSpeed : 0.0, 0.0};
            miss = std::max(miss, v.distance(ideal) / kSpeed);
            energy += 0.5 * kMass * v.lengthSquared();
        }
        const double energy0 = 0.5 * kMass * kSpeed * kSpeed; // C = 1 keeps all of it (lecture 3)
        m.error = miss;
        m.error2 = std::fabs(energy - energy0) / energy0;
        m.momentum = worstMomentum_;
        return m;
    }

private:
    double worstMomentum_ = 0.0;
};

[[maybe_unused]] const bool registered = registerScene({
    .name = "newton-cradle",
    .errorName = "outcome_velocity_error_rel",
    .error2Name = "energy_error_rel",
    .logError = true,
    .gravity = {0.0, 0.0},
    // The first ball meets the row at 0.51 s; by 3 s the last one has left it by 7.5 m.
    .duration = [](const SceneSize& size) { return size.quick ? 1.5 : 3.0; },
    .boundsMin = {-20, -20},
    .boundsMax = {20, 20},
    .build =
        [](Sim& sim, const SceneSize&) {
            // The first ball starts kGap short of touching the row; the row's centres are one
            // diameter apart, so each touches the next.
            sim.addBall({.position = {-2.0 * kRadius - kGap, 0},
                         .velocity = {kSpeed, 0},
                         .radius = kRadius,
                         .mass = kMass,
                         .bounciness = 1.0});
            for (int i = 1; i < kBalls; ++i)
                sim.addBall(
                    {.position = {2.0 * kRadius * (i - 1), 0}, .radius = kRadius, .mass = kMass, .bounciness = 1.0});
        },
    .probe = [](const SceneSize&, double) { return std::make_unique<CradleProbe>(); },
});

} // namespace
} // namespace bench
