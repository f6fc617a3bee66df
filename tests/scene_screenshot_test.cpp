// Scene screenshot tests: every physics scene in levels/physics/ is simulated to a chosen step,
// drawn by the game's SceneView exactly as `rube run --out` draws it, rendered offscreen
// (OSMesa) at 640x360 and compared with its golden screenshots/<scene>_<step>.png.
// A missing golden fails and leaves the frame in the build tree's screenshot-failures/ to be
// looked at; UPDATE_SCREENSHOTS=1 regenerates the goldens (look at each before committing).
#include "scene_file.hpp"
#include "scene_framing.hpp"
#include "scene_view.hpp"
#include "test_gl_backend.hpp"

#include "rube/render/render_context.hpp"
#include "rube/render/renderer.hpp"
#include "rube/render/screenshot.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <memory>
#include <set>
#include <string>

using namespace rube;
using namespace rube::game;

namespace {

constexpr render::FrameSize kFrameSize{640, 360};

// The golden frames: a frame where something is happening, and the overlays each scene shows
// best (trails where paths matter, impact markers where impacts do).
struct Golden {
    const char* scene;
    int step; // steps taken: the golden's name, and the HUD's "step N"
    bool trails;
    bool impacts;
};
constexpr Golden kGoldens[] = {
    {"ball-stack", 120, false, false},   // t = 2 s: the column should still stand
    {"blocks", 90, false, true},         // t = 1.5 s: lecture 3's blocks mid-flight, impacts on one axis each
    {"bounce", 120, true, false},        // t = 2 s: on the way up after the first bounce
    {"bullet", 1, true, true},           // the step that crosses the line: the impact and the way back
    {"float", 300, false, false},        // t = 5 s: one high, one half under, one on the bottom
    {"islands", 45, true, true},         // t = 0.75 s: the ball's path off the cap (exact), the pile landing (solver)
    {"newtons-cradle", 61, false, true}, // just after the chain of impacts at t = 1 s
    {"pendulum", 90, true, false},       // t = 1.5 s: the three ropes out of step, the double pendulum folded
    {"pile", 45, false, false},          // t = 0.75 s: the balls landing on the pile
    {"pool-break", 20, true, true},      // t = 0.33 s: the break
    {"projectile", 90, true, false},     // t = 1.5 s: past the top of the parabola
    {"rolling", 90, true, false},        // t = 1.5 s: the slider ahead, the disc, the ring behind; spokes turned
    {"seesaw-domino", 90, false, false}, // t = 1.5 s: the seesaw down, the box in flight, the dominoes fallen
    {"slope-rest", 60, true, true},      // t = 1 s: sliding, pressed onto the slope
    {"gears", 60, false, false},         // t = 1 s: teeth turned, the rack halfway to its limit
    {"belt", 60, false, false},          // t = 1 s: three wheels turning one way, the rider on the rim
    {"pulley", 45, false, false},        // t = 0.75 s: the heavy box falling, the light one rising
    {"springs", 40, false, false},       // t = 0.67 s: coils stretched and squeezed, the pair in flight
    {"piston", 90, false, false},        // t = 1.5 s: the ram out 1.5 m, balls leaving the ledge
    {"weld", 36, false, false},          // t = 0.6 s: the hammer down at the ball, the flag swaying
    {"chain", 60, false, false},         // t = 1 s: the chain falling in a curve, the weight below
};

// One context and renderer for the whole executable: making a GL context costs more than a test.
render::Renderer& renderer() {
    static std::unique_ptr<render::RenderContext> context = render::createOffscreenContext(kFrameSize,
                                                                                           rube::test::testGlBackend());
    static render::Renderer instance(*context);
    return instance;
}

render::Image renderGolden(const Golden& golden) {
    const SceneLoad load = loadSceneFile(std::filesystem::path(RUBE_LEVELS_DIR) /
                                         (std::string(golden.scene) + ".toml"));
    INFO((load.errors.empty() ? std::string("no errors") : load.errors.front().format()));
    REQUIRE(load.ok());
    World world = buildWorld(*load.scene);
    ViewOptions options;
    options.trails = golden.trails;
    options.impacts = golden.impacts;
    SceneView view(load.scene->name, world, sceneCamera(frameScene(*load.scene, world), kFrameSize), kFrameSize,
                   options);
    for (int i = 0; i < golden.step; ++i) {
        world.step();
        view.afterStep(world);
    }
    render::DrawList list;
    view.draw(world, list);
    return renderer().render(list, view.camera());
}

void checkGoldens(std::string_view scene) {
    int checked = 0;
    for (const Golden& golden : kGoldens) {
        if (golden.scene != scene) continue;
        ++checked;
        const auto goldenPath = std::filesystem::path(RUBE_SCREENSHOTS_DIR) /
                                render::goldenFileName(scene, golden.step);
        const render::ScreenshotCheck check = render::checkScreenshot(renderGolden(golden), goldenPath,
                                                                      RUBE_SCREENSHOT_FAILURES_DIR);
        INFO(check.message);
        CHECK(check.passed);
    }
    CHECK(checked > 0);
}

} // namespace

TEST_CASE("every physics scene has a golden frame", "[screenshot][scene]") {
    std::set<std::string> withGoldens;
    for (const Golden& golden : kGoldens) withGoldens.insert(golden.scene);
    for (const auto& entry : std::filesystem::directory_iterator(RUBE_LEVELS_DIR)) {
        if (entry.path().extension() != ".toml") continue;
        const std::string scene = entry.path().stem().string();
        INFO(scene << " has no golden frame: add one to kGoldens in " << __FILE__);
        CHECK(withGoldens.contains(scene));
    }
}

// One test per scene, so that `ctest -R screenshot` names the scene that changed.
TEST_CASE("ball-stack matches its golden frames", "[screenshot][scene]") { checkGoldens("ball-stack"); }
TEST_CASE("blocks matches its golden frames", "[screenshot][scene]") { checkGoldens("blocks"); }
TEST_CASE("bounce matches its golden frames", "[screenshot][scene]") { checkGoldens("bounce"); }
TEST_CASE("bullet matches its golden frames", "[screenshot][scene]") { checkGoldens("bullet"); }
TEST_CASE("float matches its golden frames", "[screenshot][scene]") { checkGoldens("float"); }
TEST_CASE("newtons-cradle matches its golden frames", "[screenshot][scene]") { checkGoldens("newtons-cradle"); }
TEST_CASE("pendulum matches its golden frames", "[screenshot][scene]") { checkGoldens("pendulum"); }
TEST_CASE("pile matches its golden frames", "[screenshot][scene]") { checkGoldens("pile"); }
TEST_CASE("pool-break matches its golden frames", "[screenshot][scene]") { checkGoldens("pool-break"); }
TEST_CASE("projectile matches its golden frames", "[screenshot][scene]") { checkGoldens("projectile"); }
TEST_CASE("rolling matches its golden frames", "[screenshot][scene]") { checkGoldens("rolling"); }
TEST_CASE("seesaw-domino matches its golden frames", "[screenshot][scene]") { checkGoldens("seesaw-domino"); }
TEST_CASE("islands matches its golden frames", "[screenshot][scene]") { checkGoldens("islands"); }
TEST_CASE("slope-rest matches its golden frames", "[screenshot][scene]") { checkGoldens("slope-rest"); }
TEST_CASE("gears matches its golden frames", "[screenshot][scene]") { checkGoldens("gears"); }
TEST_CASE("belt matches its golden frames", "[screenshot][scene]") { checkGoldens("belt"); }
TEST_CASE("pulley matches its golden frames", "[screenshot][scene]") { checkGoldens("pulley"); }
TEST_CASE("springs matches its golden frames", "[screenshot][scene]") { checkGoldens("springs"); }
TEST_CASE("piston matches its golden frames", "[screenshot][scene]") { checkGoldens("piston"); }
TEST_CASE("weld matches its golden frames", "[screenshot][scene]") { checkGoldens("weld"); }
TEST_CASE("chain matches its golden frames", "[screenshot][scene]") { checkGoldens("chain"); }
