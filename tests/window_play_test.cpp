// `rube play` end to end, under Xvfb: a session in a real GLFW window is played with synthetic
// input through the handlers GLFW's callbacks call (PlaySession's InputListener), recorded as a
// script, replayed off-screen by the `rube` binary, and the window's level area at a step is
// compared with the off-screen frame of the same step, with the screenshot tests' thresholds.
#include "edit_session.hpp"
#include "play_session.hpp"
#include "play_visit.hpp"
#include "scene_file.hpp"

#include "rube/render/renderer.hpp"
#include "rube/render/screenshot.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <sys/wait.h>
#include <filesystem>
#include <fstream>

using namespace rube;
using namespace rube::game;
using render::Key;
using render::KeyAction;
using render::MouseButton;

namespace {

const std::filesystem::path kLevels = RUBE_GAME_LEVELS_DIR;
const std::filesystem::path kWork = RUBE_WINDOW_PLAY_DIR;

SceneDesc level(const std::string& name) {
    SceneLoad load = loadSceneFile(kLevels / (name + ".toml"));
    REQUIRE(load.ok());
    return *load.scene;
}

// The top `frame.height` rows of the window: its level area, what `rube run` draws.
render::Image levelArea(const render::Image& window, render::FrameSize frame) {
    render::Image area;
    area.resize(frame.width, frame.height);
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) std::copy_n(window.pixel(x, y), 3, area.pixel(x, y));
    return area;
}

void moveTo(PlaySession& session, render::Point p) { session.cursorMoved(p.x, p.y); }

void dragTo(PlaySession& session, render::Point from, render::Point to) {
    moveTo(session, from);
    session.mouseButton(MouseButton::left, true);
    // The way a hand moves: several cursor events on the way, each checked as the drag goes.
    for (int i = 1; i <= 4; ++i)
        moveTo(session, {from.x + (to.x - from.x) * static_cast<float>(i) / 4.0f,
                         from.y + (to.y - from.y) * static_cast<float>(i) / 4.0f});
}

} // namespace

TEST_CASE("a session played in a window replays off-screen to the same frames", "[window][play]") {
    constexpr render::FrameSize frame{640, 360};
    PlaySession session(level("ramp"), (kLevels / "ramp.toml").string(), frame);
    render::WindowOptions options;
    options.title = "rube play test";
    options.vsync = false;
    std::unique_ptr<render::RenderContext> window = render::createWindowContext(session.windowSize(), options);
    REQUIRE(window->size().width == session.windowSize().width);
    REQUIRE(window->size().height == session.windowSize().height);
    render::Renderer renderer(*window);
    // The synthetic events go straight to the handlers GLFW's callbacks call. The window is not
    // given the session as its listener here: Xvfb's own pointer would report where it rests at
    // every present() and overrule the made-up cursor.
    render::DrawList list;
    const auto show = [&] {
        session.draw(list);
        renderer.draw(list, session.windowCamera());
        render::Image image;
        window->readPixels(image);
        window->present();
        return image;
    };

    // The window's frames are kept beside the replay's, to look at when a check fails.
    std::filesystem::remove_all(kWork);
    std::filesystem::create_directories(kWork);
    const auto slot = session.slotPixel(partKind("ramp"));
    REQUIRE(slot);
    // A ramp dropped on the floor, outside the zone, is refused with the reason and goes back.
    dragTo(session, *slot, session.pixelOf({2.0, 0.3}));
    CHECK_THAT(session.message(), Catch::StartsWith("ramp at [2, 0.3]: "));
    render::writePng(kWork / "window-refused.png", show());
    session.mouseButton(MouseButton::left, false);
    CHECK(session.placements().empty());
    CHECK_THAT(session.message(), Catch::StartsWith("not placed: ramp at [2, 0.3]: "));
    CHECK(session.remaining(partKind("ramp")) == 1);

    // Then into the zone, turned twice by the wheel (2 x -15 degrees), and released.
    dragTo(session, *slot, session.pixelOf({-4.5, 2.5}));
    session.scrolled(-2.0f);
    render::writePng(kWork / "window-dragging.png", show());
    session.mouseButton(MouseButton::left, false);
    REQUIRE(session.placements().size() == 1);
    CHECK(session.placements()[0].position.x == Approx(-4.5));
    CHECK(session.placements()[0].position.y == Approx(2.5));
    CHECK(session.placements()[0].angleDegrees == -30.0);
    CHECK(session.remaining(partKind("ramp")) == 0);

    // Space runs the machine; frames are drawn and presented as the window loop does.
    session.key(Key::space, KeyAction::press);
    REQUIRE(session.mode() == PlaySession::Mode::running);
    constexpr std::int64_t kCompared[] = {120, 300};
    std::vector<render::Image> windowFrames;
    while (session.run()->steps() < kCompared[1]) {
        session.step();
        if (session.run()->steps() == kCompared[0] || session.run()->steps() == kCompared[1]) {
            const render::Image whole = show();
            render::writePng(kWork / ("window-step-" + std::to_string(session.run()->steps()) + ".png"), whole);
            windowFrames.push_back(levelArea(whole, frame));
        } else if (session.run()->steps() % 20 == 0) show();
    }
    REQUIRE(session.run()->goalStep());

    // The recording, replayed by `rube run` off-screen.
    const std::filesystem::path script = kWork / "ramp.recorded.toml";
    std::ofstream(script) << session.recordedScript();
    const std::string command = std::string("\"") + RUBE_BINARY + "\" run \"" + (kLevels / "ramp.toml").string() +
                                "\" --script \"" + script.string() + "\" --out \"" + (kWork / "frames").string() +
                                "\" > \"" + (kWork / "replay.txt").string() + "\" 2>&1";
    INFO(command);
    REQUIRE(std::system(command.c_str()) == 0);
    std::ifstream replay(kWork / "replay.txt");
    const std::string printed((std::istreambuf_iterator<char>(replay)), std::istreambuf_iterator<char>());
    CHECK_THAT(printed,
               Catch::Contains("goal:             reached at step " + std::to_string(*session.run()->goalStep())));

    for (std::size_t i = 0; i < windowFrames.size(); ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05lld.png", static_cast<long long>(kCompared[i]));
        const render::ScreenshotCheck check = render::checkScreenshot(windowFrames[i], kWork / "frames" / name,
                                                                      RUBE_SCREENSHOT_FAILURES_DIR "/window-play");
        INFO("step " << kCompared[i] << ": " << check.message);
        CHECK(check.passed);
        CHECK_FALSE(check.goldenWritten);
    }
}

TEST_CASE("a cannon aimed with the mouse and fired by a click replays to the same shot", "[window][play]") {
    constexpr render::FrameSize frame{640, 360};
    PlaySession session(level("cannon-arc"), (kLevels / "cannon-arc.toml").string(), frame);
    render::WindowOptions options;
    options.vsync = false;
    std::unique_ptr<render::RenderContext> window = render::createWindowContext(session.windowSize(), options);
    render::Renderer renderer(*window);
    render::DrawList list;

    const SceneDesc& desc = level("cannon-arc");
    const ItemDesc& gun = desc.level.items[static_cast<std::size_t>(desc.level.find("gun"))];
    // Drag from the cannon's pivot towards a point up and to the right: the aim follows the cursor.
    dragTo(session, session.pixelOf(gun.position), session.pixelOf(gun.position + Vec2{1.0, 1.2}));
    session.mouseButton(MouseButton::left, false);
    CHECK_THAT(session.message(), Catch::StartsWith("aim gun: 50"));
    session.key(Key::space, KeyAction::press);
    for (int i = 0; i < 30; ++i) session.step();
    moveTo(session, session.pixelOf(gun.position));
    session.mouseButton(MouseButton::left, true);
    session.mouseButton(MouseButton::left, false);
    REQUIRE(session.actions().size() == 1);
    CHECK(session.actions()[0].kind == ActionKind::fire);
    CHECK(session.actions()[0].step == 30);
    for (int i = 0; i < 90; ++i) session.step();
    session.draw(list);
    renderer.draw(list, session.windowCamera());
    render::Image image;
    window->readPixels(image);
    window->present();

    std::filesystem::create_directories(kWork);
    const std::filesystem::path script = kWork / "cannon.recorded.toml";
    std::ofstream(script) << session.recordedScript();
    const std::filesystem::path out = kWork / "cannon-frames";
    const std::string command = std::string("\"") + RUBE_BINARY + "\" run \"" + (kLevels / "cannon-arc.toml").string() +
                                "\" --script \"" + script.string() + "\" --out \"" + out.string() +
                                "\" --frames 121 > /dev/null 2>&1";
    INFO(command);
    // The shot misses the bullseye (the goal is not this test's business): exit 1 is fine, 2 is not.
    const int status = std::system(command.c_str());
    REQUIRE(WIFEXITED(status));
    REQUIRE(WEXITSTATUS(status) != 2);
    const render::ScreenshotCheck check = render::checkScreenshot(levelArea(image, frame), out / "frame_00120.png",
                                                                  RUBE_SCREENSHOT_FAILURES_DIR "/window-play-cannon");
    INFO(check.message);
    CHECK(check.passed);
}

namespace {

// A real window of `size` pixels that shows what a session or a visit draws, and reads it back.
class TestWindow {
public:
    explicit TestWindow(render::FrameSize size) : window_(open(size)), renderer_(*window_) {}
    template <class Screen>
    render::Image show(const Screen& screen, const render::Camera& camera) {
        screen.draw(list_);
        renderer_.draw(list_, camera);
        render::Image image;
        window_->readPixels(image);
        window_->present();
        return image;
    }

private:
    static std::unique_ptr<render::RenderContext> open(render::FrameSize size) {
        render::WindowOptions options;
        options.vsync = false;
        return render::createWindowContext(size, options);
    }
    std::unique_ptr<render::RenderContext> window_;
    render::Renderer renderer_;
    render::DrawList list_;
};

// Pixels of `colour` (to within a few levels, for blending) in the rows [top, bottom) of `image`.
int pixelsOf(const render::Image& image, render::Color colour, int top, int bottom) {
    int count = 0;
    for (int y = top; y < bottom; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            if (std::abs(p[0] - colour.r) <= 8 && std::abs(p[1] - colour.g) <= 8 && std::abs(p[2] - colour.b) <= 8)
                ++count;
        }
    return count;
}

} // namespace

TEST_CASE("the fail state in a window: past the time limit the HUD turns to TIME UP and R retries", "[window][play]") {
    constexpr render::FrameSize frame{640, 360};
    const SceneDesc desc = level("cannon-arc");
    REQUIRE(desc.level.goal->timeLimit);
    PlaySession session(desc, (kLevels / "cannon-arc.toml").string(), frame);
    TestWindow window(session.windowSize());
    const auto show = [&] { return window.show(session, session.windowCamera()); };
    // The HUD's goal line (rows 26 to 40 of the level area) is in the fail colour only once the
    // time is up; nothing was placed and the gun never fires, so the goal is missed.
    const render::Color failColour = render::Palette::greybox()["magnet"];
    session.key(Key::space, KeyAction::press);
    const auto limitSteps = static_cast<std::int64_t>(std::floor(*desc.level.goal->timeLimit / 0.01 + 1e-6));
    while (session.run()->steps() < limitSteps) session.step();
    const render::Image inTime = show();
    CHECK_FALSE(session.timeUp());
    session.step();
    REQUIRE(session.timeUp());
    const render::Image late = show();
    std::filesystem::create_directories(kWork);
    render::writePng(kWork / "window-time-up.png", late);
    CHECK(pixelsOf(inTime, failColour, 24, 42) < 5);
    CHECK(pixelsOf(late, failColour, 24, 42) > 100);
    // The bar's message line says so too, in the same colour.
    const int bar = frame.height + InventoryBar::kHeight - 20;
    CHECK(pixelsOf(late, failColour, bar, bar + 16) > 100);
    session.key(Key::r, KeyAction::press);
    CHECK(session.mode() == PlaySession::Mode::editing);
    CHECK(pixelsOf(show(), failColour, 24, 42) < 5);
}

TEST_CASE(
    "a visit in a window: from the level list to a level and its solution then N to the next and Esc back to the list",
    "[window][play]") {
    const LevelIndexLoad index = loadLevelIndex(kLevels / "index.toml");
    REQUIRE(index.levels);
    const std::vector<IndexedLevel>& levels = *index.levels;
    std::filesystem::create_directories(kWork);
    const std::filesystem::path progressFile = kWork / "visit-progress" / "solved.txt";
    std::filesystem::remove_all(progressFile.parent_path());
    // The third level was solved before: its solution may be watched (W).
    {
        Progress before(progressFile);
        std::string reason;
        REQUIRE(before.markSolved(levelKey(levels[2].file), reason));
    }
    VisitOptions options;
    options.levelFrame = {640, 360};
    options.progressFile = progressFile;
    std::vector<std::string> ended;
    PlayVisit visit(
        levels, std::nullopt, options,
        [&](const PlaySession& session, const SceneDesc& scene) {
            ended.push_back(scene.name + (session.run() && session.run()->goalStep() ? " reached" : ""));
        },
        [](const std::string& message) { FAIL(message); });
    TestWindow window(visit.windowSize());
    const auto show = [&] {
        visit.tick(0.0);
        return window.show(visit, visit.camera());
    };
    const auto press = [&](Key key) {
        visit.key(key, KeyAction::press);
        visit.key(key, KeyAction::release);
    };

    // The list: the highlight is on the selected row and follows Down.
    REQUIRE(visit.list());
    const render::Color highlight = render::Palette::greybox()["highlight"];
    const auto rowHighlighted = [&](const render::Image& image, std::size_t row) {
        const int y = static_cast<int>(visit.list()->rowPixel(row).y);
        return pixelsOf(image, highlight, y - 12, y - 10) > 100; // the highlight's top edge
    };
    render::Image image = show();
    CHECK(rowHighlighted(image, 0));
    CHECK_FALSE(rowHighlighted(image, 2));
    press(Key::down);
    press(Key::down);
    image = show();
    render::writePng(kWork / "window-level-list.png", image);
    CHECK(rowHighlighted(image, 2));
    CHECK_FALSE(rowHighlighted(image, 0));
    CHECK_THAT(visit.list()->rowText(2), Catch::EndsWith("solved"));
    press(Key::enter);
    show();
    REQUIRE(visit.session());
    CHECK(std::filesystem::equivalent(visit.levelFile(), levels[2].file));

    // Solved before, so W plays the intended solution to its goal; N then opens the next level.
    press(Key::w);
    REQUIRE(visit.session()->mode() == PlaySession::Mode::running);
    while (!visit.session()->run()->goalStep() && visit.session()->run()->steps() < 3000) {
        visit.session()->step();
        if (visit.session()->run()->steps() % 50 == 0) show();
    }
    REQUIRE(visit.session()->run()->goalStep());
    press(Key::n);
    show();
    REQUIRE(visit.session());
    CHECK(std::filesystem::equivalent(visit.levelFile(), levels[3].file));
    REQUIRE(ended.size() == 1);
    CHECK_THAT(ended[0], Catch::EndsWith(" reached"));

    // Escape goes back to the list, on the level just left; the progress file has both.
    press(Key::escape);
    show();
    REQUIRE(visit.list());
    CHECK(visit.list()->selected() == 3);
    CHECK_FALSE(visit.finished());
    const Progress after(progressFile);
    CHECK(after.solved(levelKey(levels[2].file)));
    CHECK_FALSE(after.solved(levelKey(levels[3].file)));
    press(Key::escape);
    visit.tick(0.0);
    CHECK(visit.finished());
    CHECK(ended.size() == 2);
}

TEST_CASE("a level built in the editor by synthetic input is saved and checked and replays to its goal",
          "[window][edit]") {
    std::filesystem::create_directories(kWork);
    const std::filesystem::path file = kWork / "made.toml";
    std::filesystem::remove(file);
    EditSession editor(EditSession::newLevel("made"), file, {640, 360});
    TestWindow window(editor.windowSize());
    const auto show = [&] { return window.show(editor, editor.windowCamera()); };
    const auto at = [&](Vec2 world) {
        const render::Point p = editor.pixelOf(world);
        editor.cursorMoved(p.x, p.y);
    };
    const auto press = [&](Key key) {
        editor.key(key, KeyAction::press);
        editor.key(key, KeyAction::release);
    };
    const auto control = [&](Key key) {
        editor.key(Key::control, KeyAction::press);
        press(key);
        editor.key(Key::control, KeyAction::release);
    };
    const auto click = [&](Vec2 world) {
        at(world);
        editor.mouseButton(MouseButton::left, true);
        editor.mouseButton(MouseButton::left, false);
    };
    const auto choose = [&](const char* kind) {
        for (std::size_t i = 0; i < allPartKinds().size() && editor.selectedKind() != partKind(kind); ++i)
            press(Key::tab);
        REQUIRE(editor.selectedKind() == partKind(kind));
    };

    // A target in mid-air, a heavy ball over it marked as the player's, a zone around the ball.
    choose("target");
    click({0.0, 1.5});
    choose("heavy");
    click({0.2, 4.0});
    // Moved by a drag: 5 cm snapping.
    at({0.2, 4.0});
    editor.mouseButton(MouseButton::left, true);
    at({0.01, 4.02});
    editor.mouseButton(MouseButton::left, false);
    REQUIRE(editor.level().level.items.size() == 2);
    CHECK(editor.level().level.items[1].position.x == 0.0);
    CHECK(editor.level().level.items[1].position.y == 4.0);
    at({0.0, 4.0});
    press(Key::p);
    REQUIRE(editor.playerParts().size() == 1);
    CHECK(editor.level().level.items.size() == 1);
    press(Key::z);
    at({-1.0, 3.0});
    editor.mouseButton(MouseButton::left, true);
    at({1.0, 5.0});
    show();
    editor.mouseButton(MouseButton::left, false);
    REQUIRE(editor.level().level.zones.size() == 1);
    // A drag from a corner resizes the zone; past the opposite corner it flips, min below max.
    at({1.0, 5.0});
    editor.mouseButton(MouseButton::left, true);
    at({1.5, 5.5});
    editor.mouseButton(MouseButton::left, false);
    CHECK(editor.level().level.zones[0].box.max.x == 1.5);
    CHECK(editor.level().level.zones[0].box.max.y == 5.5);
    at({1.5, 3.0});
    editor.mouseButton(MouseButton::left, true);
    at({-1.5, 2.5});
    editor.mouseButton(MouseButton::left, false);
    CHECK(editor.level().level.zones[0].box.min.x == -1.5);
    CHECK(editor.level().level.zones[0].box.max.x == -1.0);
    CHECK(editor.level().level.zones[0].box.min.y == 2.5);
    control(Key::z);
    control(Key::z);
    CHECK(editor.level().level.zones[0].box.min.x == -1.0);
    CHECK(editor.level().level.zones[0].box.max.x == 1.0);
    CHECK(editor.level().level.zones[0].box.max.y == 5.0);
    press(Key::z);
    REQUIRE(editor.level().level.zones.size() == 1);
    at({0.0, 1.5});
    press(Key::t);
    REQUIRE(editor.level().level.goal);
    CHECK(editor.level().level.goal->item == "target1");
    CHECK(editor.level().level.goal->timeLimit == 10.0);
    render::writePng(kWork / "editor.png", show());

    // Undo and redo: the goal goes and comes back; the zone too.
    control(Key::z);
    CHECK_FALSE(editor.level().level.goal);
    control(Key::z);
    CHECK(editor.level().level.zones.empty());
    control(Key::y);
    control(Key::y);
    CHECK(editor.level().level.goal);
    CHECK(editor.level().level.zones.size() == 1);
    for (int i = 0; i < 4; ++i) press(Key::down);
    CHECK(editor.level().level.goal->timeLimit == 6.0);

    // Tried: the ball falls onto the target; R comes back to editing, nothing lost.
    press(Key::space);
    REQUIRE(editor.trying());
    while (!editor.trying()->run()->goalStep() && editor.trying()->run()->steps() < 1000) {
        editor.trying()->step();
        if (editor.trying()->run()->steps() % 25 == 0) show();
    }
    REQUIRE(editor.trying()->run()->goalStep());
    const std::int64_t goalStep = *editor.trying()->run()->goalStep();
    press(Key::r);
    CHECK_FALSE(editor.trying());
    CHECK(editor.playerParts().size() == 1);

    // V fits the view to the parts and zones, a metre around them; undone, the view is back.
    const Aabb before = *editor.level().view;
    press(Key::v);
    REQUIRE(editor.level().view);
    const Aabb fitted = *editor.level().view;
    CHECK(fitted.min.x == -2.0);
    CHECK(fitted.max.x == 2.0);
    CHECK(fitted.max.y == 6.0);
    // The camera follows: the view's top left corner is on the window's left or top edge.
    const auto onEdge = [&](const Aabb& view) {
        const render::Point corner = editor.pixelOf({view.min.x, view.max.y});
        return std::min(std::abs(corner.x), std::abs(corner.y)) <= 1.0f;
    };
    CHECK(onEdge(fitted));
    CHECK_FALSE(onEdge(before));
    control(Key::z);
    CHECK(editor.level().view->max.x == before.max.x);
    CHECK(onEdge(before));
    control(Key::y);
    CHECK(editor.level().view->max.x == fitted.max.x);

    // H types a hint (the 'h' that H types is not part of it); Enter keeps it, Esc drops a draft.
    press(Key::h);
    for (const char c : std::string("hDrop it, [x]")) editor.typed(static_cast<char32_t>(c));
    editor.typed(U'\u00e9'); // outside the HUD's font: not taken
    press(Key::backspace);
    press(Key::backspace);
    press(Key::backspace);
    for (const char c : std::string("on it.")) editor.typed(static_cast<char32_t>(c));
    press(Key::p); // typed, not marking: a letter of the hint
    editor.typed(U'!');
    press(Key::enter);
    REQUIRE(editor.level().level.hints.size() == 1);
    CHECK(editor.level().level.hints[0].text == "Drop it, on it.!");
    CHECK(editor.playerParts().size() == 1);
    press(Key::h);
    editor.typed(U'h');
    editor.typed(U'x');
    press(Key::escape);
    CHECK(editor.level().level.hints.size() == 1);
    CHECK_FALSE(editor.quitRequested());

    // Spares: the inventory gives two planks beyond the player's ball.
    choose("plank");
    press(Key::i);
    press(Key::i);
    press(Key::i);
    press(Key::k);
    CHECK(editor.inventory().at("plank") == 2);
    CHECK(editor.inventory().at("heavy") == 1);
    choose("target");
    press(Key::i);
    CHECK_THAT(editor.message(), Catch::Contains("cannot be in the inventory"));

    // A switch needs `triggers`: L links it to the next part it can trigger, in turn.
    choose("switch");
    click({6.0, 0.5});
    at({6.0, 0.5});
    press(Key::l);
    CHECK_THAT(editor.message(), Catch::StartsWith("L: nothing a switch can trigger yet"));
    choose("cannon");
    click({-6.0, 2.0});
    click({-4.0, 2.0});
    at({6.0, 0.5});
    press(Key::l);
    CHECK(editor.message() == "switch1 triggers cannon1");
    press(Key::l);
    CHECK(editor.message() == "switch1 triggers cannon2");
    press(Key::l);
    CHECK(editor.message() == "switch1 triggers cannon1");
    press(Key::v);

    // E types a part's own key (the cannon's speed), O the goal's text, J then Enter changes a
    // hint; C and a drag set the view beyond the fitted one.
    const auto typeText = [&](const std::string& text) {
        for (const char c : text) editor.typed(static_cast<char32_t>(c));
    };
    at({-6.0, 2.0});
    press(Key::e);
    typeText("e9");
    press(Key::enter);
    CHECK(editor.message() == "cannon1: speed = 9");
    press(Key::o);
    typeText("o");
    for (int i = 0; i < 40; ++i) press(Key::backspace);
    typeText("Drop the ball on the target");
    press(Key::enter);
    press(Key::j);
    press(Key::enter);
    typeText(" Soon.");
    press(Key::enter);
    press(Key::c);
    show();
    at({9.0, 8.0});
    editor.mouseButton(MouseButton::left, true);
    at({-9.0, -1.0});
    editor.mouseButton(MouseButton::left, false);
    show();

    // Saved: `rube check --strict` passes the level and its solution, which replays to that step.
    control(Key::s);
    INFO(editor.message());
    REQUIRE_THAT(editor.message(), Catch::StartsWith("saved made.toml and made.solution.toml"));
    CHECK_THAT(editor.message(), Catch::EndsWith(", and holds with each part moved one 5 cm grid step"));
    const std::filesystem::path solution = kWork / "made.solution.toml";
    const std::string check = std::string("\"") + RUBE_BINARY + "\" check --strict \"" + file.string() + "\" \"" +
                              solution.string() + "\" > \"" + (kWork / "made.check.txt").string() + "\" 2>&1";
    INFO(check);
    CHECK(std::system(check.c_str()) == 0);
    const std::string replay = std::string("\"") + RUBE_BINARY + "\" run \"" + file.string() + "\" --script \"" +
                               solution.string() + "\" --no-render > \"" + (kWork / "made.run.txt").string() +
                               "\" 2>&1";
    INFO(replay);
    REQUIRE(std::system(replay.c_str()) == 0);
    std::ifstream printed(kWork / "made.run.txt");
    const std::string text((std::istreambuf_iterator<char>(printed)), std::istreambuf_iterator<char>());
    CHECK_THAT(text, Catch::Contains("goal:             reached at step " + std::to_string(goalStep)));
    std::ifstream saved(file);
    const std::string written((std::istreambuf_iterator<char>(saved)), std::istreambuf_iterator<char>());
    CHECK_THAT(written, Catch::Contains("time_limit = 6\n")); // set with Down
    CHECK_THAT(written, Catch::Contains("heavy = 1\nplank = 2\n"));
    CHECK_THAT(written, Catch::Contains("[[hint]]\ntext = 'Drop it, on it.! Soon.'\n"));
    CHECK_THAT(written, Catch::Contains("[view]\nmin = [-9, -1]\nmax = [9, 8]\n"));
    CHECK_THAT(written, Catch::Contains("name = 'cannon1'\nposition = [-6, 2]\nspeed = 9\n"));
    CHECK_THAT(written, Catch::Contains("text = 'Drop the ball on the target'\ncondition = 'target-hit'\n"));
    CHECK_THAT(written, Catch::Contains("name = 'switch1'\nposition = [6, 0.5]\ntriggers = 'cannon1'\n"));

    // A shipped level opened with its solution keeps its inventory, spares and all.
    for (const char* name : {"ramp", "chain-reaction", "pegs"}) {
        const SceneDesc shipped = level(name);
        const ScriptLoad solution = loadScriptFile(kLevels / (std::string(name) + ".solution.toml"), shipped);
        REQUIRE(solution.script);
        const EditSession opened(shipped, kWork / "opened.toml", {640, 360}, solution.script->placements);
        CHECK(opened.inventory() == shipped.level.inventory);
        CHECK(opened.playerParts().size() == solution.script->placements.size());
    }
}
