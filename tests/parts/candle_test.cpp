// The candle (game/src/items/candle.cpp): the rope it names is cut on the step at whose end the
// world's time first reaches its lighting + burn_time (so within one step after it), over a range of
// burn times and time steps; an unlit candle waits for a switch; the rope's ball then falls freely.
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

std::string num(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

// A ball hanging on a rope, and a candle under the rope set to burn it.
std::string candleLevel(double dt, double burnTime, bool lit) {
    return "name = \"t\"\n[world]\ntime_step = " + num(dt) + "\n" +
           "[[circle]]\nname = \"bob\"\nposition = [0, 3]\nradius = 0.3\n" +
           "[[rope]]\nname = \"cord\"\ncircle = \"bob\"\nanchor = [0, 5]\nlength = 2\n" +
           "[[item]]\nkind = \"candle\"\nname = \"wick\"\nposition = [0.5, 3.5]\nburns = \"cord\"\nburn_time = " +
           num(burnTime) + "\nlit = " + (lit ? "true" : "false") + "\n";
}

// The step in which the rope was cut (the first whose end finds it cut), within `limit` steps.
std::optional<std::int64_t> cutStep(LevelRun& run, std::int64_t limit, std::int64_t lightAt = -1) {
    for (std::int64_t i = 0; i < limit; ++i) {
        if (i == lightAt) run.toggle(0);
        run.step();
        if (run.world().ropes()[0].cut) return run.steps();
    }
    return std::nullopt;
}

std::string firstError(const std::string& text) {
    const SceneLoad load = parseScene(text, "t.toml");
    return load.errors.empty() ? std::string("no error") : load.errors.front().format();
}

} // namespace

TEST_CASE("candle: burns through its rope within one step of burn_time, over burn times and time steps",
          "[parts][candle]") {
    for (const double dt : {1.0 / 60.0, 0.01, 1.0 / 120.0, 0.004}) {
        for (const double burnTime : {0.0, 0.05, 0.5, 1.0, 2.345, 4.0}) {
            CAPTURE(dt, burnTime);
            const SceneLoad load = parseScene(candleLevel(dt, burnTime, true), "t.toml");
            REQUIRE(load.ok());
            LevelRun run(*load.scene, {});
            const auto step = cutStep(run, static_cast<std::int64_t>(burnTime / dt) + 10);
            REQUIRE(step);
            const double at = static_cast<double>(*step) * dt;
            CHECK(at >= burnTime - 1e-9);
            CHECK(at < std::max(burnTime, dt) + dt);
            CHECK(*step == std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(burnTime / dt - 1e-9))));
            // Cut: the ball it held leaves the rope's length below the anchor.
            for (int i = 0; i < static_cast<int>(0.8 / dt); ++i) run.step(); // free fall: 3.1 m in 0.8 s
            CHECK(run.world().circles()[0].position.y < 5.0 - 2.0 - 1.0);
        }
    }
}

TEST_CASE("candle: an unlit candle burns from the step a switch lights it, and is lit once", "[parts][candle]") {
    for (const double dt : {0.01, 1.0 / 60.0}) {
        for (const std::int64_t lightAt : {0, 13, 100}) {
            for (const double burnTime : {0.3, 1.5}) {
                CAPTURE(dt, lightAt, burnTime);
                const SceneLoad load = parseScene(candleLevel(dt, burnTime, false), "t.toml");
                REQUIRE(load.ok());
                LevelRun run(*load.scene, {});
                const auto step = cutStep(run, lightAt + static_cast<std::int64_t>(burnTime / dt) + 10, lightAt);
                REQUIRE(step);
                CHECK(*step == lightAt + static_cast<std::int64_t>(std::ceil(burnTime / dt - 1e-9)));
            }
        }
    }
    const SceneLoad load = parseScene(candleLevel(0.01, 0.1, false), "t.toml");
    REQUIRE(load.ok());
    LevelRun run(*load.scene, {});
    CHECK_FALSE(cutStep(run, 500)); // never lit, never cut
}

TEST_CASE("candle: read like every [[item]], and burns names a rope", "[parts][candle]") {
    const std::string head =
        "name = \"t\"\n[[circle]]\nname = \"bob\"\nposition = [0, 3]\nradius = 0.3\n[[rope]]\nname = "
        "\"cord\"\ncircle = \"bob\"\nanchor = [0, 5]\nlength = 2\n[[item]]\nkind = "
        "\"candle\"\nposition = [0, 0]\n";
    CHECK(firstError(head + "burns = \"cord\"\n") == "no error");
    CHECK(firstError(head + "burns = \"crod\"\n") == "t.toml:14:9: unknown rope 'crod' (did you mean 'cord'?)");
    CHECK(firstError(head + "burn_time = 1\n").find("burns") != std::string::npos);
    CHECK(firstError(head + "burns = \"cord\"\nburn_time = -1\n").starts_with("t.toml:15:13: burn_time must be"));
}
