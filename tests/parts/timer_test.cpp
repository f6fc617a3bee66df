// The timer (game/src/items/timer.cpp): switches what it names on the step at whose end the world's
// time first reaches its start + delay, over a range of delays and time steps; a timer that waits for
// a switch counts from the step it was switched; it names several things at once (wires).
#include "level_run.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace rube;
using namespace rube::game;

namespace {

std::string num(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

// A timer named "clock" wired to two bombs far apart (nothing else moves), or to `triggers` as written.
std::string timerLevel(double dt, double delay, const std::string& start) {
    return "name = \"t\"\n[world]\ntime_step = " + num(dt) + "\ngravity = [0, 0]\n" +
           "[[item]]\nkind = \"timer\"\nname = \"clock\"\nposition = [0, 0]\ndelay = " + num(delay) + "\nstart = \"" +
           start + "\"\ntriggers = [\"a\", \"b\"]\n" +
           "[[item]]\nkind = \"bomb\"\nname = \"a\"\nposition = [5, 0]\ntrigger = \"switch\"\n" +
           "[[item]]\nkind = \"bomb\"\nname = \"b\"\nposition = [-5, 0]\ntrigger = \"switch\"\n";
}

// The steps at which each bomb went off, in file order.
std::vector<std::int64_t> explosionSteps(const LevelRun& run) {
    std::vector<std::int64_t> steps;
    for (const GameEvent& e : run.events())
        if (e.kind == EventKind::explosion) steps.push_back(e.step);
    return steps;
}

std::string firstError(const std::string& text) {
    const SceneLoad load = parseScene(text, "t.toml");
    return load.errors.empty() ? std::string("no error") : load.errors.front().format();
}

} // namespace

TEST_CASE("timer: switches everything it names on the step its delay ends, over delays and time steps",
          "[parts][timer]") {
    for (const double dt : {1.0 / 60.0, 0.01, 1.0 / 120.0, 0.004}) {
        for (const double delay : {0.0, 0.013, 0.5, 1.0, 1.2345, 3.7}) {
            CAPTURE(dt, delay);
            const SceneLoad load = parseScene(timerLevel(dt, delay, "run"), "t.toml");
            REQUIRE(load.ok());
            LevelRun run(*load.scene, {});
            // The first step whose end is at or past the delay: t_n = n dt >= delay.
            const auto expected = static_cast<std::int64_t>(std::max(1.0, std::ceil(delay / dt - 1e-9)));
            for (int i = 0; i < expected + 5; ++i) run.step();
            const std::vector<std::int64_t> steps = explosionSteps(run);
            REQUIRE(steps.size() == 2);
            CHECK(steps[0] == expected);
            CHECK(steps[1] == expected);
            // Within one step of the delay, never before it.
            CHECK(static_cast<double>(steps[0]) * dt >= delay - 1e-9);
            CHECK(static_cast<double>(steps[0]) * dt < std::max(delay, dt) + dt);
            CHECK(run.states()[0].fired);
        }
    }
}

TEST_CASE("timer: one that starts when switched counts from the switch, and starts once", "[parts][timer]") {
    for (const double dt : {0.01, 1.0 / 60.0}) {
        for (const int switchedAt : {0, 7, 40}) {
            for (const double delay : {0.25, 1.0, 2.02}) {
                CAPTURE(dt, switchedAt, delay);
                const SceneLoad load = parseScene(timerLevel(dt, delay, "switch"), "t.toml");
                REQUIRE(load.ok());
                LevelRun run(*load.scene, {});
                const auto wait = static_cast<std::int64_t>(std::ceil(delay / dt - 1e-9));
                for (std::int64_t i = 0; i < switchedAt + wait + 5; ++i) {
                    if (i == switchedAt) run.toggle(0);
                    if (i == switchedAt + 3) run.toggle(0); // a second switch does not restart it
                    run.step();
                }
                const std::vector<std::int64_t> steps = explosionSteps(run);
                REQUIRE(steps.size() == 2);
                CHECK(steps[0] == switchedAt + wait);
            }
        }
    }
    // Never switched: it never fires.
    const SceneLoad load = parseScene(timerLevel(0.01, 0.1, "switch"), "t.toml");
    REQUIRE(load.ok());
    LevelRun run(*load.scene, {});
    for (int i = 0; i < 500; ++i) run.step();
    CHECK(explosionSteps(run).empty());
}

TEST_CASE("timer: read like every [[item]], and triggers names switched parts or ropes", "[parts][timer]") {
    const std::string head = "name = \"t\"\n[[item]]\nkind = \"bomb\"\nname = \"tnt\"\nposition = [3, 0]\n"
                             "trigger = \"switch\"\n[[item]]\nkind = \"timer\"\nposition = [0, 0]\n";
    CHECK(firstError(head + "delay = 1\ntriggers = \"tnt\"\n") == "no error");
    CHECK(firstError(head + "delay = 1\ntriggers = [\"tnt\"]\n") == "no error");
    CHECK(firstError(head + "triggers = \"tnt\"\n").find("delay") != std::string::npos);
    CHECK(firstError(head + "delay = -1\ntriggers = \"tnt\"\n").starts_with("t.toml:10:9: delay must be"));
    CHECK(firstError(head + "delay = 1\ntriggers = \"tn\"\n").ends_with("rope 'tn' (the level has: tnt)"));
    CHECK(firstError(head + "delay = 1\ntriggers = []\n") == "t.toml:11:12: triggers must name at least one thing");
    CHECK(firstError(head + "delay = 1\ntriggers = [\"tnt\", 3]\n") ==
          "t.toml:11:20: triggers must be a name or an array of names");
    CHECK(firstError(head + "delay = 1\nstart = \"later\"\ntriggers = \"tnt\"\n").find("run") != std::string::npos);
}
