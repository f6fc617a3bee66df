// `rube items --sheet DIR`: each kind's default item, alone in a small level, drawn by the kind's
// own draw() over the world's boards and boxes (as LevelView draws a level) with its inventory icon
// (drawIcon) in a corner and its name on top, through the offscreen renderer; the PNGs go through
// the FrameWriter `rube run --out` uses, so each file appears whole or not at all.
#include "items_command.hpp"

#include "level_run.hpp"
#include "scene_view.hpp"
#include "part_catalogue.hpp"

#include "rube/render/draw_list.hpp"
#include "rube/render/frame_writer.hpp"
#include "rube/render/palette.hpp"
#include "rube/render/render_context.hpp"
#include "rube/render/renderer.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace rube::game {

namespace {

constexpr float kMarginMetres = 0.5f; // room around the extent: some kinds draw a little past it (a fan's housing)
constexpr double kMinWidth = 1.6;     // m: a peg is not blown up to fill the picture
constexpr double kMinHeight = 1.2;    // m
constexpr int kLabelMargin = 8;       // pixels
constexpr int kLabelScale = 2;
constexpr float kIconPixels = 36.0f; // the inventory icon's size, pixels

render::Point pt(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

// The part's extent and its air column if it blows (the air is what a fan is for), grown to at
// least kMinWidth x kMinHeight about its centre.
render::Rect framing(ItemKind kind) {
    const ItemDesc item = kind->make({0.0, 0.0});
    Aabb box = kind->extent(item);
    if (const auto wind = kind->bodies(item).wind) {
        const Vec2 across = Vec2{-wind->direction.y, wind->direction.x} * (0.5 * wind->width);
        const Vec2 end = wind->origin + wind->direction * wind->length;
        for (const Vec2 p : {end + across, end - across}) {
            box.min = {std::min(box.min.x, p.x), std::min(box.min.y, p.y)};
            box.max = {std::max(box.max.x, p.x), std::max(box.max.y, p.y)};
        }
    }
    const Vec2 centre = (box.min + box.max) * 0.5;
    const double halfW = 0.5 * std::max(box.max.x - box.min.x, kMinWidth);
    const double halfH = 0.5 * std::max(box.max.y - box.min.y, kMinHeight);
    return {pt(centre - Vec2{halfW, halfH}), pt(centre + Vec2{halfW, halfH})};
}

// One kind's picture: its default item in a level of its own, at step 0.
void drawKind(ItemKind kind, const render::Camera& camera, render::FrameSize size, render::DrawList& list) {
    SceneDesc scene;
    scene.name = std::string(kind->name());
    ItemDesc item = kind->make({0.0, 0.0});
    item.name = scene.name; // goals and switches name items; a picture shows one that could be named
    scene.level.items.push_back(std::move(item));
    const LevelRun run(scene, {});
    const render::Palette& palette = render::Palette::greybox();
    list.clear();
    list.background = palette["background"];
    // Boards, walls and housings are the world's segments, drawn as LevelView draws them.
    for (const Segment& s : run.world().segments())
        list.capsule(pt(s.a), pt(s.b), static_cast<float>(s.radius),
                     {palette["ground"], palette["ground_outline"], 1.5f});
    drawConveyors(run.world(), list);   // a running belt's chevrons, as in a level
    drawRigidBodies(run.world(), list); // crates and dominoes: boxes, drawn as in a level
    kind->draw({run, 0, list});
    const float ppm = camera.pixelsPerMetre(size);
    const render::Point corner = camera.toWorld(
        {static_cast<float>(size.width) - kIconPixels, static_cast<float>(size.height) - kIconPixels}, size);
    kind->drawIcon({corner.x, corner.y}, kIconPixels / ppm, true, list);
    list.text(kLabelMargin, kLabelMargin, scene.name, palette["hud_text"], kLabelScale);
    // A 1 m bar in the bottom left corner: each picture is framed to its part, so this gives the scale.
    const render::Point left = camera.toWorld({static_cast<float>(kLabelMargin), static_cast<float>(kLabelMargin)},
                                              size);
    list.capsule(left, {left.x + 1.0f, left.y}, 1.5f / ppm, {palette["hud_text"], render::Color::transparent(), 0.0f});
    list.text(kLabelMargin, size.height - kLabelMargin - 7 * kLabelScale - 8, "1 m", palette["hud_text"], kLabelScale);
}

ExitCode writeSheet(const ItemsOptions& options, std::ostream& out, std::ostream& err) {
    const std::filesystem::path folder(options.sheet);
    // The writer would create the folder too; doing it here gives the plain reason ("Not a directory").
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error) {
        err << "rube items: cannot write pictures to " << options.sheet << ": " << error.message() << '\n';
        return ExitCode::badInput;
    }
    std::unique_ptr<render::FrameWriter> writer;
    try {
        writer = std::make_unique<render::FrameWriter>(folder);
    } catch (const std::exception& e) {
        err << "rube items: cannot write pictures to " << options.sheet << ": " << e.what() << '\n';
        return ExitCode::badInput;
    }
    const auto kinds = allPartKinds();
    try {
        const auto context = render::createOffscreenContext(options.size);
        render::Renderer renderer(*context);
        render::DrawList list;
        for (std::size_t i = 0; i < kinds.size(); ++i) {
            if (options.progress)
                err << "\rrube items: picture " << i + 1 << " of " << kinds.size() << " (" << kinds[i]->name()
                    << ")\033[K" << std::flush;
            const render::Camera camera = render::Camera::fitting(framing(kinds[i]), options.size, kMarginMetres);
            drawKind(kinds[i], camera, options.size, list);
            renderer.draw(list, camera);
            render::Image picture = writer->spareImage();
            renderer.readPixels(picture);
            writer->write(std::move(picture), partPictureName(kinds[i]));
        }
        writer->finish();
    } catch (const std::exception& e) {
        if (options.progress) err << "\r\033[K";
        err << "rube items: cannot render the sheet: " << e.what() << '\n';
        return ExitCode::failed;
    }
    if (options.progress) err << "\r\033[K" << std::flush;
    out << "rube items: " << kinds.size() << " pictures, " << options.size.width << "x" << options.size.height
        << ", in " << options.sheet << '\n';
    return ExitCode::ok;
}

} // namespace

ExitCode listItems(const ItemsOptions& options, std::ostream& out, std::ostream& err) {
    if (options.sheet.empty()) {
        out << partCatalogueText();
        return ExitCode::ok;
    }
    return writeSheet(options, out, err);
}

} // namespace rube::game
