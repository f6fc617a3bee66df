// Level screenshot tests: each level's first frame and its goal frame, played by its solution
// script and drawn by LevelView as `rube run --script --out` draws them, compared at 640x360 with
// screenshots/<level>_<frame>.png. UPDATE_SCREENSHOTS=1 regenerates the goldens (look at each).
#include "level_folder.hpp"
#include "level_view.hpp"
#include "scene_file.hpp"
#include "scene_framing.hpp"
#include "script_file.hpp"
#include "test_gl_backend.hpp"

#include "rube/render/render_context.hpp"
#include "rube/render/renderer.hpp"
#include "rube/render/screenshot.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
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
    view.draw(run, run.steps(), list);
    const auto golden = std::filesystem::path(RUBE_SCREENSHOTS_DIR) /
                        render::goldenFileName(level, static_cast<int>(run.steps()));
    const render::ScreenshotCheck result = render::checkScreenshot(renderer().render(list, view.camera()), golden,
                                                                   RUBE_SCREENSHOT_FAILURES_DIR);
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
        for (; next < script.script->actions.size() && script.script->actions[next].step == run.steps(); ++next)
            REQUIRE(takeAction(script.script->actions[next], run).empty());
    };
    act();
    check(run, view, name);
    for (int i = 0; i < 5000 && !run.goalStep(); ++i) {
        run.step();
        act();
    }
    REQUIRE(run.goalStep());
    check(run, view, name);
}

} // namespace

// Every level with a solution (levels/NAME.solution.toml), sorted: a new level is checked by being there.
TEST_CASE("every level: first and goal frames", "[screenshot][level]") {
    std::vector<std::string> names;
    for (const LevelFile& file : levelFilesIn(RUBE_GAME_LEVELS_DIR, LevelFileRole::solution)) names.push_back(file.level);
    REQUIRE(names.size() >= 16);
    for (const std::string& name : names) {
        INFO(name);
        checkLevel(name);
    }
}
