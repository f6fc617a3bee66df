// The pressure plate (game/src/items/pressure_plate.cpp): a ball of mass m dropped from a gap h onto
// it touches it at t_c = sqrt(2 h / g); the plate switches what it names within one step after
// t_c + hold when m >= min_mass, and never when m < min_mass, over balls, heights, holds and steps.
#include "level_run.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

using namespace rube;
using namespace rube::game;

namespace {

constexpr double kThickness = 0.08; // the plate's half thickness, m

std::string num(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

// A plate at the origin wired to a bomb far away, and a ball of `kind` (radius r) whose bottom is
// `gap` m above the plate's top.
std::string plateLevel(const std::string& kind, double r, double gap, double minMass, double hold, double dt) {
    return "name = \"t\"\n[world]\ntime_step = " + num(dt) + "\n" +
           "[[item]]\nkind = \"pressure-plate\"\nname = \"plate\"\nposition = [0, 0]\nmin_mass = " + num(minMass) +
           "\nhold = " + num(hold) + "\ntriggers = \"tnt\"\n" +
           "[[item]]\nkind = \"bomb\"\nname = \"tnt\"\nposition = [20, 0]\ntrigger = \"switch\"\n" +
           "[[item]]\nkind = \"" + kind + "\"\nposition = [0, " + num(kThickness + r + gap) + "]\n";
}

std::optional<std::int64_t> explosionStep(const LevelRun& run) {
    for (const GameEvent& e : run.events())
        if (e.kind == EventKind::explosion) return e.step;
    return std::nullopt;
}

} // namespace

TEST_CASE("pressure plate: a heavy enough ball presses it within one step of contact + hold, a light one never",
          "[parts][pressure-plate]") {
    struct Ball {
        const char* kind;
        double radius, mass;
    };
    for (const Ball ball : {Ball{"heavy", 0.3, 8.0}, Ball{"steel", 0.2, 4.0}, Ball{"bouncy", 0.25, 0.5}}) {
        for (const double minMass : {0.4, 2.0, 4.0, 6.0}) {
            for (const double gap : {0.3, 1.0, 2.5}) {
                for (const double hold : {0.0, 0.0371, 0.2, 0.123, 0.75}) {
                    for (const double dt : {0.01, 1.0 / 60.0}) {
                        CAPTURE(ball.kind, minMass, gap, hold, dt);
                        const SceneLoad load = parseScene(plateLevel(ball.kind, ball.radius, gap, minMass, hold, dt),
                                                          "t.toml");
                        REQUIRE(load.ok());
                        LevelRun run(*load.scene, {});
                        const double g = -run.world().def().gravity.y;
                        const double contact = std::sqrt(2.0 * gap / g); // free fall to the plate's top
                        const auto steps = static_cast<int>((contact + hold) / dt) + 30;
                        for (int i = 0; i < steps; ++i) run.step();
                        const auto fired = explosionStep(run);
                        if (ball.mass < minMass) {
                            CHECK_FALSE(fired);
                            CHECK_FALSE(run.states()[0].fired);
                            continue;
                        }
                        REQUIRE(fired);
                        const double at = static_cast<double>(*fired) * dt; // the end of the step it fired in
                        CHECK(at >= contact + hold - 1e-9);
                        CHECK(at < contact + hold + dt + 1e-9);
                    }
                }
            }
        }
    }
}

TEST_CASE("pressure plate: weight lifted before the hold ends starts the hold again", "[parts][pressure-plate]") {
    // A steel ball dropped on a plate whose hold is long, then knocked off by a bomb near it: never fires.
    const std::string level = "name = \"t\"\n[world]\ntime_step = 0.01\n[[item]]\nkind = \"pressure-plate\"\n"
                              "name = \"plate\"\nposition = [0, 0]\nhold = 1\ntriggers = \"far\"\n"
                              "[[item]]\nkind = \"bomb\"\nname = \"far\"\nposition = [20, 0]\ntrigger = \"switch\"\n"
                              "[[item]]\nkind = \"bomb\"\nname = \"near\"\nposition = [-1, 0.5]\ntrigger = \"timer\"\n"
                              "fuse = 0.8\nblast_radius = 3\nstrength = 40\n"
                              "[[item]]\nkind = \"steel\"\nposition = [0, 0.5]\n";
    const SceneLoad load = parseScene(level, "t.toml");
    REQUIRE(load.ok());
    LevelRun run(*load.scene, {});
    for (int i = 0; i < 300; ++i) run.step();
    int explosions = 0;
    for (const GameEvent& e : run.events()) explosions += e.kind == EventKind::explosion ? 1 : 0;
    CHECK(explosions == 1); // only the near bomb
    CHECK_FALSE(run.states()[0].fired);
}
