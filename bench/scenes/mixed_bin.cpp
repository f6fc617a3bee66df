// mixed-bin (issue 26): 200 bodies, boxes of five sizes (0.1 to 0.5 m half-sizes, some long) and balls
// (r = 0.1 to 0.3 m), dropped in a seeded jumble (rows of ten, 0.9 m apart, up to 19 m) into a bin
// 10 m wide whose 25 m walls nothing can bounce over, 5 s. Errors: the
// fastest body at the end (m/s; a settled bin is still) and escapes (the runner counts balls that leave).
// --quick: 40 bodies.
#include "scene.hpp"

#include <algorithm>
#include <array>
#include <cstdint>

namespace bench {
namespace {

const std::array<LineSpec, 3> kBin{{{.a = {-5, 0}, .b = {5, 0}, .friction = 0.6},
                                    {.a = {-5, 0}, .b = {-5, 25}, .friction = 0.6},
                                    {.a = {5, 0}, .b = {5, 25}, .friction = 0.6}}};

// A small fixed generator (splitmix64), so every engine gets the same jumble on every machine.
double uniform(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}

void build(Sim& sim, int bodies) {
    for (const LineSpec& line : kBin) sim.addLine(line);
    std::uint64_t seed = 26;
    const Vec2 sizes[] = {{0.1, 0.1}, {0.2, 0.2}, {0.3, 0.15}, {0.5, 0.1}, {0.25, 0.25}};
    // Rows of ten 0.9 m apart from y = 1.5 m, jittered, every third body a ball.
    for (int k = 0; k < bodies; ++k) {
        const Vec2 at{-4.05 + (k % 10) * 0.9 + 0.2 * (uniform(seed) - 0.5), 1.5 + (k / 10) * 0.9};
        if (k % 3 == 2) {
            sim.addBall(
                {.position = at, .radius = 0.1 + 0.2 * uniform(seed), .mass = 0.5, .bounciness = 0.2, .friction = 0.6});
            continue;
        }
        sim.addBox({.position = at, .angle = 6.28 * uniform(seed), .halfExtents = sizes[k % 5], .bounciness = 0.2});
    }
}

class BinProbe final : public Probe {
public:
    void observe(const Sim&, int, double) override {}
    Metrics finish(const Sim& sim) override {
        double fastest = 0.0;
        for (int i = 0; i < sim.ballCount(); ++i) fastest = std::max(fastest, sim.ball(i).velocity.length());
        for (int i = 0; i < sim.boxCount(); ++i) fastest = std::max(fastest, sim.box(i).velocity.length());
        Metrics m;
        m.error = fastest;
        return m;
    }
};

[[maybe_unused]] const bool registered = registerScene({
    .name = "mixed-bin",
    .errorName = "fastest_final_speed_m_s",
    .error2Name = "",
    .logError = true,
    .gravity = {0.0, -9.81},
    .duration = [](const SceneSize& size) { return size.quick ? 1.0 : 5.0; },
    .boundsMin = {-10, -5},
    .boundsMax = {10, 40},
    .build = [](Sim& sim, const SceneSize& size) { build(sim, size.quick ? 40 : 200); },
    .probe = [](const SceneSize&, double) { return std::make_unique<BinProbe>(); },
    .boxes = true,
});

} // namespace
} // namespace bench
