// pool-break: no gravity, a cue ball at 8 m/s breaks a rack of 15 on a table with four cushions.
// The reference is rube's exact method at a tiny step (1/3840 s); the error is the RMS distance of
// the balls from their reference positions, sampled every 1/30 s over the first 2 s.

#include "scene.hpp"

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

namespace bench {
namespace {

constexpr double kRadius = 0.0286;
constexpr double kSampleRate = 30.0; // every rate of the sweep (30..240 Hz) lands on these times
constexpr double kReferenceRate = 3840.0;

double duration(const SceneSize& size) { return size.quick ? 0.5 : 2.0; }

void build(Sim& sim, const SceneSize&) {
    // The cushions: a little less lively than the balls (pair C = 0.75 x 0.95).
    const std::array<Vec2, 4> corner{{{0, 0}, {2.54, 0}, {2.54, 1.27}, {0, 1.27}}};
    for (std::size_t i = 0; i < corner.size(); ++i)
        sim.addLine({.a = corner[i], .b = corner[(i + 1) % corner.size()], .bounciness = 0.75});
    const BallSpec ball{.radius = kRadius, .mass = 0.17, .bounciness = 0.95};
    BallSpec cue = ball;
    cue.position = {0.635, 0.635};
    cue.velocity = {8, 0};
    sim.addBall(cue);
    // The rack: rows of 1 to 5 balls, 0.2 mm apart so that none starts in contact.
    const double dx = 2.0 * kRadius * std::sqrt(3.0) / 2.0 + 0.0002, dy = 2.0 * kRadius + 0.0002;
    for (int row = 0; row < 5; ++row) {
        for (int k = 0; k <= row; ++k) {
            BallSpec b = ball;
            b.position = {1.905 + row * dx, 0.635 + (k - row / 2.0) * dy};
            sim.addBall(b);
        }
    }
}

using Samples = std::vector<std::vector<Vec2>>; // [sample][ball]

// The reference run: rube's exact method at 1/3840 s, sampled at the same times as the bench runs.
const Samples& reference(const SceneSize& size) {
    static std::map<bool, Samples> cache; // one per size; the bench is single-threaded
    auto [it, added] = cache.try_emplace(size.quick);
    if (!added) return it->second;
    const Engine* exact = nullptr;
    for (const Engine& e : engines())
        if (e.name == "rube-exact") exact = &e;
    if (!exact) throw std::runtime_error("pool-break needs rube-exact for its reference");
    auto sim = exact->make({{0.0, 0.0}, 1.0 / kReferenceRate});
    build(*sim, size);
    const int every = static_cast<int>(std::lround(kReferenceRate / kSampleRate));
    const int steps = static_cast<int>(std::lround(duration(size) * kReferenceRate));
    for (int step = 1; step <= steps; ++step) {
        sim->step();
        if (step % every != 0) continue;
        auto& sample = it->second.emplace_back();
        for (int i = 0; i < sim->ballCount(); ++i) sample.push_back(sim->ball(i).position);
    }
    return it->second;
}

class PoolBreakProbe final : public Probe {
public:
    PoolBreakProbe(const Samples& reference, double timeStep)
        : reference_(reference), every_(std::max(1, static_cast<int>(std::lround(1.0 / (kSampleRate * timeStep))))) {}

    void observe(const Sim& sim, int step, double) override {
        if (step % every_ != 0) return;
        const std::size_t k = static_cast<std::size_t>(step / every_) - 1;
        if (k >= reference_.size()) return;
        for (int i = 0; i < sim.ballCount(); ++i) {
            sumSquares_ += sim.ball(i).position.distance(reference_[k][static_cast<std::size_t>(i)]) *
                           sim.ball(i).position.distance(reference_[k][static_cast<std::size_t>(i)]);
            ++count_;
        }
    }
    Metrics finish(const Sim&) override {
        Metrics m;
        m.error = count_ > 0 ? std::sqrt(sumSquares_ / count_) : 0.0;
        return m;
    }

private:
    const Samples& reference_;
    int every_;
    double sumSquares_ = 0.0;
    long count_ = 0;
};

[[maybe_unused]] const bool registered = registerScene({
    .name = "pool-break",
    .errorName = "rms_distance_from_reference_m",
    .error2Name = "",
    .logError = true,
    .gravity = {0.0, 0.0},
    .duration = duration,
    .boundsMin = {-1, -1},
    .boundsMax = {3.54, 2.27},
    .build = build,
    .probe = [](const SceneSize& size,
                double timeStep) { return std::make_unique<PoolBreakProbe>(reference(size), timeStep); },
});

} // namespace
} // namespace bench
