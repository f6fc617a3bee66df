// The play window's game kit (issue 23), without a window: the fail state, undo and redo, the
// grid and the cursor's coordinates, refusals that fit the bar, hints, the intended solution
// after a level is solved, N, a switch clicked by hand, the progress file and the level list.
#include "level_select.hpp"
#include "play_helpers.hpp"
#include "play_session.hpp"
#include "progress.hpp"
#include "scene_file.hpp"

#include "rube/render/palette.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>

using namespace rube;
using namespace rube::game;
using render::Key;
using render::KeyAction;
using render::MouseButton;
using namespace rube::game::play_test;

namespace {

constexpr render::FrameSize kFrame{640, 360};

// A bench: a floor, a gun a switch fires, a target out of reach, planks and a ball to place.
// `extra` is appended (a [goal] time limit, hints).
SceneDesc bench(const std::string& extra = "", const std::string& goalExtra = "") {
    const std::string text = "name = \"bench\"" + std::string(kTestBench) + R"(
[[item]]
kind = "switch"
name = "button"
position = [6, 0.5]
triggers = "gun"
[[item]]
kind = "target"
name = "flag"
position = [6, 7]
)" + std::string(kTestStock) +
                             goalExtra + "\n" + extra;
    const SceneLoad load = parseScene(text, "bench.toml");
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return *load.scene;
}

void press(PlaySession& s, Key key) {
    s.key(key, KeyAction::press);
    s.key(key, KeyAction::release);
}

void control(PlaySession& s, Key key) {
    s.key(Key::control, KeyAction::press);
    press(s, key);
    s.key(Key::control, KeyAction::release);
}

std::vector<std::string> texts(const render::DrawList& list) {
    std::vector<std::string> out;
    for (const render::Primitive& p : list.primitives())
        if (const auto* t = std::get_if<render::primitive::Text>(&p)) out.emplace_back(list.textOf(*t));
    return out;
}

bool anyTextStartsWith(const render::DrawList& list, const std::string& head) {
    for (const std::string& t : texts(list))
        if (t.rfind(head, 0) == 0) return true;
    return false;
}

// Sets an environment variable for a test's length.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        ::setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv() {
        if (old_) ::setenv(name_, old_->c_str(), 1);
        else ::unsetenv(name_);
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* name_;
    std::optional<std::string> old_;
};

// An angle in (-180, 180], as the window keeps it.
double normal(double degrees) {
    while (degrees > 180.0) degrees -= 360.0;
    while (degrees <= -180.0) degrees += 360.0;
    return degrees;
}

std::filesystem::path freshFolder(const std::string& name) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("rube-play-kit-" + name);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

} // namespace

TEST_CASE("play kit: past the time limit without the goal, HUD and bar say TIME UP and R retries", "[play][kit]") {
    // Limits on and between steps: up exactly from the first step whose time passes the limit.
    for (const double limit : {0.25, 0.5, 0.777, 1.3}) {
        INFO("time_limit = " << limit);
        std::ostringstream goal;
        goal << "time_limit = " << limit;
        PlaySession s(bench("", goal.str()), "bench.toml", kFrame);
        press(s, Key::space);
        REQUIRE(s.mode() == PlaySession::Mode::running);
        const double dt = 0.01;
        // The last step not past the limit: its time k dt <= limit.
        const auto lastInTime = static_cast<std::int64_t>(std::floor(limit / dt + 1e-6));
        while (s.run()->steps() < lastInTime) {
            s.step();
            REQUIRE_FALSE(s.timeUp());
        }
        render::DrawList list;
        s.draw(list);
        CHECK(anyTextStartsWith(list, "goal: hit the flag"));
        CHECK_THAT(s.message(), !Catch::Contains("TIME UP"));
        s.step();
        CHECK(s.timeUp());
        s.draw(list);
        CHECK(anyTextStartsWith(list, "TIME UP after "));
        CHECK_THAT(s.message(), Catch::StartsWith("TIME UP") && Catch::Contains("R to retry"));
        CHECK(anyTextStartsWith(list, "RUN step"));
        bool retryShown = false;
        for (const std::string& t : texts(list)) retryShown = retryShown || t.find("R retry") != std::string::npos;
        CHECK(retryShown);
        // The machine runs on, still failed; R goes back to editing, a new run starts afresh.
        for (int i = 0; i < 30; ++i) s.step();
        CHECK(s.timeUp());
        press(s, Key::r);
        CHECK(s.mode() == PlaySession::Mode::editing);
        CHECK_FALSE(s.timeUp());
        press(s, Key::space);
        CHECK_FALSE(s.timeUp());
    }
    // A level solved in time is never failed, however long it runs on.
    for (const char* name : {"ramp", "bucket"}) {
        INFO(name);
        const SceneDesc level = loadLevel(name);
        REQUIRE(level.level.goal->timeLimit);
        const ScriptLoad solution = loadScriptFile(kLevels / (std::string(name) + ".solution.toml"), level);
        REQUIRE(solution.script);
        PlaySession s(level, name, kFrame);
        s.load(*solution.script);
        press(s, Key::space);
        const auto past = static_cast<std::int64_t>(*level.level.goal->timeLimit / 0.01) + 50;
        while (s.run()->steps() < past) {
            s.step();
            REQUIRE_FALSE(s.timeUp());
        }
        CHECK(s.run()->goalStep());
    }
}

TEST_CASE("play kit: Ctrl+Z undoes and Ctrl+Y redoes every kind of edit, 100 deep", "[play][kit][undo]") {
    PlaySession s(bench(), "bench.toml", kFrame);
    control(s, Key::z);
    CHECK_THAT(s.message(), Catch::StartsWith("nothing to undo"));
    place(s, partKind("plank"), {0.0, 3.5});
    REQUIRE(s.placements().size() == 1);
    // Sixty turns, each an edit of its own.
    constexpr int kTurns = 60;
    moveTo(s, {0.0, 3.5});
    for (int i = 1; i <= kTurns; ++i) {
        press(s, Key::rightBracket);
        REQUIRE(s.placements()[0].angleDegrees == normal(-15.0 * i));
    }
    CHECK(s.undoable() == kTurns + 1);
    for (int j = 1; j <= kTurns; ++j) {
        control(s, Key::z);
        REQUIRE(s.placements().size() == 1);
        REQUIRE(s.placements()[0].angleDegrees == normal(-15.0 * (kTurns - j)));
    }
    control(s, Key::z); // the placement itself
    CHECK(s.placements().empty());
    CHECK(s.remaining(partKind("plank")) == 2);
    CHECK_FALSE(s.undo());
    // Z without Control is no undo.
    control(s, Key::y);
    REQUIRE(s.placements().size() == 1);
    press(s, Key::z);
    CHECK(s.placements().size() == 1);
    for (int j = 1; j <= kTurns; ++j) control(s, Key::y);
    CHECK(s.placements()[0].angleDegrees == normal(-15.0 * kTurns));
    CHECK_FALSE(s.redo());

    // A move, a removal and an aim are undone too; a new edit forgets what was undone.
    moveTo(s, {0.0, 3.5});
    s.mouseButton(MouseButton::left, true);
    moveTo(s, {-2.0, 2.0});
    s.mouseButton(MouseButton::left, false);
    REQUIRE(s.placements()[0].position.x == -2.0);
    control(s, Key::z);
    CHECK(s.placements()[0].position.x == 0.0);
    CHECK(s.redoable() == 1);
    moveTo(s, {0.0, 3.5});
    press(s, Key::deleteKey);
    CHECK(s.placements().empty());
    CHECK(s.redoable() == 0);
    control(s, Key::z);
    CHECK(s.placements().size() == 1);
    const std::string before = s.recordedScript();
    moveTo(s, {-6.0, 0.6});
    s.mouseButton(MouseButton::left, true);
    moveTo(s, {-5.0, 1.8});
    s.mouseButton(MouseButton::left, false);
    REQUIRE(s.recordedScript() != before);
    control(s, Key::z);
    CHECK(s.recordedScript() == before);

    // No undo while the machine runs (R first); a failed placement is no edit.
    const std::size_t edits = s.undoable();
    place(s, partKind("plank"), {7.0, 3.0});
    CHECK(s.undoable() == edits);
    press(s, Key::space);
    control(s, Key::z);
    CHECK(s.mode() == PlaySession::Mode::running);
    press(s, Key::r);

    // The depth: the oldest edits go first.
    moveTo(s, {0.0, 3.5});
    for (std::size_t i = 0; i < EditHistory<int>::kDepth + 50; ++i) press(s, Key::rightBracket);
    CHECK(s.undoable() == EditHistory<int>::kDepth);
}

TEST_CASE("play kit: G toggles the grid, and the bar shows the cursor's coordinates", "[play][kit]") {
    PlaySession s(bench(), "bench.toml", kFrame);
    CHECK(s.gridSnap());
    const Vec2 at{1.2345, 3.4567};
    place(s, partKind("heavy"), at);
    REQUIRE(s.placements().size() == 1);
    CHECK(s.placements()[0].position.x == 1.25);
    CHECK(s.placements()[0].position.y == 3.45);
    control(s, Key::z);
    press(s, Key::g);
    CHECK_FALSE(s.gridSnap());
    CHECK_THAT(s.message(), Catch::StartsWith("grid off"));
    place(s, partKind("heavy"), at);
    REQUIRE(s.placements().size() == 1);
    // The placement is the cursor's world point to the millimetre; the bar shows the cursor's
    // point to the centimetre, at the top right.
    moveTo(s, at);
    const Vec2 placed = s.placements()[0].position;
    CHECK(std::abs(placed.x - at.x) < 0.02);
    CHECK(placed.x * 1000.0 == std::round(placed.x * 1000.0));
    CHECK(placed.y * 1000.0 == std::round(placed.y * 1000.0));
    const auto shown = [&](const char* grid) {
        render::DrawList list;
        s.draw(list);
        for (const std::string& t : texts(list)) {
            double x = 0.0, y = 0.0;
            char state[16] = {};
            if (std::sscanf(t.c_str(), "x %lf  y %lf  grid %15[a-z0-9 ]", &x, &y, state) == 3) {
                INFO(t);
                CHECK(std::string(state) == grid);
                CHECK(std::abs(x - placed.x) <= 0.0051);
                CHECK(std::abs(y - placed.y) <= 0.0051);
                CHECK(t.find('.') + 3 == t.find(' ', t.find('.'))); // two decimals
                return true;
            }
        }
        return false;
    };
    CHECK(shown("off"));
    press(s, Key::g);
    CHECK(shown("5 cm"));
}

TEST_CASE("play kit: refusals on the bar are short, rounded to centimetres and fit the window", "[play][kit]") {
    // The window's default size, and a small one: the lines the bar draws never run off it.
    for (const render::FrameSize frame : {render::FrameSize{1280, 720}, render::FrameSize{640, 360}}) {
        PlaySession s(bench(), "bench.toml", frame);
        place(s, partKind("plank"), {0.0, 3.0});
        press(s, Key::g); // off the grid: positions with three decimals
        const std::regex longDecimal(R"(\d\.\d{3})");
        int refusals = 0;
        for (double x = -7.9; x <= 7.9; x += 0.61)
            for (double y = -0.5; y <= 7.5; y += 0.53) {
                const auto slot = s.slotPixel(partKind("plank"));
                s.cursorMoved(slot->x, slot->y);
                s.mouseButton(MouseButton::left, true);
                moveTo(s, {x, y});
                const std::string refused = s.message();
                s.mouseButton(MouseButton::left, false);
                if (s.placements().size() > 1) {
                    control(s, Key::z);
                    continue;
                }
                ++refusals;
                INFO(refused);
                CHECK_FALSE(std::regex_search(refused, longDecimal));
                if (frame.width == 1280) CHECK(render::textWidth(refused, 2) <= frame.width - 16);
                render::DrawList list;
                s.draw(list);
                for (const render::Primitive& p : list.primitives())
                    if (const auto* t = std::get_if<render::primitive::Text>(&p))
                        CHECK(t->x + render::textWidth(list.textOf(*t), t->scale) <= frame.width);
            }
        CHECK(refusals > 50);
    }
}

TEST_CASE("play kit: H shows the level's hints in turn", "[play][kit][hint]") {
    PlaySession none(bench(), "bench.toml", kFrame);
    press(none, Key::h);
    CHECK(none.message() == "this level has no hints");
    const SceneDesc level = bench("[[hint]]\ntext = \"The switch fires the gun.\"\n[[hint]]\ntext = \"Roll a ball.\"\n"
                                  "[[hint]]\ntext = \"Aim high.\"\n");
    REQUIRE(level.level.hints.size() == 3);
    PlaySession s(level, "bench.toml", kFrame);
    const char* expected[] = {"hint 1/3: The switch fires the gun.", "hint 2/3: Roll a ball.", "hint 3/3: Aim high.",
                              "hint 1/3: The switch fires the gun."};
    for (const char* e : expected) {
        press(s, Key::h);
        CHECK(s.message() == e);
    }
}

TEST_CASE("play kit: [[hint]] errors are one line at their file:line:col", "[play][kit][hint]") {
    struct Case {
        std::string text;
        std::string error;
    };
    const std::string head = "name = \"h\"\n[[segment]]\na = [0, 0]\nb = [1, 0]\n";
    const Case cases[] = {
        {head + "[[hint]]\ntxt = \"typo\"\n", "h.toml:6:1: unknown key 'txt' in [[hint]]"},
        {head + "[[hint]]\ntext = \"  \"\n", "h.toml:6:8: a hint's text must not be empty"},
        {head + "[[hint]]\n", "h.toml:5:1: missing required key 'text' in [[hint]]"},
        {head + "[[hint]]\ntext = 3\n", "h.toml:6:8: text must be a string"},
        {head + "[[hints]]\ntext = \"x\"\n", "did you mean 'hint'?"},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        const SceneLoad load = parseScene(c.text, "h.toml");
        REQUIRE_FALSE(load.ok());
        std::string all;
        for (const SceneError& e : load.errors) all += e.format() + "\n";
        CHECK_THAT(all, Catch::Contains(c.error));
    }
}

TEST_CASE("play kit: a switch clicked by hand is drawn as one a ball pressed", "[play][kit]") {
    PlaySession s(bench(), "bench.toml", kFrame);
    press(s, Key::space);
    const auto switchFill = [&] {
        render::DrawList list;
        s.draw(list);
        const Vec2 at = s.run()->itemPosition(1);
        for (const render::Primitive& p : list.primitives())
            if (const auto* b = std::get_if<render::primitive::Box>(&p))
                if (std::abs(b->centre.x - at.x) < 1e-4 && std::abs(b->centre.y - at.y) < 1e-4) return b->style.fill;
        FAIL("no box drawn at the switch");
        return render::Color{};
    };
    const render::Color highlight = render::Palette::greybox()["highlight"];
    CHECK_FALSE(switchFill() == highlight);
    moveTo(s, s.run()->itemPosition(1));
    s.mouseButton(MouseButton::left, true);
    s.mouseButton(MouseButton::left, false);
    REQUIRE(s.actions().size() == 1);
    CHECK(s.actions()[0].kind == ActionKind::toggle);
    CHECK(s.run()->states()[1].pressed);
    CHECK(switchFill() == highlight);
    // And it fired the gun, as a ball's press would.
    CHECK(s.run()->states()[0].fired);
}

TEST_CASE("play kit: W plays the intended solution once solved, N asks for the next level", "[play][kit]") {
    for (const char* name : {"ramp", "pegs"}) {
        INFO(name);
        const SceneDesc level = loadLevel(name);
        const ScriptLoad solution = loadScriptFile(kLevels / (std::string(name) + ".solution.toml"), level);
        REQUIRE(solution.script);
        PlaySession s(level, name, kFrame);
        s.setSolution(*solution.script);
        press(s, Key::w);
        CHECK_THAT(s.message(), Catch::StartsWith("solve the level first"));
        CHECK(s.mode() == PlaySession::Mode::editing);
        press(s, Key::space);
        press(s, Key::n);
        CHECK_FALSE(s.nextRequested());
        CHECK_THAT(s.message(), Catch::StartsWith("reach the goal first"));
        press(s, Key::r);
        s.markSolved(); // solved in an earlier session (the progress file)
        press(s, Key::w);
        REQUIRE(s.mode() == PlaySession::Mode::running);
        CHECK(s.placements().size() == solution.script->placements.size());
        while (!s.run()->goalStep() && s.run()->steps() < 2000) s.step();
        CHECK(s.run()->goalStep());
        press(s, Key::n);
        CHECK(s.nextRequested());
        // The player's own edits (none) come back with R and Ctrl+Z.
        press(s, Key::r);
        control(s, Key::z);
        CHECK(s.placements().empty());
    }
}

TEST_CASE("play kit: progress is kept under XDG_DATA_HOME, else ~/.local/share", "[play][kit][progress]") {
    const std::filesystem::path data = freshFolder("data");
    {
        ScopedEnv xdg("XDG_DATA_HOME", data.string());
        CHECK(Progress::defaultFile() == data / "rube" / "solved.txt");
        Progress progress(Progress::defaultFile());
        CHECK_FALSE(progress.solved("ramp"));
        std::string reason;
        REQUIRE(progress.markSolved("ramp", reason));
        REQUIRE(progress.markSolved("pegs", reason));
        REQUIRE(progress.markSolved("ramp", reason));
        const Progress again(Progress::defaultFile());
        CHECK(again.solved("ramp"));
        CHECK(again.solved("pegs"));
        CHECK_FALSE(again.solved("bucket"));
    }
    {
        // A relative XDG_DATA_HOME is invalid (the XDG spec): HOME's default is used.
        ScopedEnv xdg("XDG_DATA_HOME", "relative/data");
        ScopedEnv home("HOME", data.string());
        CHECK(Progress::defaultFile() == data / ".local" / "share" / "rube" / "solved.txt");
    }
    CHECK(levelKey("levels/cannon-arc.toml") == "cannon-arc");
    // An unwritable folder: the reason is given, and the level counts as solved for the session.
    const std::filesystem::path file = data / "blocked" / "solved.txt";
    std::ofstream(data / "blocked") << "a file, not a folder";
    Progress blocked(file);
    std::string reason;
    CHECK_FALSE(blocked.markSolved("ramp", reason));
    CHECK_FALSE(reason.empty());
    CHECK(blocked.solved("ramp"));
}

TEST_CASE("play kit: the level list shows the index in order with the solved ones, picked by key or click",
          "[play][kit][select]") {
    const LevelIndexLoad index = loadLevelIndex(kLevels / "index.toml");
    REQUIRE(index.levels);
    const std::vector<IndexedLevel>& levels = *index.levels;
    REQUIRE(levels.size() > 3);
    const std::filesystem::path data = freshFolder("select");
    Progress progress(data / "solved.txt");
    std::string reason;
    REQUIRE(progress.markSolved(levelKey(levels[0].file), reason));
    REQUIRE(progress.markSolved(levelKey(levels[2].file), reason));
    const render::FrameSize window{640, 360 + InventoryBar::kHeight};
    LevelSelect select(levels, progress, window);
    for (std::size_t i = 0; i < levels.size(); ++i) {
        INFO(i);
        CHECK_THAT(select.rowText(i), Catch::StartsWith(std::to_string(i + 1) + ". " + levels[i].title));
        CHECK((select.rowText(i).find("solved") != std::string::npos) == (i == 0 || i == 2));
    }
    render::DrawList list;
    select.draw(list);
    CHECK(anyTextStartsWith(list, "rube: choose a level (2 of " + std::to_string(levels.size()) + " solved)"));
    // Keys: down and up move, Enter plays; the list scrolls to keep the selection in view.
    for (std::size_t i = 1; i < levels.size(); ++i) select.key(Key::down, KeyAction::press);
    CHECK(select.selected() == levels.size() - 1);
    const render::Point last = select.rowPixel(levels.size() - 1);
    CHECK(last.y > 0.0f);
    CHECK(last.y < static_cast<float>(window.height));
    select.key(Key::down, KeyAction::press);
    CHECK(select.selected() == levels.size() - 1);
    select.key(Key::up, KeyAction::press);
    CHECK_FALSE(select.chosen());
    select.key(Key::enter, KeyAction::press);
    REQUIRE(select.chosen());
    CHECK(*select.chosen() == levels.size() - 2);
    // A click on a row plays that level.
    LevelSelect clicked(levels, progress, window);
    const render::Point row = clicked.rowPixel(3);
    clicked.cursorMoved(row.x, row.y);
    CHECK(clicked.selected() == 3);
    clicked.mouseButton(MouseButton::left, true);
    REQUIRE(clicked.chosen());
    CHECK(*clicked.chosen() == 3);
    // Escape leaves without a level.
    LevelSelect left(levels, progress, window);
    left.key(Key::escape, KeyAction::press);
    CHECK(left.quitRequested());
    CHECK_FALSE(left.chosen());
}
