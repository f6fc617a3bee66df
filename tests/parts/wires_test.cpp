// Wires (game/src/items/wires.hpp): any trigger (switch, timer, pressure plate, detector) switches
// every part it names that is switched (by PartRole::triggered, never by kind) and cuts every
// [[rope]] it names, in one step; a trigger may switch another trigger (a switch starts a timer).
#include "level_run.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace rube;
using namespace rube::game;

namespace {

int count(const LevelRun& run, EventKind kind) {
    int n = 0;
    for (const GameEvent& e : run.events()) n += e.kind == kind ? 1 : 0;
    return n;
}

} // namespace

TEST_CASE("wires: a switch names several things and switches each, whatever its kind", "[parts][wires]") {
    // Every kind that plays `triggered`, named by one switch, with a rope: one click switches all.
    std::string level =
        "name = \"t\"\n[world]\ngravity = [0, 0]\n[[circle]]\nname = \"bob\"\nposition = [0, "
        "-3]\nradius = 0.2\n[[rope]]\nname = \"cord\"\ncircle = \"bob\"\nanchor = [0, -2]\nlength = 1\n";
    std::string names = "\"cord\"";
    int bombs = 0;
    double x = 0.0;
    for (ItemKind kind : partKindsPlaying(PartRole::triggered)) {
        x += 10.0;
        const std::string name = "p" + std::to_string(static_cast<int>(x));
        std::string keys;
        if (kind->name() == std::string_view("bomb")) keys = "trigger = \"switch\"\n", ++bombs;
        if (kind->name() == std::string_view("timer")) keys = "delay = 0\nstart = \"switch\"\ntriggers = \"cord\"\n";
        if (kind->name() == std::string_view("candle")) keys = "burns = \"cord\"\nlit = false\n";
        if (kind->name() == std::string_view("scissors")) keys = "cuts = \"cord\"\n";
        level += "[[item]]\nkind = \"" + std::string(kind->name()) + "\"\nname = \"" + name + "\"\nposition = [" +
                 std::to_string(x) + ", 0]\n" + keys;
        names += ", \"" + name + "\"";
    }
    level += "[[item]]\nkind = \"switch\"\nname = \"s\"\nposition = [-5, 0]\ntriggers = [" + names + "]\n";
    const SceneLoad load = parseScene(level, "t.toml");
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    LevelRun run(*load.scene, {});
    const int sw = run.find("s");
    run.toggle(sw);
    CHECK(run.world().ropes()[0].cut);
    CHECK(count(run, EventKind::shot) == 1);          // the cannon fired
    CHECK(count(run, EventKind::explosion) == bombs); // the bombs went off
    // Fans, magnets and rockets flipped; the timer started (switch-started, it fires on the next step).
    for (std::size_t i = 0; i < run.items().size(); ++i) {
        const std::string_view kind = run.items()[i].kind->name();
        if (kind == "timer") CHECK(run.states()[i].since.has_value());
        if (kind == "laser") CHECK(run.states()[i].pressed);
        if (kind == "candle") CHECK(run.states()[i].since.has_value());
    }
    CHECK(partKindsPlaying(PartRole::triggered).size() >= 8);
}

TEST_CASE("wires: a trigger may start another: a switch starts a timer that sets off a bomb", "[parts][wires]") {
    const std::string level =
        "name = \"t\"\n[world]\ntime_step = 0.01\n"
        "[[item]]\nkind = \"switch\"\nname = \"s\"\nposition = [0, 0]\ntriggers = \"clock\"\n"
        "[[item]]\nkind = \"timer\"\nname = \"clock\"\nposition = [3, 0]\ndelay = 0.5\nstart = \"switch\"\n"
        "triggers = [\"tnt\"]\n"
        "[[item]]\nkind = \"bomb\"\nname = \"tnt\"\nposition = [9, 0]\ntrigger = \"switch\"\n";
    const SceneLoad load = parseScene(level, "t.toml");
    REQUIRE(load.ok());
    LevelRun run(*load.scene, {});
    for (int i = 0; i < 100; ++i) {
        if (i == 20) run.toggle(0);
        run.step();
        if (count(run, EventKind::explosion) == 1) {
            CHECK(run.steps() == 20 + 50);
            return;
        }
    }
    FAIL("the bomb never went off");
}
