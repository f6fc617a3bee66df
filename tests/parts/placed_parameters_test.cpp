// [[place]] with the part's own keys (a plank's length, a bomb's trigger and fuse, a ball's radius):
// the kind reads them as in a level's [[item]], with its own ranges and rules, the placement rules
// see the item as given, a script writes them back as read, and actions and expectations may name
// a placed item.
#include "placement.hpp"
#include "scene_file.hpp"
#include "script_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace rube;
using namespace rube::game;

namespace {

// A floor, a 6 m wide zone above it, and a stock of each part these tests place.
const char* const kLevel = R"(name = "kit"
[world]
time_step = 0.01
[[segment]]
a = [-10, 0]
b = [10, 0]
[[item]]
kind = "target"
name = "post"
position = [8, 1]
[inventory]
plank = 3
bomb = 2
heavy = 2
[[zone]]
min = [-3, 0.2]
max = [3, 6]
[goal]
text = "hit the post"
condition = "target-hit"
target = "post"
)";

SceneDesc level() {
    const SceneLoad load = parseScene(kLevel, "kit.toml");
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return *load.scene;
}

ScriptLoad script(const std::string& body) {
    return parseScript("level = \"kit\"\n" + body, "kit.solution.toml", level());
}

std::string firstError(const ScriptLoad& load) { return load.errors.empty() ? "" : load.errors.front().format(); }

} // namespace

TEST_CASE("a placed plank is as long as its length key says, and the zone judges that length", "[parts][place]") {
    for (const double length : {0.5, 1.0, 2.0, 3.3, 5.8, 5.95, 6.2, 9.0}) {
        CAPTURE(length);
        const ScriptLoad load = script(
            "[[place]]\nkind = \"plank\"\nposition = [0, 3]\nlength = " + std::to_string(length) + "\n");
        // The board's capsule is length + 2 x 0.05 m end to end: it fits the 6 m zone while that is at most 6.
        const bool fits = length + 0.1 <= 6.0;
        CHECK(load.script.has_value() == fits);
        if (!fits) {
            CHECK(firstError(load).find("placement refused: plank at [0, 3]") != std::string::npos);
            continue;
        }
        const ItemDesc item = placedItem(load.script->placements.front());
        const ItemBodies bodies = item.kind->bodies(item);
        REQUIRE(bodies.segments.size() == 1);
        CHECK(std::abs((bodies.segments[0].b - bodies.segments[0].a).length() - length) < 1e-12);
    }
}

TEST_CASE("a placed part's keys are read by its kind: unknown keys, ranges and rules are refused", "[parts][place]") {
    CHECK(firstError(script("[[place]]\nkind = \"plank\"\nposition = [0, 3]\nlenght = 1\n"))
              .find("unknown key 'lenght' in [[place]] (did you mean 'length'?)") != std::string::npos);
    CHECK(firstError(script("[[place]]\nkind = \"plank\"\nposition = [0, 3]\nlength = -1\n")).find("length") !=
          std::string::npos);
    CHECK(firstError(script("[[place]]\nkind = \"bomb\"\nposition = [0, 3]\ntrigger = \"timer\"\n"))
              .find("a bomb with trigger 'timer' needs fuse = seconds") != std::string::npos);
    // A key of another kind is not this kind's: a heavy ball has no length.
    CHECK(firstError(script("[[place]]\nkind = \"heavy\"\nposition = [0, 3]\nlength = 1\n"))
              .find("unknown key 'length'") != std::string::npos);
    // A name is new: it may not repeat a level item's or an earlier placement's.
    CHECK(firstError(script("[[place]]\nkind = \"heavy\"\nposition = [0, 3]\nname = \"post\"\n"))
              .find("name 'post' is taken by an item of level 'kit'") != std::string::npos);
    CHECK(firstError(script("[[place]]\nkind = \"heavy\"\nposition = [0, 3]\nname = \"a\"\n"
                            "[[place]]\nkind = \"heavy\"\nposition = [2, 3]\nname = \"a\"\n"))
              .find("name 'a' is taken by the placement at line 2") != std::string::npos);
}

TEST_CASE("a placed bomb named by the script is detonated by name, at the action's step", "[parts][place]") {
    for (const int frame : {1, 7, 40}) {
        CAPTURE(frame);
        const ScriptLoad load = script(
            "[[place]]\nkind = \"bomb\"\nposition = [0, 1]\nname = \"mine\"\ntrigger = \"switch\"\n"
            "[[action]]\nstep = " +
            std::to_string(frame) +
            "\ndo = \"detonate\"\nitem = \"mine\"\n"
            "[[expect]]\nexplosion = \"mine\"\nbefore_step = 100\n");
        INFO(firstError(load));
        REQUIRE(load.script);
        const ScriptDesc& s = *load.script;
        LevelRun run(level(), s.placements);
        std::size_t next = 0;
        for (int step = 0; step < 60; ++step) {
            for (; next < s.actions.size() && s.actions[next].step == step; ++next)
                CHECK(takeAction(s.actions[next], run).empty());
            run.step();
        }
        int explosions = 0;
        for (const GameEvent& e : run.events())
            if (e.kind == EventKind::explosion) {
                ++explosions;
                CHECK(e.item == "mine");
                CHECK(e.step == frame); // steps taken when it went off: set off before step `frame`
            }
        CHECK(explosions == 1);
    }
    // Without the name the action names nothing the level or the script has.
    CHECK(firstError(script("[[place]]\nkind = \"bomb\"\nposition = [0, 1]\ntrigger = \"switch\"\n"
                            "[[action]]\nstep = 1\ndo = \"detonate\"\nitem = \"mine\"\n"))
              .find("unknown bomb 'mine'") != std::string::npos);
}

TEST_CASE("a script writes a placement's own keys back as it read them", "[parts][place]") {
    const std::string body =
        "[[place]]\nkind = \"bomb\"\nposition = [0, 1]\nname = \"mine\"\ntrigger = \"timer\"\nfuse = 1.5\n"
        "[[place]]\nkind = \"plank\"\nposition = [0, 3]\nangle = 10\nlength = 2.5\n";
    const ScriptLoad first = script(body);
    INFO(firstError(first));
    REQUIRE(first.script);
    const std::string written = writeScript(*first.script);
    INFO(written);
    CHECK(written.find("trigger = \"timer\"\nfuse = 1.5\n") != std::string::npos);
    CHECK(written.find("length = 2.5\n") != std::string::npos);
    const ScriptLoad again = parseScript(written, "again.toml", level());
    INFO(firstError(again));
    REQUIRE(again.script);
    CHECK(writeScript(*again.script) == written);
    const ItemDesc plank = placedItem(again.script->placements[1]);
    CHECK(std::abs((plank.kind->bodies(plank).segments[0].b - plank.kind->bodies(plank).segments[0].a).length() - 2.5) <
          1e-12);
}
