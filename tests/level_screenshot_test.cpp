// Level screenshot tests: each level's first frame and its goal frame, played by its solution
// script and drawn by LevelView as `rube run --script --out` draws them, compared at 640x360 with
// screenshots/<level>_<frame>.png. UPDATE_SCREENSHOTS=1 regenerates the goldens (look at each).
#include "level_view.hpp"
#include "scene_file.hpp"
#include "scene_framing.hpp"
#include "script_file.hpp"
#include "test_gl_backend.hpp"

#include "rube/render/render_context.hpp"
#include "rube/render/renderer.hpp"
#include "rube/render/screenshot.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <memory>

using namespace rube;
using namespace rube::game;

namespace {

constexpr render::FrameSize kFrameSize{640, 360};

render::Renderer& renderer() {
    static std::unique_ptr<render::RenderContext> context = render::createOffscreenContext(kFrameSize,
                                                                                           rube::test::testGlBackend());
    static render::Renderer instance(*context);
    return instance;
}

void check(const LevelRun& run, const LevelView& view, const std::string& level) {
    render::DrawList list;
    view.draw(run, run.frame(), list);
    const auto golden = std::filesystem::path(RUBE_SCREENSHOTS_DIR) / render::goldenFileName(level, static_cast<int>(run.frame()));
    const render::ScreenshotCheck result =
        render::checkScreenshot(renderer().render(list, view.camera()), golden, RUBE_SCREENSHOT_FAILURES_DIR);
    INFO(result.message);
    CHECK(result.passed);
}

// The first frame, then the run up to its goal frame as the script plays it.
void checkLevel(const std::string& name) {
    const std::filesystem::path dir(RUBE_GAME_LEVELS_DIR);
    const SceneLoad load = loadSceneFile(dir / (name + ".toml"));
    REQUIRE(load.ok());
    const ScriptLoad script = loadScriptFile(dir / (name + ".solution.toml"), *load.scene);
    REQUIRE(script.script);
    LevelRun run(*load.scene, script.script->placements);
    const LevelView view(name, sceneCamera(frameScene(*load.scene, run.world()), kFrameSize), kFrameSize);
    std::size_t next = 0;
    const auto act = [&] {
        for (; next < script.script->actions.size() && script.script->actions[next].frame == run.frame(); ++next)
            REQUIRE(takeAction(script.script->actions[next], run).empty());
    };
    act();
    check(run, view, name);
    for (int i = 0; i < 5000 && !run.goalFrame(); ++i) {
        run.step();
        act();
    }
    REQUIRE(run.goalFrame());
    check(run, view, name);
}

} // namespace

TEST_CASE("ramp: first and goal frames", "[screenshot][level]") { checkLevel("ramp"); }
TEST_CASE("cannon-arc: first and goal frames", "[screenshot][level]") { checkLevel("cannon-arc"); }
TEST_CASE("moving-target: first and goal frames", "[screenshot][level]") { checkLevel("moving-target"); }
TEST_CASE("chain-reaction: first and goal frames", "[screenshot][level]") { checkLevel("chain-reaction"); }
TEST_CASE("newton: first and goal frames", "[screenshot][level]") { checkLevel("newton"); }
TEST_CASE("bucket: first and goal frames", "[screenshot][level]") { checkLevel("bucket"); }
TEST_CASE("trampoline: first and goal frames", "[screenshot][level]") { checkLevel("trampoline"); }
TEST_CASE("balloon: first and goal frames", "[screenshot][level]") { checkLevel("balloon"); }
TEST_CASE("magnet: first and goal frames", "[screenshot][level]") { checkLevel("magnet"); }
TEST_CASE("fan: first and goal frames", "[screenshot][level]") { checkLevel("fan"); }
TEST_CASE("rope: first and goal frames", "[screenshot][level]") { checkLevel("rope"); }
TEST_CASE("paddle: first and goal frames", "[screenshot][level]") { checkLevel("paddle"); }
TEST_CASE("seesaw: first and goal frames", "[screenshot][level]") { checkLevel("seesaw"); }
TEST_CASE("crates: first and goal frames", "[screenshot][level]") { checkLevel("crates"); }
TEST_CASE("water: first and goal frames", "[screenshot][level]") { checkLevel("water"); }
TEST_CASE("feather: first and goal frames", "[screenshot][level]") { checkLevel("feather"); }
