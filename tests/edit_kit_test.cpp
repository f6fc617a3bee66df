// The editor's kit without a window (EditSession sees the window only as an InputListener): the
// level's hints, loaded or typed, changed and removed; the goal's kind, target, time limit and
// text; the [view] drawn with a drag; a part's own keys typed and checked as the reader checks them.
// The editor in a real window, saving and replaying a level, is tests/window_play_test.cpp.
#include "edit_session.hpp"
#include "level_writer.hpp"
#include "play_helpers.hpp"
#include "scene_file.hpp"
#include "script_file.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <optional>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>

using namespace rube;
using namespace rube::game;
using render::Key;
using render::KeyAction;
using render::MouseButton;

namespace {

constexpr render::FrameSize kFrame{640, 360};

SceneDesc levelOf(const std::string& text) {
    const SceneLoad load = parseScene(text, "kit.toml");
    INFO((load.ok() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return *load.scene;
}

// The play tests' bench (a floor, the view, the cannon "gun"), two targets, a bucket, a switch that
// fires the gun, and `extra`.
SceneDesc bench(const std::string& extra = "") {
    return levelOf("name = \"kit\"" + std::string(play_test::kTestBench) + R"(
[[item]]
kind = "target"
name = "flag"
position = [3, 1]
[[item]]
kind = "target"
name = "pennant"
position = [5, 1]
[[item]]
kind = "bucket"
name = "pail"
position = [-3, 0.1]
[[item]]
kind = "switch"
name = "button"
position = [6, 0.5]
triggers = "gun"
)" + extra);
}

// What a hand does: keys pressed and let go, characters typed, the cursor over a world point.
struct Hand {
    EditSession& editor;
    void press(Key key) {
        editor.key(key, KeyAction::press);
        editor.key(key, KeyAction::release);
    }
    void control(Key key) {
        editor.key(Key::control, KeyAction::press);
        press(key);
        editor.key(Key::control, KeyAction::release);
    }
    // As GLFW sends it: the key's event, then its character.
    void type(const std::string& text) {
        for (const char c : text) editor.typed(static_cast<char32_t>(c));
    }
    void erase(int characters) {
        for (int i = 0; i < characters; ++i) press(Key::backspace);
    }
    void at(Vec2 world) {
        const render::Point p = editor.pixelOf(world);
        editor.cursorMoved(p.x, p.y);
    }
    void drag(Vec2 from, Vec2 to) {
        at(from);
        editor.mouseButton(MouseButton::left, true);
        at((from + to) * 0.5);
        at(to);
        editor.mouseButton(MouseButton::left, false);
    }
};

bool sameBox(const Aabb& a, const Aabb& b) { return a.min == b.min && a.max == b.max; }

// The level as the editor would save it, read back by the level reader.
SceneDesc readBack(const EditSession& editor) {
    const std::string text = writeLevel(editor.level());
    const SceneLoad load = parseScene(text, "saved.toml");
    INFO(text);
    INFO((load.ok() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return *load.scene;
}

} // namespace

TEST_CASE("the editor changes and removes a level's hints, loaded or typed, and undoes it", "[edit]") {
    // Loaded hints count from 1 to n; each is picked with J in turn, the pick wrapping round.
    const int loaded = GENERATE(1, 2, 3);
    std::string hints;
    for (int i = 1; i <= loaded; ++i) hints += "[[hint]]\ntext = \"hint number " + std::to_string(i) + "\"\n";
    EditSession editor(bench(hints), "kit.toml", kFrame);
    Hand hand{editor};
    REQUIRE(editor.level().level.hints.size() == static_cast<std::size_t>(loaded));
    for (int i = 0; i <= loaded; ++i) {
        hand.press(Key::j);
        const int shown = i % loaded + 1;
        CHECK_THAT(editor.message(),
                   Catch::StartsWith("hint " + std::to_string(shown) + " of " + std::to_string(loaded) +
                                     ": hint number " + std::to_string(shown)));
    }
    // The last J picked hint 1: Enter opens it in the bar, typed over from its end.
    hand.press(Key::enter);
    CHECK_THAT(editor.message(), Catch::EndsWith("hint number 1_"));
    hand.erase(8);
    hand.type("one, changed");
    hand.press(Key::enter);
    REQUIRE(editor.level().level.hints.size() == static_cast<std::size_t>(loaded));
    CHECK(editor.level().level.hints[0].text == "hint one, changed");

    // J then Delete removes the last hint; Delete without a pick removes no hint.
    for (int i = 0; i < loaded; ++i) hand.press(Key::j);
    hand.press(Key::deleteKey);
    CHECK(editor.level().level.hints.size() == static_cast<std::size_t>(loaded - 1));
    hand.press(Key::deleteKey);
    CHECK(editor.level().level.hints.size() == static_cast<std::size_t>(loaded - 1));
    // A changed text emptied is refused (the reader refuses an empty hint); Esc leaves it as it was.
    if (loaded > 1) {
        hand.press(Key::j);
        hand.press(Key::enter);
        hand.erase(40);
        hand.press(Key::enter);
        CHECK_THAT(editor.message(), Catch::StartsWith("a hint's text must not be empty"));
        hand.press(Key::j);
        hand.press(Key::enter);
        hand.type(" and more");
        hand.press(Key::escape);
        CHECK_FALSE(editor.quitRequested());
        CHECK(editor.level().level.hints[0].text == "hint one, changed");
    }
    // The written level holds what is left, in order; undo brings back the removed and the old text.
    const SceneDesc saved = readBack(editor);
    REQUIRE(saved.level.hints.size() == static_cast<std::size_t>(loaded - 1));
    for (int i = 1; i < loaded - 1; ++i)
        CHECK(saved.level.hints[static_cast<std::size_t>(i)].text == "hint number " + std::to_string(i + 1));
    hand.control(Key::z);
    hand.control(Key::z);
    REQUIRE(editor.level().level.hints.size() == static_cast<std::size_t>(loaded));
    CHECK(editor.level().level.hints[0].text == "hint number 1");
    CHECK(editor.level().level.hints.back().text == "hint number " + std::to_string(loaded));

    // With no hints J says so, and H still adds one.
    EditSession bare(bench(), "kit.toml", kFrame);
    Hand other{bare};
    other.press(Key::j);
    CHECK_THAT(bare.message(), Catch::StartsWith("J: the level has no hints"));
    other.press(Key::h);
    other.type("hA new one");
    other.press(Key::enter);
    REQUIRE(bare.level().level.hints.size() == 1);
    CHECK(bare.level().level.hints[0].text == "A new one");
}

TEST_CASE("the editor sets the goal's kind, its target or bucket, its time limit and its text", "[edit]") {
    EditSession editor(bench(), "kit.toml", kFrame);
    Hand hand{editor};
    const Vec2 flag{3.0, 1.0}, pennant{5.0, 1.0}, pail{-3.0, 0.15}, gun{-6.0, 0.6};
    // The goal as the editor holds it must be the goal the written level reads back.
    const auto same = [&] {
        REQUIRE(editor.level().level.goal);
        const SceneDesc saved = readBack(editor);
        REQUIRE(saved.level.goal);
        const Goal& held = *editor.level().level.goal;
        CHECK(saved.level.goal->kind == held.kind);
        CHECK(saved.level.goal->item == held.item);
        CHECK(saved.level.goal->text == held.text);
        CHECK(saved.level.goal->timeLimit == held.timeLimit);
        return held;
    };
    hand.press(Key::o);
    CHECK_THAT(editor.message(), Catch::StartsWith("T sets a goal first"));
    hand.at(gun);
    hand.press(Key::t);
    CHECK_FALSE(editor.level().level.goal);

    // T on a target: hit it; on it again: every target; again: that target.
    hand.at(flag);
    hand.press(Key::t);
    Goal goal = same();
    CHECK(goal.kind == GoalKind::targetHit);
    CHECK(goal.item == "flag");
    CHECK(goal.text == "hit the flag");
    hand.press(Key::t);
    goal = same();
    CHECK(goal.kind == GoalKind::allTargets);
    CHECK(goal.text == "hit every target");
    CHECK_THAT(editor.message(), Catch::StartsWith("goal all-targets: hit every target within 10 s"));
    hand.press(Key::t);
    CHECK(same().kind == GoalKind::targetHit);
    hand.at(pail);
    hand.press(Key::t);
    goal = same();
    CHECK(goal.kind == GoalKind::ballInBucket);
    CHECK(goal.item == "pail");
    CHECK(goal.text == "get a ball into the pail");

    // The time limit: Up and Down by a second, never under one.
    const int ups = GENERATE(0, 3, 12);
    const int downs = GENERATE(0, 4, 15);
    for (int i = 0; i < ups; ++i) hand.press(Key::up);
    for (int i = 0; i < downs; ++i) hand.press(Key::down);
    double expected = 10.0;
    for (int i = 0; i < ups; ++i) expected += 1.0;
    for (int i = 0; i < downs; ++i) expected = std::max(1.0, expected - 1.0);
    CHECK(same().timeLimit == expected);

    // O types the text, over the one there; T keeps a typed text when it changes the goal.
    hand.press(Key::o);
    hand.type("o");
    CHECK_THAT(editor.message(), Catch::EndsWith("get a ball into the pail_"));
    hand.erase(40);
    hand.type("Drop a ball, into the pail!");
    hand.press(Key::enter);
    CHECK(same().text == "Drop a ball, into the pail!");
    hand.at(pennant);
    hand.press(Key::t);
    goal = same();
    CHECK(goal.kind == GoalKind::targetHit);
    CHECK(goal.item == "pennant");
    CHECK(goal.text == "Drop a ball, into the pail!");
    CHECK(goal.timeLimit == expected);
    hand.press(Key::o);
    hand.erase(40);
    hand.press(Key::enter);
    CHECK_THAT(editor.message(), Catch::StartsWith("the goal's text must not be empty"));
    CHECK(same().text == "Drop a ball, into the pail!");
    hand.control(Key::z);
    CHECK(same().item == "pail");

    // Every target, then both removed: no goal is left (the reader refuses all-targets without one).
    hand.at(flag);
    hand.press(Key::t);
    hand.press(Key::t);
    CHECK(same().kind == GoalKind::allTargets);
    hand.press(Key::deleteKey);
    CHECK(same().kind == GoalKind::allTargets);
    hand.at(pennant);
    hand.press(Key::deleteKey);
    CHECK_FALSE(editor.level().level.goal);
    readBack(editor);
}

TEST_CASE("the editor makes a zone the goal's area, and names what must reach it", "[edit]") {
    EditSession editor(bench(R"(
[[item]]
kind = "steel"
name = "ball"
position = [0, 4]
[[zone]]
min = [-2, 2]
max = [-1, 3.5]
[[zone]]
min = [1, 5]
max = [2.5, 6]
)"),
                       "kit.toml", kFrame);
    Hand hand{editor};
    const auto saved = [&] {
        const SceneDesc back = readBack(editor);
        REQUIRE(back.level.goal);
        return *back.level.goal;
    };
    // T on the ball before any area: not a goal yet, and the message says what comes first.
    hand.at({0.0, 4.0});
    hand.press(Key::t);
    CHECK_FALSE(editor.level().level.goal);
    CHECK_THAT(editor.message(), Catch::Contains("T on a zone first"));
    // T on the second zone: its rectangle is the area, any ball, and it is no longer a zone.
    hand.at({1.7, 5.5});
    hand.press(Key::t);
    Goal goal = saved();
    CHECK(goal.kind == GoalKind::reachArea);
    CHECK(goal.item.empty());
    CHECK(goal.area.min == Vec2{1.0, 5.0});
    CHECK(goal.area.max == Vec2{2.5, 6.0});
    CHECK(goal.text == "get a ball into the area");
    CHECK(editor.level().level.zones.size() == 1);
    CHECK_THAT(editor.message(), Catch::StartsWith("goal reach-area: get a ball into the area within 10 s"));
    // T on the ball: it must; T again: any ball again.
    hand.at({0.0, 4.0});
    hand.press(Key::t);
    goal = saved();
    CHECK(goal.item == "ball");
    CHECK(goal.text == "get the ball into the area");
    CHECK(goal.area.max == Vec2{2.5, 6.0});
    hand.press(Key::t);
    CHECK(saved().item.empty());
    hand.press(Key::t);
    // The other zone, T'd, moves the area and keeps the ball.
    hand.at({-1.5, 2.5});
    hand.press(Key::t);
    goal = saved();
    CHECK(goal.item == "ball");
    CHECK(goal.area.min == Vec2{-2.0, 2.0});
    CHECK(editor.level().level.zones.empty());
    // Ctrl+Z gives the zone back and the area before; a target's T makes it a target goal again.
    hand.control(Key::z);
    CHECK(editor.level().level.zones.size() == 1);
    CHECK(saved().area.min == Vec2{1.0, 5.0});
    hand.at({3.0, 1.0});
    hand.press(Key::t);
    CHECK(saved().kind == GoalKind::targetHit);
    // Deleting the named ball takes the goal with it; deleting an unnamed part does not.
    hand.at({-1.5, 2.5});
    hand.press(Key::t);
    hand.at({0.0, 4.0});
    hand.press(Key::t);
    CHECK(saved().item == "ball");
    hand.press(Key::deleteKey);
    CHECK_FALSE(editor.level().level.goal);
}

TEST_CASE("the editor's view: C shows more of the world and a drag sets the level's [view] anywhere", "[edit]") {
    EditSession editor(bench(), "kit.toml", kFrame);
    Hand hand{editor};
    const Aabb before = *editor.level().view;
    // How wide a box is drawn, in pixels.
    const auto pixelWidth = [&](const Aabb& box) { return editor.pixelOf(box.max).x - editor.pixelOf(box.min).x; };
    // The camera shows the level's view: the whole of it in the level area, touching two edges.
    const auto shown = [&](const Aabb& view) {
        const render::Point a = editor.pixelOf({view.min.x, view.max.y}); // top left
        const render::Point b = editor.pixelOf({view.max.x, view.min.y}); // bottom right
        const float w = static_cast<float>(kFrame.width), h = static_cast<float>(kFrame.height);
        const bool inside = a.x >= -1.0f && a.y >= -1.0f && b.x <= w + 1.0f && b.y <= h + 1.0f;
        const bool fills = (std::abs(a.x) <= 1.0f && std::abs(b.x - w) <= 1.0f) ||
                           (std::abs(a.y) <= 1.0f && std::abs(b.y - h) <= 1.0f);
        return inside && fills;
    };
    REQUIRE(shown(before));
    const float widthBefore = pixelWidth(before);

    // C: three times the width around it, the view outlined; the wheel zooms out and back in.
    hand.press(Key::c);
    REQUIRE(editor.drawingView());
    CHECK(pixelWidth(before) == Approx(widthBefore / 3.0f).epsilon(1e-4));
    const int notches = GENERATE(1, 2, 3);
    editor.scrolled(static_cast<float>(-notches));
    CHECK(pixelWidth(before) ==
          Approx(widthBefore / 3.0f / std::pow(1.25f, static_cast<float>(notches))).epsilon(1e-4));
    editor.scrolled(static_cast<float>(notches));
    CHECK(pixelWidth(before) == Approx(widthBefore / 3.0f).epsilon(1e-4));
    // C again: nothing changed, the camera back on the view.
    hand.press(Key::c);
    CHECK_FALSE(editor.drawingView());
    CHECK(sameBox(*editor.level().view, before));
    CHECK(shown(before));

    // Drags, either way round, inside the old view, across it and wholly outside it.
    const auto [from, to] = GENERATE(std::pair{Vec2{-12.0, -2.0}, Vec2{12.0, 14.0}},
                                     std::pair{Vec2{6.0, 4.0}, Vec2{2.0, 1.0}},
                                     std::pair{Vec2{-15.5, 3.0}, Vec2{-9.0, 9.5}});
    hand.press(Key::c);
    hand.drag(from, to);
    CHECK_FALSE(editor.drawingView());
    const Aabb view{{std::min(from.x, to.x), std::min(from.y, to.y)}, {std::max(from.x, to.x), std::max(from.y, to.y)}};
    REQUIRE(editor.level().view);
    CHECK(sameBox(*editor.level().view, view));
    CHECK(shown(view));
    CHECK_THAT(editor.message(), Catch::StartsWith("view [" + scriptNumber(view.min.x)));
    const SceneDesc saved = readBack(editor);
    REQUIRE(saved.view);
    CHECK(sameBox(*saved.view, view));
    // Undone: the view as it was, and the camera on it.
    hand.control(Key::z);
    CHECK(sameBox(*editor.level().view, before));
    CHECK(shown(before));

    // A click or a drag under a metre sets no view; the view stays being drawn.
    hand.press(Key::c);
    hand.drag({1.0, 1.0}, {1.5, 5.0});
    CHECK_THAT(editor.message(), Catch::StartsWith("a view is at least 1 m each way"));
    CHECK(sameBox(*editor.level().view, before));
    CHECK(editor.drawingView());
}

namespace {

// A part's own keys, as the editor offers them: the descriptor's, but kind, name, position, angle.
std::vector<std::string> ownKeysOf(ItemKind kind) {
    std::vector<std::string> keys;
    for (const PartKey& key : kind->keys())
        if (key.key != "kind" && key.key != "name" && key.key != "position" && key.key != "angle")
            keys.emplace_back(key.key);
    return keys;
}

void choose(EditSession& editor, Hand& hand, ItemKind kind) {
    for (std::size_t i = 0; i < allPartKinds().size() && editor.selectedKind() != kind; ++i) hand.press(Key::tab);
    REQUIRE(editor.selectedKind() == kind);
}

// E as GLFW sends it: the key, then the 'e' it types (which the field does not take).
void pressE(Hand& hand) {
    hand.press(Key::e);
    hand.editor.typed(U'e');
}

// Types `text` for the key shown, over what the field holds.
void retype(Hand& hand, const std::string& text) {
    hand.erase(40);
    hand.type(text);
}

// The reader's message for `item` of `level` with `line` among its keys (replacing the key's line).
std::string readerSays(SceneDesc level, const std::string& item, const std::string& line) {
    ItemDesc& changed = level.level.items[static_cast<std::size_t>(level.level.find(item))];
    const std::string key = line.substr(0, line.find(" = ") + 3);
    std::erase_if(changed.ownLines, [&](const std::string& own) { return own.starts_with(key); });
    changed.ownLines.push_back(line);
    const SceneLoad load = parseScene(writeLevel(level), "kit.toml");
    REQUIRE_FALSE(load.ok());
    return load.errors.front().message;
}

} // namespace

TEST_CASE("E offers every kind's own keys from its descriptor, in its order, Tab going round", "[edit]") {
    for (ItemKind kind : allPartKinds()) {
        INFO(kind->name());
        EditSession editor(bench(), "kit.toml", kFrame);
        Hand hand{editor};
        choose(editor, hand, kind);
        hand.at({0.0, 5.0});
        editor.mouseButton(MouseButton::left, true);
        editor.mouseButton(MouseButton::left, false);
        const ItemDesc placed = editor.level().level.items.back();
        REQUIRE(placed.kind == kind);
        const std::vector<std::string> keys = ownKeysOf(kind);
        // Point where the kind picks the part (a launcher at its plunger, pulled back from where it
        // was placed); a part with nothing to click (a belt, whose wheels are picked) has no E.
        const Aabb box = kind->extent(placed);
        const auto picks = [&](Vec2 p) { return kind->picked(placed, placed.position, p, 0.0); };
        std::optional<Vec2> pick;
        if (picks(placed.position)) pick = placed.position;
        const Vec2 cell{(box.max.x - box.min.x) / 20.0, (box.max.y - box.min.y) / 20.0};
        for (int gy = 1; gy < 20 && !pick; ++gy)
            for (int gx = 1; gx < 20 && !pick; ++gx) {
                const Vec2 p{box.min.x + cell.x * gx, box.min.y + cell.y * gy};
                // Well inside what picks it, so the window's pixels do not move the cursor off it.
                if (picks(p) && picks(p + Vec2{cell.x, 0.0}) && picks(p - Vec2{cell.x, 0.0}) &&
                    picks(p + Vec2{0.0, cell.y}) && picks(p - Vec2{0.0, cell.y}))
                    pick = p;
            }
        if (!pick) continue;
        hand.at(*pick);
        pressE(hand);
        if (keys.empty()) {
            CHECK_THAT(editor.message(), Catch::EndsWith("has no keys of its own"));
            continue;
        }
        for (std::size_t i = 0; i <= keys.size(); ++i) {
            CHECK_THAT(editor.message(), Catch::StartsWith(placed.name + " " + keys[i % keys.size()] + " ("));
            CHECK_THAT(editor.message(), Catch::EndsWith("_"));
            hand.press(Key::tab);
        }
        hand.press(Key::escape);
        CHECK(editor.level().level.items.back().ownLines == placed.ownLines);
        CHECK_FALSE(editor.quitRequested());
    }
}

TEST_CASE("E sets a part's own keys, which the part then has, and the reader's refusals are shown", "[edit]") {
    EditSession editor(bench(), "kit.toml", kFrame);
    Hand hand{editor};
    const Vec2 gun{-6.0, 0.6};
    const auto item = [&](const std::string& name) {
        const int i = editor.level().level.find(name);
        REQUIRE(i >= 0);
        return editor.level().level.items[static_cast<std::size_t>(i)];
    };

    SECTION("a cannon's speed is its shots' muzzle speed") {
        const double speed = GENERATE(0.5, 3.0, 8.5, 12.25, 40.0);
        hand.at(gun);
        pressE(hand);
        CHECK_THAT(editor.message(), Catch::StartsWith("gun speed (8; muzzle speed, m/s): 10_"));
        retype(hand, scriptNumber(speed));
        hand.press(Key::enter);
        CHECK(editor.message() == "gun: speed = " + scriptNumber(speed));
        CHECK(item("gun").kind->muzzleSpeed(item("gun")) == speed);
        const SceneDesc saved = readBack(editor);
        const ItemDesc& read = saved.level.items[static_cast<std::size_t>(saved.level.find("gun"))];
        CHECK(read.kind->muzzleSpeed(read) == speed);
        // Nothing typed: back to the kind's default (8 m/s); undone, the speed typed.
        hand.at(gun);
        pressE(hand);
        hand.erase(40);
        hand.press(Key::enter);
        CHECK(item("gun").kind->muzzleSpeed(item("gun")) == 8.0);
        hand.control(Key::z);
        CHECK(item("gun").kind->muzzleSpeed(item("gun")) == speed);
    }

    SECTION("a plank's length is its board's, at any tilt") {
        const double length = GENERATE(0.5, 1.25, 3.0, 6.0);
        const int turns = GENERATE(0, 1, 5);
        choose(editor, hand, partKind("plank"));
        hand.at({0.0, 5.0});
        editor.mouseButton(MouseButton::left, true);
        editor.mouseButton(MouseButton::left, false);
        for (int i = 0; i < turns; ++i) hand.press(Key::leftBracket);
        pressE(hand);
        retype(hand, scriptNumber(length));
        hand.press(Key::enter);
        const ItemDesc plank = item("plank1");
        const ItemBodies bodies = itemBodies(plank);
        REQUIRE(bodies.segments.size() == 1);
        const Vec2 along = bodies.segments[0].b - bodies.segments[0].a;
        CHECK(along.length() == Approx(length).epsilon(1e-12));
        CHECK(std::atan2(along.y, along.x) * 180.0 / std::numbers::pi == Approx(15.0 * turns).margin(1e-9));
        CHECK(readBack(editor).level.items.size() == editor.level().level.items.size());
        // Made the player's, it keeps its length: the solution's [[place]] gives it, as a script
        // may, and the placement read back from it is as long.
        const auto boardLength = [](const Placement& p) {
            const ItemBodies placed = itemBodies(placedItem(p));
            return placed.segments[0].a.distance(placed.segments[0].b);
        };
        hand.at({0.0, 5.0});
        hand.press(Key::p);
        REQUIRE(editor.playerParts().size() == 1);
        CHECK(boardLength(editor.playerParts()[0]) == Approx(length).epsilon(1e-12));
        ScriptDesc solution;
        solution.level = "kit";
        solution.placements = editor.playerParts();
        SceneDesc stocked = readBack(editor);
        stocked.level.inventory["plank"] = 1;
        stocked.level.zones.push_back({{{-8.0, 1.0}, {8.0, 8.0}}, {}});
        const ScriptLoad script = parseScript(writeScript(solution), "kit.solution.toml", stocked);
        INFO(writeScript(solution));
        INFO((script.errors.empty() ? std::string() : script.errors.front().format()));
        REQUIRE(script.script);
        CHECK(boardLength(script.script->placements[0]) == Approx(length).epsilon(1e-12));
        // E on the player's part: its length changes, checked as the reader checks an [[item]].
        pressE(hand);
        retype(hand, "0");
        hand.press(Key::enter);
        CHECK_THAT(editor.message(), Catch::StartsWith("refused: length must be"));
        CHECK(boardLength(editor.playerParts()[0]) == Approx(length).epsilon(1e-12));
        pressE(hand);
        retype(hand, scriptNumber(length + 1.0));
        hand.press(Key::enter);
        CHECK(boardLength(editor.playerParts()[0]) == Approx(length + 1.0).epsilon(1e-12));
        // Fixed again, the plank keeps that length; nothing typed, it has its kind's.
        hand.press(Key::p);
        REQUIRE(editor.playerParts().empty());
        CHECK(itemBodies(editor.level().level.items.back())
                  .segments[0]
                  .a.distance(itemBodies(editor.level().level.items.back()).segments[0].b) == Approx(length + 1.0));
        hand.press(Key::p);
        pressE(hand);
        hand.erase(40);
        hand.press(Key::enter);
        CHECK(boardLength(editor.playerParts()[0]) == Approx(2.0));
        CHECK(editor.playerParts()[0].ownKeys.empty());
    }

    SECTION("a bomb's timer and its fuse are set together: Tab keeps what is typed") {
        const double fuse = GENERATE(0.0, 1.5, 7.0);
        choose(editor, hand, partKind("bomb"));
        hand.at({0.0, 5.0});
        editor.mouseButton(MouseButton::left, true);
        editor.mouseButton(MouseButton::left, false);
        pressE(hand);
        hand.press(Key::tab); // blast_radius
        hand.press(Key::tab); // strength
        hand.press(Key::tab); // trigger
        CHECK_THAT(editor.message(), Catch::StartsWith("bomb1 trigger (impact;"));
        hand.type("timer");
        hand.press(Key::tab);
        CHECK_THAT(editor.message(), Catch::StartsWith("bomb1 fuse ("));
        hand.type(scriptNumber(fuse));
        hand.press(Key::enter);
        CHECK(editor.message() == "bomb1: trigger = 'timer', fuse = " + scriptNumber(fuse));
        const SceneDesc saved = readBack(editor);
        const ItemDesc& bomb = saved.level.items[static_cast<std::size_t>(saved.level.find("bomb1"))];
        std::vector<std::string> lines = bomb.ownLines;
        std::sort(lines.begin(), lines.end());
        CHECK(lines == std::vector<std::string>{"fuse = " + scriptNumber(fuse), "trigger = 'timer'"});
    }

    SECTION("what the reader refuses is refused with its message, and nothing changes") {
        const auto [name, index, typed, line] = GENERATE(
            std::tuple{"gun", 0, "-1", "speed = -1"}, std::tuple{"gun", 0, "fast", "speed = 'fast'"},
            std::tuple{"gun", 1, "plank", "ammo = 'plank'"}, std::tuple{"gun", 2, "-2", "fire_at = -2"},
            std::tuple{"button", 0, "0", "radius = 0"}, std::tuple{"button", 1, "nowhere", "triggers = 'nowhere'"},
            std::tuple{"button", 1, "flag", "triggers = 'flag'"}, std::tuple{"pail", 0, "1e9", "width = 1e9"});
        const SceneDesc before = editor.level();
        const std::size_t undoable = editor.undoable();
        const ItemDesc& target = before.level.items[static_cast<std::size_t>(before.level.find(name))];
        hand.at(target.kind->plays(PartRole::goalBucket) ? target.position + Vec2{0.0, 0.05} : target.position);
        pressE(hand);
        for (int i = 0; i < index; ++i) hand.press(Key::tab);
        retype(hand, typed);
        hand.press(Key::enter);
        CHECK(editor.message() == "refused: " + readerSays(before, name, line));
        CHECK(item(name).ownLines == target.ownLines);
        CHECK(editor.undoable() == undoable);
    }
}

TEST_CASE("a belt is picked on its runs between its wheels, and E sets the wheels it runs on", "[edit]") {
    // Wheels of radius r1 at (-2, 4) and r2 at (2, 4): the runs are the outer tangents, touching
    // wheel i at its centre + r_i n with n = (cos phi, +-sin phi), cos phi = (r1 - r2) / d.
    const double r1 = GENERATE(0.5, 0.8), r2 = GENERATE(0.3, 0.5);
    const Vec2 one{-2.0, 4.0}, two{2.0, 4.0};
    EditSession editor(bench("[[item]]\nkind = \"wheel\"\nname = \"left\"\nposition = [-2, 4]\nradius = " +
                             scriptNumber(r1) + "\n[[item]]\nkind = \"wheel\"\nname = \"right\"\nposition = [2, 4]\n" +
                             "radius = " + scriptNumber(r2) + "\n[[item]]\nkind = \"wheel\"\nname = \"spare\"\n" +
                             "position = [0, 7]\n[[item]]\nkind = \"belt\"\nname = \"strap\"\nposition = [0, 4]\n" +
                             "from = \"left\"\nto = \"right\"\n"),
                       "kit.toml", kFrame);
    Hand hand{editor};
    const double cosPhi = (r1 - r2) / one.distance(two), sinPhi = std::sqrt(1.0 - cosPhi * cosPhi);
    for (const double side : {1.0, -1.0}) {
        INFO("run " << side << ", r1 " << r1 << ", r2 " << r2);
        const Vec2 n{cosPhi, side * sinPhi};
        const Vec2 middle = ((one + n * r1) + (two + n * r2)) * 0.5;
        hand.at(middle);
        pressE(hand);
        CHECK_THAT(editor.message(), Catch::StartsWith("strap from ("));
        hand.press(Key::escape);
    }
    // Between the runs, nearer neither, the belt is not what is pointed at.
    hand.at({0.0, 4.0});
    pressE(hand);
    CHECK_THAT(editor.message(), !Catch::StartsWith("strap"));
    hand.press(Key::escape);

    // E on the top run moves its end to the spare wheel: the level then runs it there.
    const Vec2 n{cosPhi, sinPhi};
    hand.at(((one + n * r1) + (two + n * r2)) * 0.5);
    pressE(hand);
    hand.press(Key::tab);
    CHECK_THAT(editor.message(), Catch::StartsWith("strap to ("));
    retype(hand, "\"spare\"");
    hand.press(Key::enter);
    const SceneDesc saved = readBack(editor);
    const ItemDesc& belt = saved.level.items[static_cast<std::size_t>(saved.level.find("strap"))];
    const ItemBodies joined = belt.kind->bodies(belt);
    REQUIRE(joined.joints.size() == 1);
    CHECK(joined.joints[0].gearItemA == "left");
    CHECK(joined.joints[0].gearItemB == "spare");
}

// Ctrl+S says whether the solution still reaches the goal with each of the player's parts moved one
// 5 cm grid step either way (solution_nudges.hpp). Here the goal must come within half a second: a
// heavy ball dropped 1.2 m onto the flag (contact after sqrt(2 x 1.2 / 9.81) = 0.495 s) just makes
// it, and moved 5 cm up (0.505 s) it misses; dropped from 5 cm lower, every move of it makes it.
TEST_CASE("saving says whether the solution holds with each part moved one grid step", "[edit]") {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "rube-edit-kit-test";
    std::filesystem::create_directories(folder);
    for (const auto& [height, said] :
         {std::pair{2.75, std::string(", and holds with each part moved one 5 cm grid step")},
          std::pair{2.8, std::string(", but misses with heavy1 moved 5 cm up")}}) {
        INFO("dropped from " << height << " m");
        // The bench and its stock (play_helpers.hpp), the flag under the drop, half a second to hit it.
        EditSession editor(levelOf("name = \"late\"" + std::string(play_test::kTestBench) +
                                   "[[item]]\nkind = \"target\"\nname = \"flag\"\nposition = [0, 1]\n" +
                                   play_test::kTestStock + "time_limit = 0.5\n"),
                           folder / "late.toml", kFrame);
        Hand hand{editor};
        choose(editor, hand, partKind("heavy"));
        hand.at({0.0, height});
        editor.mouseButton(MouseButton::left, true);
        editor.mouseButton(MouseButton::left, false);
        hand.press(Key::p);
        REQUIRE(editor.playerParts().size() == 1);
        CHECK(editor.playerParts()[0].position.y == height);
        hand.control(Key::s);
        CHECK(editor.message() == "saved late.toml and late.solution.toml: the solution reaches the goal at step " +
                                      std::string(height == 2.8 ? "50" : "49") + said);
    }
    std::filesystem::remove_all(folder);
}
