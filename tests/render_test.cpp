// Renderer tests that need no GL context: palette, camera, draw-list building, image
// comparison, PNG files and the frame writer. (The ones that draw are in screenshot_*.cpp.)
#include "rube/render/camera.hpp"
#include "rube/render/draw_list.hpp"
#include "rube/render/frame_writer.hpp"
#include "rube/render/image.hpp"
#include "rube/render/image_compare.hpp"
#include "rube/render/palette.hpp"
#include "rube/render/render_context.hpp"
#include "rube/render/screenshot.hpp"
#include "rube/render/video_writer.hpp"

#include "shape_instance.hpp" // internal: how a draw list becomes shader instances

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <optional>
#include <string>

using namespace rube::render;

namespace {

// A fresh folder under the system's temporary folder, removed when the test ends.
struct TemporaryFolder {
    std::filesystem::path path;
    TemporaryFolder() {
        std::string pattern = (std::filesystem::temp_directory_path() / "rube-render-test-XXXXXX").string();
        REQUIRE(::mkdtemp(pattern.data()) != nullptr);
        path = pattern;
    }
    ~TemporaryFolder() { std::filesystem::remove_all(path); }
};

// Hides UPDATE_SCREENSHOTS for one test, so regenerating goldens cannot change its outcome.
struct NoScreenshotUpdate {
    std::optional<std::string> saved;
    NoScreenshotUpdate() {
        if (const char* value = std::getenv("UPDATE_SCREENSHOTS")) saved = value;
        ::unsetenv("UPDATE_SCREENSHOTS");
    }
    ~NoScreenshotUpdate() {
        if (saved) ::setenv("UPDATE_SCREENSHOTS", saved->c_str(), 1);
    }
};

// A grey test card with a dark square, so shifts and differences have edges to act on.
Image testCard(int squareX = 20, int squareY = 10) {
    Image image = Image::filled(64, 48, 200, 200, 200);
    for (int y = squareY; y < squareY + 16; ++y) {
        for (int x = squareX; x < squareX + 16; ++x) {
            std::uint8_t* p = image.pixel(x, y);
            p[0] = 40;
            p[1] = 40;
            p[2] = 40;
        }
    }
    return image;
}

std::vector<std::string> filesIn(const std::filesystem::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace

TEST_CASE("palette: colours parse, comments are skipped, mistakes are named", "[render]") {
    Palette palette = Palette::parse("# a comment\nball = \"#ff8000\"  # orange\n\ntrail = \"#10203040\"\n");
    CHECK(palette["ball"] == Color{255, 128, 0, 255});
    CHECK(palette["trail"] == Color{16, 32, 48, 64});
    CHECK(palette.contains("ball"));
    CHECK_FALSE(palette.contains("bal"));
    CHECK_THROWS_WITH(palette["bal"], Catch::Contains("bal"));
    CHECK_THROWS_WITH(Palette::parse("ball = #ff8000"), Catch::Contains("line 1"));
    CHECK_THROWS_WITH(Palette::parse("\nball = \"#ff80\""), Catch::Contains("line 2"));
    CHECK_THROWS_WITH(Palette::parse("a = \"#000000\"\na = \"#111111\""), Catch::Contains("twice"));
    CHECK_THROWS(parseColor("#gg0000"));
}

TEST_CASE("palette: the embedded greybox palette has every role and neutral greys", "[render]") {
    const Palette& palette = Palette::greybox();
    for (const char* role : {"background", "ground", "ground_outline", "ball", "ball_outline", "spoke", "box",
                             "box_outline", "trail", "arrow", "explosion", "hud_text"}) {
        INFO(role);
        CHECK(palette.contains(role));
    }
    // r = g = b keeps PNG frames small (see assets/palette.toml).
    for (const char* grey : {"background", "ground", "ball", "box"}) {
        Color c = palette[grey];
        CHECK((c.r == c.g && c.g == c.b));
    }
    CHECK(DrawList{}.background == palette["background"]);
}

TEST_CASE("camera: fitting shows the whole rect, centred, with square pixels", "[render]") {
    FrameSize frame{1280, 720};
    Camera wide = Camera::fitting({{0, 0}, {32, 9}}, frame); // wider than 16:9: width decides
    CHECK(wide.viewHeight == Approx(18.0f));
    CHECK(wide.centre.x == Approx(16.0f));
    Camera tall = Camera::fitting({{-1, -5}, {1, 5}}, frame, 1.0f); // taller: height (with margin) decides
    CHECK(tall.viewHeight == Approx(12.0f));
    Point corner = wide.toPixels({0, 0}, frame);
    CHECK(corner.x == Approx(0.0f).margin(1e-3));
    CHECK(corner.y == Approx(180.0f)); // y up: 9 m of empty band above and below
    Point back = wide.toWorld(wide.toPixels({3.5f, 2.25f}, frame), frame);
    CHECK(back.x == Approx(3.5f));
    CHECK(back.y == Approx(2.25f));
}

TEST_CASE("draw list: primitives become pixel-space instances in order", "[render]") {
    FrameSize frame{200, 100};
    Camera camera{{0, 0}, 10.0f}; // 10 pixels per metre, origin at the frame's centre
    Style style{{255, 255, 255, 255}, {0, 0, 0, 255}, 2.0f};
    DrawList list;
    list.circleWithSpoke({1.0f, 2.0f}, 0.5f, 0.0f, style);
    list.box({0, 0}, {1.0f, 2.0f}, 0.0f, style);
    list.ring({0, 0}, 3.0f, 4.0f, {255, 0, 0, 255});
    list.line({0, 0}, {1, 0}, 3.0f, {0, 0, 255, 255});

    std::vector<ShapeInstance> instances;
    buildInstances(list, camera, frame, instances);
    REQUIRE(instances.size() == 5);
    // The disc: centre and radius in pixels, y up from the bottom-left corner.
    CHECK(instances[0].kind() == ShapeKind::disc);
    CHECK(instances[0].geomA[0] == Approx(110.0f));
    CHECK(instances[0].geomA[1] == Approx(70.0f));
    CHECK(instances[0].geomA[2] == Approx(5.0f));
    CHECK(instances[0].outlineWidth == Approx(2.0f));
    // The spoke: a capsule in the outline colour from the centre towards the rim at angle 0.
    CHECK(instances[1].kind() == ShapeKind::capsule);
    CHECK(instances[1].fill == style.outline);
    CHECK(instances[1].geomA[2] > instances[1].geomA[0]);
    CHECK(instances[1].geomA[2] + instances[1].geomB[0] <= Approx(115.0f)); // the cap stops at the rim
    CHECK(instances[2].kind() == ShapeKind::box);
    CHECK(instances[2].geomA[2] == Approx(10.0f));
    CHECK(instances[2].geomA[3] == Approx(20.0f));
    // The ring: a disc with no fill and the ring's colour as a 4-pixel outline.
    CHECK(instances[3].kind() == ShapeKind::disc);
    CHECK(instances[3].fill.a == 0);
    CHECK(instances[3].outlineWidth == Approx(4.0f));
    CHECK(instances[4].geomB[0] == Approx(1.5f)); // a 3-pixel line is a capsule of radius 1.5 px
}

TEST_CASE("draw list: a concave polygon becomes n - 2 triangles covering its area", "[render]") {
    // An L shape, clockwise, area 3.
    const Point shape[] = {{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}};
    DrawList list;
    list.polygon(shape, {});
    auto triangles = list.triangles();
    REQUIRE(triangles.size() == 4);
    double area = 0.0;
    int boundaryEdges = 0;
    for (const Triangle& t : triangles) {
        Point a = list.points()[t.index[0]], b = list.points()[t.index[1]], c = list.points()[t.index[2]];
        double twice = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        CHECK(twice > 0.0); // counter-clockwise, whatever the input winding
        area += 0.5 * twice;
        for (int bit = 0; bit < 3; ++bit) boundaryEdges += (t.boundaryEdges >> bit) & 1;
    }
    CHECK(area == Approx(3.0));
    CHECK(boundaryEdges == 6); // each outline edge antialiased exactly once, diagonals never
}

TEST_CASE("draw list: a trail fades from its first colour to its last", "[render]") {
    const Point points[] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}};
    DrawList list;
    list.polyline(points, 2.0f, {0, 0, 0, 0}, {0, 0, 0, 200});
    std::vector<ShapeInstance> instances;
    buildInstances(list, Camera{}, {100, 100}, instances);
    REQUIRE(instances.size() == 4);
    CHECK(instances[0].fill.a == 25);
    CHECK(instances[3].fill.a == 175);
}

TEST_CASE("draw list: text becomes crisp boxes from the top-left corner, odd characters show as '?'", "[render]") {
    DrawList list;
    list.text(10, 5, "I\x01", {0, 0, 0, 255}, 2);
    CHECK(list.textOf(std::get<primitive::Text>(list.primitives()[0])) == "I?");
    std::vector<ShapeInstance> instances;
    buildInstances(list, Camera{}, {100, 50}, instances);
    REQUIRE_FALSE(instances.empty());
    for (const ShapeInstance& s : instances) {
        CHECK(s.kind() == ShapeKind::box);
        // Edges on whole pixels at scale 2: the antialiasing leaves them sharp.
        CHECK(std::fmod(s.geomA[0] - s.geomA[2], 1.0f) == 0.0f);
        CHECK(std::fmod(s.geomA[1] + s.geomA[3], 1.0f) == 0.0f);
        CHECK(s.geomA[1] + s.geomA[3] <= 45.0f); // below the 5-pixel top margin, y up
    }
}

// textWidth lays out HUD lines (issue 23: a goal's text wraps inside the frame): every box a text
// is drawn with must lie within it, at any scale, and it grows with the text.
TEST_CASE("text width: the drawn boxes of a text lie within textWidth of its left edge", "[render]") {
    CHECK(textWidth("", 2) == 0);
    for (const std::string text : {"I", "hit the flag with the ball", "REACHED at step 266: WWW mmm ..."}) {
        for (const int scale : {1, 2, 3}) {
            CAPTURE(text, scale);
            DrawList list;
            list.text(10, 5, text, {0, 0, 0, 255}, scale);
            std::vector<ShapeInstance> instances;
            buildInstances(list, Camera{}, {4000, 100}, instances);
            float right = 0.0f;
            for (const ShapeInstance& s : instances) right = std::max(right, s.geomA[0] + s.geomA[2]);
            CHECK(right <= 10.0f + static_cast<float>(textWidth(text, scale)));
            CHECK(right > 10.0f + 0.5f * static_cast<float>(textWidth(text, scale)));
            CHECK(textWidth(text, scale) == scale * textWidth(text, 1));
        }
    }
    CHECK(textWidth("hit the flag", 2) > textWidth("hit the", 2));
}

TEST_CASE("image comparison: identical and one-pixel-shifted frames match", "[render]") {
    Image card = testCard();
    Comparison same = compareImages(card, card);
    CHECK(same.matches);
    CHECK(same.differingPixels == 0);
    Comparison shifted = compareImages(testCard(21, 11), card);
    CHECK(shifted.matches);
    CHECK(shifted.differingPixels == 0);
    CHECK(shifted.largestDifference == 160);
}

TEST_CASE("image comparison: small channel noise matches, a 3-pixel move and a size change fail", "[render]") {
    Image card = testCard();
    Image noisy = card;
    for (std::size_t i = 0; i < noisy.rgb.size(); i += 7) noisy.rgb[i] = static_cast<std::uint8_t>(noisy.rgb[i] + 16);
    CHECK(compareImages(noisy, card).matches);
    noisy.rgb[0] = static_cast<std::uint8_t>(noisy.rgb[0] + 1); // 17 > 16, at one pixel of 3072
    CHECK(compareImages(noisy, card).differingPixels == 1);
    CHECK(compareImages(noisy, card).matches); // 0.1 % of 3072 pixels: up to 3 may differ

    Comparison moved = compareImages(testCard(23, 10), card);
    CHECK_FALSE(moved.matches);
    // Checked both ways, a move by d flags d columns along each edge (2 x 3 x 16), less the
    // corner pixels of the innermost column, whose diagonal neighbour still matches (2 x 2).
    CHECK(moved.differingPixels == 2 * 3 * 16 - 2 * 2);

    Comparison resized = compareImages(Image::filled(10, 10, 0, 0, 0), card);
    CHECK_FALSE(resized.sameSize);
    CHECK_FALSE(resized.matches);
}

TEST_CASE("image comparison: a missing one-pixel line fails in either direction", "[render]") {
    Image plain = Image::filled(64, 64, 200, 200, 200);
    Image lined = plain;
    for (int x = 0; x < 64; ++x) lined.pixel(x, 30)[1] = 0;
    CHECK_FALSE(compareImages(lined, plain).matches);
    CHECK_FALSE(compareImages(plain, lined).matches);
}

TEST_CASE("image comparison: the diff image marks differences red on faded grey", "[render]") {
    Image card = testCard();
    Image diff = diffImage(testCard(23, 10), card);
    const std::uint8_t* red = diff.pixel(21, 15); // uncovered by the move
    CHECK((red[0] == 255 && red[1] == 0 && red[2] == 0));
    const std::uint8_t* light = diff.pixel(2, 2); // background, unchanged
    CHECK((light[0] == light[1] && light[1] == light[2] && light[0] >= 170));
    CHECK_THROWS(diffImage(Image::filled(2, 2, 0, 0, 0), card));
}

TEST_CASE("png: a frame written and read back is identical, with no temporary file left", "[render]") {
    TemporaryFolder folder;
    Image card = testCard();
    card.pixel(0, 0)[0] = 1; // top-left stays top-left
    writePng(folder.path / "card.png", card);
    CHECK(readPng(folder.path / "card.png") == card);
    CHECK(filesIn(folder.path) == std::vector<std::string>{"card.png"});
    CHECK_THROWS_WITH(readPng(folder.path / "missing.png"), Catch::Contains("missing.png"));
}

TEST_CASE("png: a flat 1280x720 frame encodes to a few kilobytes", "[render]") {
    std::vector<std::uint8_t> png = encodePng(Image::filled(1280, 720, 212, 212, 212));
    CHECK(png.size() < 8000);
    CHECK(png[1] == 'P');
}

TEST_CASE("frame writer: writes every frame whole and recycles their memory", "[render]") {
    TemporaryFolder folder;
    {
        FrameWriter writer(folder.path / "frames", 2);
        for (int i = 0; i < 6; ++i) {
            Image frame = writer.spareImage();
            frame = testCard(4 * i, 10);
            writer.write(std::move(frame), goldenFileName("card", i));
        }
        writer.finish();
        CHECK(writer.framesWritten() == 6);
        CHECK(writer.bytesWritten() > 0);
        CHECK(writer.spareImage().width == 64);
    }
    auto names = filesIn(folder.path / "frames");
    REQUIRE(names.size() == 6); // no probe or .part files left behind
    CHECK(names.front() == "card_0000.png");
    CHECK(readPng(folder.path / "frames" / "card_0005.png") == testCard(20, 10));
}

TEST_CASE("frame writer: an unwritable folder is reported clearly", "[render]") {
    TemporaryFolder folder;
    std::ofstream(folder.path / "a-file") << "not a folder";
    // A folder inside a file cannot exist, even for root (who may write anywhere else).
    CHECK_THROWS_WITH(FrameWriter(folder.path / "a-file" / "frames"), Catch::Contains("a-file/frames"));

    // The folder disappears after the writer started: the error comes back from finish().
    FrameWriter writer(folder.path / "gone");
    std::filesystem::remove_all(folder.path / "gone");
    writer.write(testCard(), "frame.png");
    CHECK_THROWS_WITH(writer.finish(), Catch::Contains("gone/frame.png"));
    CHECK_THROWS(writer.write(testCard(), "next.png")); // stopped at the first error
}

TEST_CASE("golden check: a missing golden fails and leaves the frame to look at", "[render]") {
    NoScreenshotUpdate noUpdate;
    TemporaryFolder folder;
    ScreenshotCheck check = checkScreenshot(testCard(), folder.path / "scene_0000.png", folder.path / "failures");
    CHECK_FALSE(check.passed);
    CHECK_THAT(check.message, Catch::Contains("UPDATE_SCREENSHOTS=1"));
    CHECK(readPng(check.actualPath) == testCard());
    CHECK_FALSE(std::filesystem::exists(folder.path / "scene_0000.png"));
}

TEST_CASE("golden check: a mismatch writes actual, expected and diff, a match passes", "[render]") {
    NoScreenshotUpdate noUpdate;
    TemporaryFolder folder;
    std::filesystem::path golden = folder.path / "scene_0001.png";
    writePng(golden, testCard());
    CHECK(checkScreenshot(testCard(), golden, folder.path / "failures").passed);

    ScreenshotCheck check = checkScreenshot(testCard(30, 20), golden, folder.path / "failures");
    CHECK_FALSE(check.passed);
    CHECK(check.comparison.differingPixels > 0);
    CHECK(readPng(check.actualPath) == testCard(30, 20));
    CHECK(readPng(check.expectedPath) == testCard());
    CHECK(readPng(check.diffPath).width == 64);
    CHECK_THAT(check.message, Catch::Contains(check.diffPath.string()));

    CHECK(checkScreenshot(testCard(), golden, folder.path / "failures").passed);
    CHECK_FALSE(std::filesystem::exists(check.diffPath)); // stale evidence is cleared by a pass
}

TEST_CASE("golden check: UPDATE_SCREENSHOTS=1 writes the golden and passes", "[render]") {
    NoScreenshotUpdate restoreAfterwards;
    ::setenv("UPDATE_SCREENSHOTS", "1", 1);
    TemporaryFolder folder;
    ScreenshotCheck check = checkScreenshot(testCard(), folder.path / "goldens" / "scene_0000.png",
                                            folder.path / "failures");
    ::unsetenv("UPDATE_SCREENSHOTS");
    CHECK(check.passed);
    CHECK(check.goldenWritten);
    CHECK(readPng(folder.path / "goldens" / "scene_0000.png") == testCard());
}

TEST_CASE("contexts: bad requests fail with a reason, before any GL is touched", "[render]") {
    CHECK_THROWS_WITH(createOffscreenContext({0, 720}), Catch::Contains("0x720"));
    // Without a display a window cannot open; the error says so instead of crashing.
    if (std::getenv("DISPLAY") == nullptr && std::getenv("WAYLAND_DISPLAY") == nullptr) {
        CHECK_THROWS_WITH(createWindowContext({320, 240}), Catch::Contains("GLFW"));
    }
}

TEST_CASE("GL back ends: names round-trip, and one not built is refused with how the build was made", "[render]") {
    for (GlBackend backend : {GlBackend::automatic, GlBackend::egl, GlBackend::osmesa}) {
        INFO(glBackendName(backend));
        CHECK(glBackendFromName(glBackendName(backend)) == backend);
        if (!glBackendBuilt(backend)) {
            CHECK_THROWS_WITH(createOffscreenContext({64, 64}, backend), Catch::Contains("built without"));
        }
    }
    CHECK((glBackendBuilt(GlBackend::egl) || glBackendBuilt(GlBackend::osmesa))); // CMake refuses a build with neither
    for (const char* name : {"", "EGL", "gl", "auto ", "mesa"}) CHECK_FALSE(glBackendFromName(name));
    // An empty size is refused before any back end is tried, whichever is asked for.
    for (GlBackend backend : {GlBackend::automatic, GlBackend::egl, GlBackend::osmesa}) {
        CHECK_THROWS_AS(createOffscreenContext({640, 0}, backend), std::invalid_argument);
    }
}

TEST_CASE("videos: the format follows the extension, H.264 refuses odd sides", "[render]") {
    CHECK(videoFormatOf("a/b.mp4") == VideoFormat::mp4);
    CHECK(videoFormatOf("B.WebM") == VideoFormat::webm);
    CHECK(videoFormatOf("c.gif") == VideoFormat::gif);
    for (const char* name : {"d.avi", "mp4", "e.mp4.part", "f", ".gif.x"}) CHECK_FALSE(videoFormatOf(name));
    for (int w = 1; w <= 8; ++w) {
        for (int h = 1; h <= 8; ++h) {
            CHECK(videoSizeProblem(VideoFormat::mp4, {w, h}).empty() == (w % 2 == 0 && h % 2 == 0));
            CHECK(videoSizeProblem(VideoFormat::webm, {w, h}).empty());
            CHECK(videoSizeProblem(VideoFormat::gif, {w, h}).empty());
        }
    }
}

TEST_CASE("videos: the frame rate given to ffmpeg is 1 / (time step x every) as a reduced fraction", "[render]") {
    const auto parse = [](const std::string& text) {
        const std::size_t slash = text.find('/');
        return std::pair{std::stoll(text.substr(0, slash)),
                         slash == std::string::npos ? 1LL : std::stoll(text.substr(slash + 1))};
    };
    // A time step of 1/N s and a frame every K steps: exactly N/K frames a second, reduced.
    for (long long n : {24, 30, 50, 60, 100, 120, 240, 1000}) {
        for (long long every = 1; every <= 12; ++every) {
            const std::string text = ffmpegRate(1.0 / ((1.0 / static_cast<double>(n)) * static_cast<double>(every)));
            INFO("dt 1/" << n << " every " << every << ": " << text);
            const auto [numerator, denominator] = parse(text);
            const long long g = std::gcd(n, every);
            CHECK(numerator == n / g);
            CHECK(denominator == every / g);
        }
    }
    // Any other rate: a fraction with a denominator of at most 1001, within 1/q^2 of it.
    for (double rate : {29.97002997002997, 23.976, 12.5, 0.75, 7.3, 59.94, 1.0 / 0.0125 / 7}) {
        const auto [numerator, denominator] = parse(ffmpegRate(rate));
        INFO(rate << " -> " << numerator << "/" << denominator);
        CHECK(denominator <= 1001);
        CHECK(std::gcd(numerator, denominator) == 1);
        CHECK(std::abs(static_cast<double>(numerator) / static_cast<double>(denominator) - rate) <=
              1.0 / static_cast<double>(denominator * denominator));
    }
    CHECK(ffmpegRate(30000.0 / 1001.0) == "30000/1001");
}
