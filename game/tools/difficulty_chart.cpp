// difficulty_chart: the measured difficulty curve. Reads levels/index.toml and draws each level, in
// the order a player meets them (top to bottom), with a bar as long as the logarithm of its solve
// fraction (rube solve's measure: the share of the valid placements and clicks that solve it), and
// the designer's difficulty beside it; through the project's own renderer, off-screen, to a PNG.
//   ./build/difficulty_chart levels/index.toml screenshots/difficulty.png
#include "level_index.hpp"

#include "rube/render/draw_list.hpp"
#include "rube/render/image.hpp"
#include "rube/render/render_context.hpp"
#include "rube/render/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace {

using namespace rube;

constexpr int kWidth = 960;
constexpr float kLeft = 260, kRight = 900, kTop = 70; // the plot, pixels from the top-left
constexpr float kRow = 18;     // pixels a level: the labels' font (scale 2) is 14 high, so the chart grows with the levels
constexpr float kMargin = 60;  // below the plot, for the axis' labels
constexpr double kDecades = 5; // 1e-5 .. 1

float barEnd(double fraction) {
    const double decades = std::clamp(std::log10(std::max(fraction, 1e-12)) + kDecades, 0.0, kDecades);
    return kLeft + static_cast<float>(decades / kDecades) * (kRight - kLeft);
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: difficulty_chart INDEX.toml OUT.png\n";
        return 2;
    }
    const game::LevelIndexLoad index = game::loadLevelIndex(argv[1]);
    if (!index.levels) {
        std::cerr << index.errors.front().format() << '\n';
        return 2;
    }
    const auto& levels = *index.levels;
    const float bottom = kTop + kRow * static_cast<float>(levels.size());
    const int height = static_cast<int>(bottom + kMargin);
    // A point given from the top-left, as the camera (world = pixels, y up) wants it.
    const auto at = [height](float x, float y) { return render::Point{x, static_cast<float>(height) - y}; };
    const render::Color ink{40, 40, 40, 255}, grid{170, 170, 170, 255}, bar{90, 110, 150, 255};
    render::DrawList list;
    list.text(20, 16, "Measured difficulty: solve fraction of each level (rube solve), in the order played", ink, 2);
    list.text(20, 40, "bar: share of valid candidates that solve it, log scale; d = the designer's difficulty 1-5", ink,
              1);
    for (int d = 0; d <= static_cast<int>(kDecades); ++d) {
        const float x = kLeft + static_cast<float>(d) / static_cast<float>(kDecades) * (kRight - kLeft);
        list.line(at(x, kTop - 6), at(x, bottom), 1.0f, grid);
        char label[16];
        std::snprintf(label, sizeof label, "1e-%d", static_cast<int>(kDecades) - d);
        list.text(static_cast<int>(x) - 16, static_cast<int>(bottom) + 10, d == kDecades ? "1" : label, ink, 2);
    }
    for (std::size_t i = 0; i < levels.size(); ++i) {
        const float y = kTop + kRow * static_cast<float>(i);
        char label[64];
        std::snprintf(label, sizeof label, "%2zu %-15s d%d", i + 1, levels[i].file.stem().string().c_str(),
                      levels[i].difficulty);
        list.text(10, static_cast<int>(y + 0.5f * kRow) - 7, label, ink, 2);
        const double fraction = levels[i].solveFraction.value_or(0.0);
        const float end = barEnd(fraction);
        if (end > kLeft)
            list.box(at(0.5f * (kLeft + end), y + 0.5f * kRow), {0.5f * (end - kLeft), 0.35f * kRow}, 0.0f,
                     {bar, bar, 0.0f});
        std::snprintf(label, sizeof label, "%.4g", fraction);
        list.text(static_cast<int>(end) + 6, static_cast<int>(y + 0.5f * kRow) - 4, label, ink, 1);
    }
    try {
        const render::FrameSize size{kWidth, height};
        const auto context = render::createOffscreenContext(size);
        render::Renderer renderer(*context);
        render::Camera camera;
        camera.centre = {0.5f * kWidth, 0.5f * static_cast<float>(height)};
        camera.viewHeight = static_cast<float>(height);
        renderer.draw(list, camera);
        render::Image image;
        renderer.readPixels(image);
        render::writePng(argv[2], image);
    } catch (const std::exception& e) {
        std::cerr << "difficulty_chart: " << e.what() << '\n';
        return 1;
    }
    std::cout << "wrote " << argv[2] << " (" << levels.size() << " levels)\n";
    return 0;
}
