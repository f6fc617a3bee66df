// bullet: a 0.05 m ball at 5, 50, 500 and 5000 m/s against a thin static line and against a thin
// line moving towards it, one lane each. With C = 1 a caught impact sends the ball back; a ball
// found past its line has tunnelled (discrete detection misses it once speed x dt > 2r + gap).

#include "scene.hpp"

#include <array>
#include <vector>

namespace bench {
namespace {

constexpr double kRadius = 0.05;
constexpr double kLaneSpacing = 3.0;
constexpr double kStartX = -5.0;
constexpr double kTargetSpeed = 2.0; // the moving line comes towards the ball at 2 m/s
constexpr std::array<double, 4> kSpeeds{5.0, 50.0, 500.0, 5000.0};

struct Lane {
    double speed;
    bool moving;
    double y;
};

std::vector<Lane> lanes(const SceneSize& size) {
    std::vector<Lane> all;
    for (const double speed : kSpeeds) {
        if (size.quick && (speed == 50.0 || speed == 5000.0)) continue;
        for (const bool moving : {false, true})
            all.push_back({speed, moving, kLaneSpacing * static_cast<double>(all.size())});
    }
    return all;
}

class BulletProbe final : public Probe {
public:
    explicit BulletProbe(const SceneSize& size) : lanes_(lanes(size)), tunnelled_(lanes_.size(), false) {}

    void observe(const Sim& sim, int, double t) override {
        for (std::size_t i = 0; i < lanes_.size(); ++i) {
            const double lineX = lanes_[i].moving ? -kTargetSpeed * t : 0.0;
            // Past the line means through it: the line is 2 m tall and the ball flies level at its middle.
            if (sim.ball(static_cast<int>(i)).position.x > lineX) tunnelled_[i] = true;
        }
    }
    Metrics finish(const Sim&) override {
        Metrics m;
        m.tunnels = 0;
        for (const bool t : tunnelled_) m.tunnels += t ? 1 : 0;
        m.error = m.tunnels;
        return m;
    }

private:
    std::vector<Lane> lanes_;
    std::vector<bool> tunnelled_;
};

[[maybe_unused]] const bool registered = registerScene({
    .name = "bullet",
    .errorName = "tunnels",
    .error2Name = "",
    .logError = false,
    .gravity = {0.0, 0.0},
    // 1.2 s: long enough for the 5 m/s ball to reach its line (about 1 s) and come back off it.
    .duration = [](const SceneSize&) { return 1.2; },
    .boundsMin = {-1e6, -1e6},
    .boundsMax = {1e6, 1e6},
    .build =
        [](Sim& sim, const SceneSize& size) {
            for (const Lane& lane : lanes(size)) {
                sim.addLine(
                    {.a = {0, lane.y - 1}, .b = {0, lane.y + 1}, .velocity = {lane.moving ? -kTargetSpeed : 0.0, 0.0}});
                sim.addBall({.position = {kStartX, lane.y},
                             .velocity = {lane.speed, 0},
                             .radius = kRadius,
                             .mass = 0.01,
                             .bounciness = 1.0,
                             .fast = true});
            }
        },
    .probe = [](const SceneSize& size, double) { return std::make_unique<BulletProbe>(size); },
});

} // namespace
} // namespace bench
