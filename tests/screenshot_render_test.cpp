// Screenshot tests: render a small fixed scene offscreen (EGL or OSMesa: test_gl_backend.hpp) and
// compare it with the golden frame screenshots/render-basics_0000.png. These are the only renderer
// tests that need a GL context; every CTest name here starts with "screenshot: ".
// Regenerate the golden on purpose with UPDATE_SCREENSHOTS=1, then look at it before committing.
#include "rube/render/draw_list.hpp"
#include "rube/render/image_compare.hpp"
#include "rube/render/palette.hpp"
#include "rube/render/render_context.hpp"
#include "rube/render/renderer.hpp"
#include "rube/render/screenshot.hpp"

#include "render_basics.hpp"
#include "test_gl_backend.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <memory>
#include <string>

#include <unistd.h>

using namespace rube::render;

namespace {

constexpr FrameSize frameSize{480, 270};
// 16 m x 9 m fills the 480x270 frame: 30 pixels per metre.
const Rect sceneRect{{-8.0f, -4.5f}, {8.0f, 4.5f}};

// One context and renderer for the whole executable: creating a GL context costs more than a test.
Renderer& renderer() {
    static std::unique_ptr<RenderContext> context = createOffscreenContext(frameSize, rube::test::testGlBackend());
    static Renderer instance(*context);
    return instance;
}

Camera sceneCamera() { return Camera::fitting(sceneRect, frameSize); }

std::filesystem::path goldenPath(std::string_view scene, int frame) {
    return std::filesystem::path(RUBE_SCREENSHOTS_DIR) / goldenFileName(scene, frame);
}

// A pixel's colour at a world point.
Color colourAt(const Image& image, Point world) {
    Point p = sceneCamera().toPixels(world, frameSize);
    int x = static_cast<int>(p.x);
    int y = frameSize.height - 1 - static_cast<int>(p.y); // image rows run top down
    const std::uint8_t* rgb = image.pixel(x, y);
    return {rgb[0], rgb[1], rgb[2], 255};
}

} // namespace

TEST_CASE("render-basics frame 0 matches its golden", "[render][screenshot]") {
    Image frame = renderer().render(renderBasics(), sceneCamera());
    ScreenshotCheck check = checkScreenshot(frame, goldenPath("render-basics", 0), RUBE_SCREENSHOT_FAILURES_DIR);
    INFO(check.message);
    CHECK(check.passed);
}

TEST_CASE("two renders of the same list are byte-identical", "[render][screenshot]") {
    DrawList list = renderBasics();
    Image first = renderer().render(list, sceneCamera());
    Image second = renderer().render(list, sceneCamera());
    REQUIRE(first.width == frameSize.width);
    REQUIRE(first.height == frameSize.height);
    CHECK(first.rgb == second.rgb);
}

TEST_CASE("the comparison fails a ball moved by 3 pixels and passes an identical render", "[render][screenshot]") {
    Image base = renderer().render(renderBasics(), sceneCamera());
    Image again = renderer().render(renderBasics(), sceneCamera());
    Image moved = renderer().render(renderBasics(0.1f), sceneCamera()); // 0.1 m = 3 px
    REQUIRE(sceneCamera().pixelsPerMetre(frameSize) == Approx(30.0f));

    Comparison same = compareImages(again, base);
    CHECK(same.matches);
    CHECK(same.differingPixels == 0);

    Comparison shifted = compareImages(moved, base);
    INFO(shifted.differingPixels << " of " << shifted.totalPixels << " pixels differ");
    CHECK_FALSE(shifted.matches);
}

TEST_CASE("a rendered frame is right way up and in the palette's colours", "[render][screenshot]") {
    const Palette& palette = Palette::greybox();
    Image frame = renderer().render(renderBasics(), sceneCamera());
    // Inside the big ball, away from its spoke and outline: the fill, exactly (no blending).
    CHECK(colourAt(frame, {-5.0f, -0.5f}) == palette["ball"]);
    // The background in an empty spot, high up on the right.
    CHECK(colourAt(frame, {7.5f, 4.2f}) == palette["background"]);
    // The ramp is at the bottom left: y up in the world is up in the picture.
    CHECK(colourAt(frame, {-7.5f, -4.2f}) == palette["ground"]);
    // The HUD line is in the top rows of the image.
    int darkPixelsAtTop = 0;
    for (int y = 8; y < 24; ++y) {
        for (int x = 8; x < 200; ++x) darkPixelsAtTop += frame.pixel(x, y)[0] < 80 ? 1 : 0;
    }
    CHECK(darkPixelsAtTop > 100);
}

TEST_CASE("a rendered frame survives a PNG round trip exactly", "[render][screenshot]") {
    Image frame = renderer().render(renderBasics(), sceneCamera());
    std::filesystem::path path = std::filesystem::path(RUBE_SCREENSHOT_FAILURES_DIR) /
                                 ("round-trip-" + std::to_string(::getpid()) + ".png");
    std::filesystem::create_directories(path.parent_path());
    writePng(path, frame);
    Image back = readPng(path);
    std::filesystem::remove(path);
    CHECK(back == frame);
}

TEST_CASE("a translucent polygon shows no seam along the diagonals inside it", "[render][screenshot]") {
    // One world unit per pixel, so the square's diagonals run exactly through pixel centres,
    // where the two triangles on either side tie: exactly one of them must draw each pixel.
    std::unique_ptr<RenderContext> context = createOffscreenContext({64, 64}, rube::test::testGlBackend());
    Renderer small(*context);
    DrawList list;
    list.background = {0, 0, 0, 255};
    const Point square[] = {{10, 10}, {50, 10}, {50, 50}, {10, 50}};
    const Point ell[] = {{52, 2}, {62, 2}, {62, 30}, {57, 30}, {57, 7}, {52, 7}};
    list.polygon(square, {{200, 200, 200, 128}, {}, 0.0f});
    list.polygon(ell, {{200, 200, 200, 128}, {}, 0.0f});
    Image frame = small.render(list, Camera{{32, 32}, 64});

    const std::uint8_t expected = frame.pixel(30, 30)[0];
    CHECK(expected == Approx(100).margin(1));
    int seams = 0;
    for (int y = 64 - 49; y < 64 - 11; ++y) {
        for (int x = 11; x < 49; ++x) seams += frame.pixel(x, y)[0] != expected ? 1 : 0;
    }
    for (int y = 64 - 29; y < 64 - 3; ++y) seams += frame.pixel(59, y)[0] != expected ? 1 : 0;
    CHECK(seams == 0);
}
