// level_gallery: every level of levels/index.toml at a glance, in the order a player meets them.
// Each level is drawn as `rube run` draws its first frame, with nothing placed and its placement
// zones shown (what the player sees before the first move), at 640x360 through the project's own
// renderer, off-screen; shrunk by half (2 x 2 pixels averaged) and tiled row by row, with the
// level's number, title and difficulty under it, into one PNG for the README's gallery.
//   ./build/level_gallery levels/index.toml screenshots/levels.png [COLUMNS]
#include "level_index.hpp"
#include "level_run.hpp"
#include "level_view.hpp"
#include "scene_file.hpp"
#include "scene_framing.hpp"

#include "rube/render/draw_list.hpp"
#include "rube/render/image.hpp"
#include "rube/render/render_context.hpp"
#include "rube/render/renderer.hpp"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace {

using namespace rube;

constexpr render::FrameSize kFrame{640, 360}; // the goldens' size, so a thumbnail reads like a frame
constexpr int kShrink = 2;                    // each thumbnail is kFrame / kShrink
constexpr int kCaption = 24;                  // pixels under each thumbnail for its title
constexpr int kGap = 6;                       // pixels between thumbnails
constexpr std::uint8_t kPaper = 235;          // the sheet's background grey

// Averages each kShrink x kShrink block of `frame` into `sheet` with its top-left at (left, top).
void paste(const render::Image& frame, render::Image& sheet, int left, int top) {
    for (int y = 0; y < frame.height / kShrink; ++y)
        for (int x = 0; x < frame.width / kShrink; ++x)
            for (int c = 0; c < 3; ++c) {
                int sum = 0;
                for (int dy = 0; dy < kShrink; ++dy)
                    for (int dx = 0; dx < kShrink; ++dx) sum += frame.pixel(x * kShrink + dx, y * kShrink + dy)[c];
                sheet.pixel(left + x, top + y)[c] = static_cast<std::uint8_t>(sum / (kShrink * kShrink));
            }
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 3 && argc != 4) {
        std::cerr << "usage: level_gallery INDEX.toml OUT.png [COLUMNS]\n";
        return 2;
    }
    const int columns = argc == 4 ? std::atoi(argv[3]) : 5;
    if (columns < 1 || columns > 20) {
        std::cerr << "level_gallery: COLUMNS must be a whole number from 1 to 20, got " << argv[3] << '\n';
        return 2;
    }
    const game::LevelIndexLoad index = game::loadLevelIndex(argv[1]);
    if (!index.levels) {
        std::cerr << index.errors.front().format() << '\n';
        return 2;
    }
    const auto& levels = *index.levels;
    const int thumbW = kFrame.width / kShrink, thumbH = kFrame.height / kShrink;
    const int rows = (static_cast<int>(levels.size()) + columns - 1) / columns;
    const int cellW = thumbW + kGap, cellH = thumbH + kCaption + kGap;
    try {
        const auto context = render::createOffscreenContext(kFrame);
        render::Renderer renderer(*context);
        render::DrawList list;
        render::Image sheet = render::Image::filled(columns * cellW + kGap, rows * cellH + kGap, kPaper, kPaper,
                                                    kPaper);
        // The captions are drawn on the sheet itself, through a camera whose world units are the sheet's pixels.
        render::DrawList captions;
        for (std::size_t i = 0; i < levels.size(); ++i) {
            const game::IndexedLevel& level = levels[i];
            std::cerr << "\rlevel_gallery: level " << i + 1 << " of " << levels.size() << "\033[K" << std::flush;
            const game::SceneLoad load = game::loadSceneFile(level.file);
            if (!load.ok()) {
                std::cerr << '\n' << load.errors.front().format() << '\n';
                return 2;
            }
            const game::LevelRun run(*load.scene, {});
            const game::LevelView view(load.scene->name,
                                       game::sceneCamera(game::frameScene(*load.scene, run.world()), kFrame), kFrame,
                                       {.labels = false, .zones = true});
            view.draw(run, 0, list);
            const render::Image frame = renderer.render(list, view.camera());
            const int left = kGap + static_cast<int>(i) % columns * cellW;
            const int top = kGap + static_cast<int>(i) / columns * cellH;
            paste(frame, sheet, left, top);
            char caption[96];
            std::snprintf(caption, sizeof caption, "%zu. %s (d%d)", i + 1, level.title.c_str(), level.difficulty);
            // A title too long for the thumbnail's width is cut short with "...".
            captions.text(left, top + thumbH + 5, game::wrapText(caption, thumbW, 2, 1).front(), {40, 40, 40, 255}, 2);
        }
        std::cerr << "\r\033[K" << std::flush;
        // The captions through a second context the sheet's size: text is the renderer's own.
        const render::FrameSize sheetSize{sheet.width, sheet.height};
        const auto sheetContext = render::createOffscreenContext(sheetSize);
        render::Renderer sheetRenderer(*sheetContext);
        captions.background = render::Color{kPaper, kPaper, kPaper, 255};
        render::Camera camera;
        camera.centre = {0.5f * static_cast<float>(sheet.width), 0.5f * static_cast<float>(sheet.height)};
        camera.viewHeight = static_cast<float>(sheet.height);
        const render::Image text = sheetRenderer.render(captions, camera);
        // Only the caption strips come from the text layer; the thumbnails stay as pasted.
        for (std::size_t i = 0; i < levels.size(); ++i) {
            const int left = kGap + static_cast<int>(i) % columns * cellW;
            const int top = kGap + static_cast<int>(i) / columns * cellH + thumbH;
            for (int y = top; y < top + kCaption; ++y)
                for (int x = left; x < left + thumbW; ++x)
                    for (int c = 0; c < 3; ++c) sheet.pixel(x, y)[c] = text.pixel(x, y)[c];
        }
        render::writePng(argv[2], sheet);
    } catch (const std::exception& e) {
        std::cerr << "\r\033[Klevel_gallery: " << e.what() << '\n';
        return 1;
    }
    std::cout << "wrote " << argv[2] << " (" << levels.size() << " levels, " << columns << " columns)\n";
    return 0;
}
