// The script writer against the script reader: every shipped solution script, and scripts that use
// every key the reader knows, read, write and read back to the same script, and writing that
// again gives the same text (writeScript and parseScript, game/src/script_file.cpp).
#include "level_folder.hpp"
#include "scene_file.hpp"
#include "script_file.hpp"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

using namespace rube;
using namespace rube::game;

namespace {

const std::filesystem::path kLevels = RUBE_GAME_LEVELS_DIR;

SceneDesc loadLevel(const std::filesystem::path& file) {
    const SceneLoad load = loadSceneFile(file);
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return *load.scene;
}

// Every double as %.17g (the reader's numbers are compared bit for bit, not to a tolerance).
std::string exact(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

// Every field of a script but where it was written (the written file has its own lines), one
// per line, so two scripts compare as text and a failure shows the field that differs.
std::string fields(const ScriptDesc& s) {
    std::ostringstream out;
    out << "level " << s.level << "\nsteps " << (s.steps ? std::to_string(*s.steps) : "-") << "\nsize "
        << (s.size ? std::to_string(s.size->width) + "x" + std::to_string(s.size->height) : "-") << "\nevery "
        << (s.every ? std::to_string(*s.every) : "-") << '\n';
    for (const Placement& p : s.placements)
        out << "place kind " << itemKindName(p.kind) << " position " << exact(p.position.x) << ' '
            << exact(p.position.y) << " angle " << exact(p.angle) << " degrees " << exact(p.angleDegrees) << " name '"
            << p.name << "'\n";
    for (const Action& a : s.actions)
        out << "action step " << a.step << " do " << actionVerb(a.kind) << " item '" << a.item << "' angle "
            << (a.angle ? exact(*a.angle) : "-") << " degrees " << exact(a.angleDegrees) << " point "
            << (a.point ? exact(a.point->x) + ' ' + exact(a.point->y) : "-") << " target '" << a.target << "' arc "
            << (a.highArc ? "high" : "low") << '\n';
    for (const Expectation& e : s.expectations) out << "expect " << e.describe() << '\n';
    return out.str();
}

// Reads `text` as a script of `level`, writes it, reads that back and writes it again: the two
// scripts read must agree field for field, and the two texts written must be the same.
void checkRoundTrip(const std::string& text, const std::string& name, const SceneDesc& level) {
    INFO(name);
    const ScriptLoad first = parseScript(text, name, level);
    INFO((first.errors.empty() ? std::string() : first.errors.front().format()));
    REQUIRE(first.script);
    const std::string written = writeScript(*first.script, "# written back by script_file_test\n");
    INFO("written:\n" << written);
    const ScriptLoad second = parseScript(written, name + " (written)", level);
    INFO((second.errors.empty() ? std::string() : second.errors.front().format()));
    REQUIRE(second.script);
    CHECK(fields(*second.script) == fields(*first.script));
    CHECK(writeScript(*second.script, "# written back by script_file_test\n") == written);
}

std::string readText(const std::filesystem::path& file) {
    SceneError error;
    const std::optional<std::string> text = readTextFile(file, error);
    INFO(error.format());
    REQUIRE(text);
    return *text;
}

} // namespace

TEST_CASE("every shipped script reads, writes and reads back to the same script", "[level][script]") {
    int solutions = 0;
    for (const LevelFileRole role : {LevelFileRole::solution, LevelFileRole::alternative, LevelFileRole::wrong}) {
        for (const LevelFile& file : levelFilesIn(kLevels, role)) {
            const SceneDesc level = loadLevel(levelOfScript(file));
            checkRoundTrip(readText(file.path), file.path.filename().string(), level);
            if (role == LevelFileRole::solution) ++solutions;
        }
    }
    // Sixteen levels ship, each with its solution; none may be skipped unseen.
    CHECK(solutions >= 16);
}

TEST_CASE("every key a script may hold is written back as it was read", "[level][script]") {
    // Between them, these use every action, every kind of expectation (with and without `by`), steps, a named and a
    // turned placement, aims at an angle (with and without an arc), a point and an item, and
    // numbers that are not short in binary (0.1, 1/3 written out).
    const SceneDesc cannon = loadLevel(kLevels / "cannon-arc.toml");
    checkRoundTrip("level = \"cannon-arc\"\nsteps = 900\n[capture]\nevery = 3\n"
                   "[[action]]\nstep = 0\ndo = \"rotate\"\nitem = \"gun\"\nangle = 33.333333333333336\n"
                   "[[action]]\nstep = 1\ndo = \"aim\"\nitem = \"gun\"\nangle = 40.1\narc = \"high\"\n"
                   "[[action]]\nstep = 2\ndo = \"aim\"\nitem = \"gun\"\npoint = [0.1, -2.7]\n"
                   "[[action]]\nstep = 2\ndo = \"aim\"\nitem = \"gun\"\ntarget = \"bullseye\"\narc = \"low\"\n"
                   "[[action]]\nstep = 3\ndo = \"fire-when\"\nitem = \"gun\"\ntarget = \"bullseye\"\n"
                   "[[action]]\nstep = 9\ndo = \"fire\"\nitem = \"gun\"\n"
                   "[[expect]]\nshot = \"gun\"\nbefore_step = 10\n[[expect]]\nhit = \"bullseye\"\nby = "
                   "\"gun\"\nbefore_step = 500\n",
                   "cannon-arc every key", cannon);
    // chain-reaction lets no click act (clicks = []); without that key its bomb and switch take them.
    SceneDesc chain = loadLevel(kLevels / "chain-reaction.toml");
    chain.level.clicks.reset();
    checkRoundTrip("level = \"chain-reaction\"\n[capture]\nsize = [320, 180]\n"
                   "[[place]]\nkind = \"heavy\"\nposition = [-4.05, 5.1]\nname = \"lump \\\"one\\\"\"\n"
                   "[[action]]\nstep = 4\ndo = \"toggle\"\nitem = \"button\"\n"
                   "[[action]]\nstep = 7\ndo = \"detonate\"\nitem = \"tnt\"\n"
                   "[[expect]]\nexplosion = \"tnt\"\nbefore_step = 8\n[[expect]]\ngoal = true\nby = \"lump "
                   "\\\"one\\\"\"\nbefore_step = 900\n",
                   "chain-reaction every key", chain);
    const SceneDesc rope = loadLevel(kLevels / "rope.toml");
    checkRoundTrip("level = \"rope\"\n[[action]]\nstep = 5\ndo = \"cut\"\nitem = \"rope\"\n", "rope cut", rope);
    const SceneDesc ramp = loadLevel(kLevels / "ramp.toml");
    checkRoundTrip("level = \"ramp\"\n[[place]]\nkind = \"ramp\"\nposition = [-4.5, 2.5]\nangle = -29.5\n",
                   "ramp turned", ramp);
    // -0 keeps its sign (written as the integer 0 it would come back +0); a cannon aimed at -0 degrees.
    checkRoundTrip("level = \"ramp\"\n[[place]]\nkind = \"ramp\"\nposition = [-4.5, 2.5]\nangle = -0.0\n", "ramp at -0",
                   ramp);
    checkRoundTrip("level = \"cannon-arc\"\n[[action]]\nstep = 0\ndo = \"aim\"\nitem = \"gun\"\nangle = -0.0\n",
                   "aim at -0", cannon);
}
