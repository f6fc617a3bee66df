// The play session without a window: the editing rules the player meets through the mouse and
// keys, the debug keys, the pacing, and the recorded script, which must replay through the same
// path `rube run` takes to the very same state (compared by the state hash).
#include "play_helpers.hpp"
#include "play_session.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace rube;
using namespace rube::game;
using render::Key;
using render::KeyAction;
using render::MouseButton;
using namespace rube::game::play_test;

namespace {

constexpr render::FrameSize kFrame{640, 360};

// A test level: a floor, a gun, a switch-less bomb, two planks and a heavy ball to place.
SceneDesc workshop() {
    const SceneLoad load = parseScene("name = \"workshop\"" + std::string(kTestBench) + R"(
[[item]]
kind = "bomb"
name = "boom"
position = [6, 0.5]
trigger = "timer"
fuse = 100
[[item]]
kind = "target"
name = "flag"
position = [6, 6]
)" + std::string(kTestStock),
                                      "workshop.toml");
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return *load.scene;
}

void moveToPixel(PlaySession& s, render::Point p) { s.cursorMoved(p.x, p.y); }

void click(PlaySession& s, Vec2 at, MouseButton button = MouseButton::left) {
    moveTo(s, at);
    s.mouseButton(button, true);
    s.mouseButton(button, false);
}

// Replays a script the way `rube run` does: placements, then each step's actions before the step.
std::uint64_t replayHash(const SceneDesc& level, const std::string& text, std::int64_t steps) {
    const ScriptLoad load = parseScript(text, "recorded.toml", level);
    INFO(text);
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.script);
    LevelRun run(level, load.script->placements);
    std::size_t next = 0;
    for (std::int64_t i = 0;; ++i) {
        for (; next < load.script->actions.size() && load.script->actions[next].step == i; ++next)
            REQUIRE(takeAction(load.script->actions[next], run).empty());
        if (i == steps) break;
        run.step();
    }
    return stateHash(run.world());
}

} // namespace

TEST_CASE("play: items dragged from the bar are placed, counted, moved, turned and removed", "[play]") {
    PlaySession s(workshop(), "workshop.toml", kFrame);
    CHECK(s.windowSize().height == kFrame.height + InventoryBar::kHeight);
    CHECK(s.remaining(partKind("plank")) == 2);
    place(s, partKind("plank"), {-2.02, 3.01});
    REQUIRE(s.placements().size() == 1);
    // Snapped to the 5 cm grid, so the script reads -2 and 3.
    CHECK(s.placements()[0].position.x == -2.0);
    CHECK(s.placements()[0].position.y == 3.0);
    CHECK(s.remaining(partKind("plank")) == 1);
    CHECK_THAT(s.message(), Catch::StartsWith("placed plank at [-2, 3]"));

    // Outside every zone: refused with the rule's reason, and the plank is back in the bar.
    place(s, partKind("plank"), {6.0, 3.0});
    CHECK(s.placements().size() == 1);
    CHECK_THAT(s.message(), Catch::StartsWith("not placed: plank at [6, 3]: not inside a zone (it spans"));
    CHECK(s.remaining(partKind("plank")) == 1);

    // Onto the first plank: refused for the overlap.
    place(s, partKind("plank"), {-2.0, 3.0});
    CHECK_THAT(s.message(), Catch::Contains("overlaps your plank (placement 1)"));

    // The wheel turns a placed plank under the cursor by 15 degrees a notch; a ball does not turn.
    moveTo(s, {-2.0, 3.0});
    s.scrolled(1.0f);
    CHECK(s.placements()[0].angleDegrees == 15.0);
    s.key(Key::rightBracket, KeyAction::press);
    s.key(Key::rightBracket, KeyAction::repeat);
    CHECK(s.placements()[0].angleDegrees == -15.0);
    place(s, partKind("heavy"), {2.0, 4.0});
    REQUIRE(s.placements().size() == 2);
    moveTo(s, {2.0, 4.0});
    s.scrolled(1.0f);
    CHECK_THAT(s.message(), Catch::Contains("a heavy has no angle to turn"));

    // Dragging a placed item moves it; a refused move puts it back where it was.
    moveTo(s, {2.0, 4.0});
    s.mouseButton(MouseButton::left, true);
    moveTo(s, {3.0, 2.0});
    s.mouseButton(MouseButton::left, false);
    CHECK(s.placements()[1].position.x == 3.0);
    moveTo(s, {3.0, 2.0});
    s.mouseButton(MouseButton::left, true);
    moveTo(s, {7.0, 2.0});
    s.mouseButton(MouseButton::left, false);
    CHECK(s.placements()[1].position.x == 3.0);
    CHECK_THAT(s.message(), Catch::StartsWith("not placed"));

    // The inventory runs out: the bar says so and nothing is dragged.
    moveToPixel(s, *s.slotPixel(partKind("heavy")));
    s.mouseButton(MouseButton::left, true);
    CHECK_THAT(s.message(), Catch::StartsWith("no heavy left: the level gives 1"));
    s.mouseButton(MouseButton::left, false);

    // Right-click removes; Delete removes the one under the cursor.
    click(s, {3.0, 2.0}, MouseButton::right);
    CHECK(s.placements().size() == 1);
    CHECK(s.remaining(partKind("heavy")) == 1);
    moveTo(s, {-2.0, 3.0});
    s.key(Key::deleteKey, KeyAction::press);
    CHECK(s.placements().empty());

    // Dropping on the bar puts a new item back.
    moveToPixel(s, *s.slotPixel(partKind("plank")));
    s.mouseButton(MouseButton::left, true);
    moveTo(s, {0.0, 3.0});
    moveToPixel(s, *s.slotPixel(partKind("heavy")));
    s.mouseButton(MouseButton::left, false);
    CHECK(s.placements().empty());
    CHECK_THAT(s.message(), Catch::StartsWith("put back: plank"));
}

TEST_CASE("play: the debug keys pause, slow, show and clear trails, reset and quit", "[play]") {
    PlaySession s(workshop(), "workshop.toml", kFrame);
    place(s, partKind("heavy"), {0.0, 5.0});
    s.key(Key::space, KeyAction::press);
    REQUIRE(s.mode() == PlaySession::Mode::running);
    // Real-time pacing: 0.05 s at a 0.01 s step is five steps.
    s.advance(0.05);
    CHECK(s.run()->steps() == 5);
    s.key(Key::p, KeyAction::press);
    s.advance(0.05);
    CHECK(s.run()->steps() == 5);
    s.key(Key::p, KeyAction::press);
    // Slow motion runs at a tenth of real time.
    s.key(Key::s, KeyAction::press);
    CHECK(s.slowMotion());
    s.advance(0.5);
    CHECK(s.run()->steps() == 10);
    s.key(Key::s, KeyAction::press);
    // A long stall does not make the machine race: at most 8 steps per call.
    s.advance(10.0);
    CHECK(s.run()->steps() == 18);
    // A held key's repeats toggle nothing.
    s.key(Key::d, KeyAction::press);
    s.key(Key::d, KeyAction::repeat);
    CHECK(s.trailsShown());
    render::DrawList withTrails;
    s.draw(withTrails);
    s.key(Key::c, KeyAction::press);
    render::DrawList cleared;
    s.draw(cleared);
    // The cleared trails draw fewer strokes: a polyline needs two points.
    CHECK(cleared.size() < withTrails.size());
    // R: back to editing with the placement kept; editing keys work again.
    s.key(Key::r, KeyAction::press);
    CHECK(s.mode() == PlaySession::Mode::editing);
    CHECK(s.placements().size() == 1);
    CHECK(s.run() == nullptr);
    CHECK_FALSE(s.quitRequested());
    s.key(Key::escape, KeyAction::press);
    CHECK(s.quitRequested());
}

TEST_CASE("play: the recorded script replays to the same state", "[play]") {
    const SceneDesc level = workshop();
    PlaySession s(level, "workshop.toml", kFrame);
    place(s, partKind("plank"), {-1.0, 2.0});
    moveTo(s, {-1.0, 2.0});
    s.scrolled(-1.0f);
    place(s, partKind("heavy"), {-1.0, 4.0});
    // Aim by dragging from the cannon: the angle snaps to half degrees.
    moveTo(s, {-6.0, 0.6});
    s.mouseButton(MouseButton::left, true);
    moveTo(s, {-5.0, 1.8});
    s.mouseButton(MouseButton::left, false);
    CHECK_THAT(s.message(), Catch::StartsWith("aim gun: 50 degrees"));
    s.key(Key::space, KeyAction::press);
    for (int i = 0; i < 25; ++i) s.step();
    click(s, {-6.0, 0.6}); // fires the gun at step 25
    for (int i = 0; i < 15; ++i) s.step();
    click(s, {6.0, 0.5});  // sets the bomb off at step 40, long before its fuse
    click(s, {-6.0, 0.6}); // the gun has fired already: nothing is recorded
    CHECK_THAT(s.message(), Catch::Contains("has fired already"));
    for (int i = 0; i < 60; ++i) s.step();
    REQUIRE(s.actions().size() == 2);
    CHECK(s.actions()[0].step == 25);
    CHECK(s.actions()[1].step == 40);
    CHECK(s.actions()[1].kind == ActionKind::detonate);

    const std::string script = s.recordedScript();
    CHECK_THAT(script, Catch::Contains("angle = -15"));
    CHECK_THAT(script, Catch::Contains("angle = 50"));
    CHECK(replayHash(level, script, s.run()->steps()) == stateHash(s.run()->world()));

    // After R the script is the set-up as it stands, without the run's actions.
    s.key(Key::r, KeyAction::press);
    CHECK_THAT(s.recordedScript(), !Catch::Contains("do = \"fire\""));
}

TEST_CASE("play: a loaded solution plays to its goal and records an expectation of it", "[play]") {
    for (const char* name : {"ramp", "bucket", "magnet"}) {
        INFO(name);
        const SceneDesc level = loadLevel(name);
        const ScriptLoad solution = loadScriptFile(kLevels / (std::string(name) + ".solution.toml"), level);
        REQUIRE(solution.script);
        PlaySession s(level, std::string(name) + ".toml", kFrame);
        s.load(*solution.script);
        CHECK(s.placements().size() == solution.script->placements.size());
        s.key(Key::space, KeyAction::press);
        while (!s.run()->goalStep() && s.run()->steps() < 2000) s.step();
        REQUIRE(s.run()->goalStep());
        const std::string script = s.recordedScript();
        CHECK_THAT(script, Catch::Contains("before_step = " + std::to_string(*s.run()->goalStep() + 1)));
        CHECK(replayHash(level, script, s.run()->steps()) == stateHash(s.run()->world()));
    }
}

TEST_CASE("play: every kind of action a loaded script takes is recorded in the script's own words", "[play]") {
    // The rope is cut by a script action here, not by the switch: the recording must say "cut".
    const SceneDesc level = loadLevel("rope");
    const ScriptLoad script = parseScript("level = \"rope\"\n[[action]]\nstep = 5\ndo = \"cut\"\nitem = \"rope\"\n",
                                          "cut.toml", level);
    INFO((script.errors.empty() ? std::string() : script.errors.front().format()));
    REQUIRE(script.script);
    PlaySession s(level, "rope.toml", kFrame);
    s.load(*script.script);
    s.key(Key::space, KeyAction::press);
    while (s.run()->steps() < 20) s.step();
    REQUIRE(s.run()->world().ropes()[0].cut);
    const std::string recorded = s.recordedScript();
    CHECK_THAT(recorded, Catch::Contains("do = \"cut\"\nitem = \"rope\""));
    CHECK(replayHash(level, recorded, s.run()->steps()) == stateHash(s.run()->world()));
}

TEST_CASE("play: a click on a part the level's clicks leave out does nothing but say so", "[play]") {
    // chain-reaction has clicks = []: its bomb must be set off by the switch, not by a click.
    const SceneDesc level = loadLevel("chain-reaction");
    PlaySession s(level, "chain-reaction.toml", kFrame);
    s.key(Key::space, KeyAction::press);
    for (int i = 0; i < 5; ++i) s.step();
    click(s, {0.0, 0.25}); // the bomb
    CHECK(s.message() == "this level lets no click act on 'tnt'");
    for (int i = 0; i < 5; ++i) s.step();
    CHECK_FALSE(s.run()->states()[static_cast<std::size_t>(s.run()->find("tnt"))].detonatedAt);
    CHECK_THAT(s.recordedScript(), !Catch::Contains("detonate"));
}
