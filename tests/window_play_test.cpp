// `rube play` end to end, under Xvfb: a session in a real GLFW window is played with synthetic
// input through the handlers GLFW's callbacks call (PlaySession's InputListener), recorded as a
// script, replayed off-screen by the `rube` binary, and the window's level area at a step is
// compared with the off-screen frame of the same step, with the screenshot tests' thresholds.
#include "play_session.hpp"
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
    CHECK_THAT(session.message(), Catch::Contains("placement refused: ramp"));
    render::writePng(kWork / "window-refused.png", show());
    session.mouseButton(MouseButton::left, false);
    CHECK(session.placements().empty());
    CHECK_THAT(session.message(), Catch::StartsWith("not placed: placement refused: ramp"));
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
