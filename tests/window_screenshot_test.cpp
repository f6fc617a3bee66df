// The window back end draws what the off-screen one draws: render-basics into a real GLFW window
// (under Xvfb in CI, so Mesa's llvmpipe again), read back from its back buffer and checked against
// the same golden with the same thresholds. Run by CTest through xvfb-run; by hand, a display will do.
#include "rube/render/render_context.hpp"
#include "rube/render/renderer.hpp"
#include "rube/render/screenshot.hpp"

#include "render_basics.hpp"

#include <catch2/catch.hpp>

using namespace rube::render;

TEST_CASE("render-basics drawn in a GLFW window matches the off-screen golden", "[screenshot][window]") {
    constexpr FrameSize frameSize{480, 270};
    WindowOptions options;
    options.title = "rube window test";
    options.vsync = false;
    std::unique_ptr<RenderContext> window = createWindowContext(frameSize, options);
    REQUIRE(window->size().width == frameSize.width);
    REQUIRE(window->size().height == frameSize.height);
    Renderer renderer(*window);
    const Camera camera = Camera::fitting({{-8.0f, -4.5f}, {8.0f, 4.5f}}, frameSize);
    // Twice, presenting in between, as a window does frame after frame: the second must match too.
    for (int frame = 0; frame < 2; ++frame) {
        renderer.draw(renderBasics(), camera);
        Image image;
        window->readPixels(image);
        const ScreenshotCheck check = checkScreenshot(
            image, std::filesystem::path(RUBE_SCREENSHOTS_DIR) / goldenFileName("render-basics", 0),
            RUBE_SCREENSHOT_FAILURES_DIR "/window");
        INFO(check.message);
        CHECK(check.passed);
        CHECK_FALSE(check.goldenWritten);
        window->present();
    }
}
