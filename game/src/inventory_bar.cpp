// The inventory bar: slots laid out left to right, drawn in world units through the window camera
// (the renderer draws nothing else), with text placed in pixels like the HUD.
#include "inventory_bar.hpp"

#include "rube/render/palette.hpp"

#include <string>

namespace rube::game {

namespace {

using render::Palette;
using render::Point;
using render::Style;

constexpr int kSlotWidth = 104;
constexpr int kSlotHeight = 64;
constexpr int kSlotGap = 8;
constexpr int kMargin = 8;
constexpr int kTextScale = 2;
constexpr int kModeLineY = kMargin + kSlotHeight + 6; // pixels below the bar's top edge
constexpr int kMessageLineY = kModeLineY + 16;

Point pt(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

Style look(const char* fill, const char* outline, float width = 1.5f) {
    const Palette& p = Palette::greybox();
    return {p[fill], p[outline], width};
}

} // namespace

InventoryBar::InventoryBar(render::Camera levelCamera, render::FrameSize levelFrame, std::vector<ItemKind> stock)
    : levelFrame_(levelFrame) {
    // Same pixels per metre and the same top edge as the level's camera: only the view grows downwards.
    const float ppm = levelCamera.pixelsPerMetre(levelFrame);
    const float top = levelCamera.centre.y + 0.5f * levelCamera.viewHeight;
    windowCamera_.viewHeight = static_cast<float>(levelFrame.height + kHeight) / ppm;
    windowCamera_.centre = {levelCamera.centre.x, top - 0.5f * windowCamera_.viewHeight};
    int left = kMargin;
    for (ItemKind kind : stock) {
        slots_.push_back({kind, left});
        left += kSlotWidth + kSlotGap;
    }
}

Point InventoryBar::worldOf(float x, float y) const {
    const render::FrameSize window = windowSize();
    return windowCamera_.toWorld({x, static_cast<float>(window.height) - y}, window);
}

Vec2 InventoryBar::toWorld(Point pixel) const {
    const Point p = worldOf(pixel.x, pixel.y);
    return {p.x, p.y};
}

Point InventoryBar::toPixel(Vec2 world) const {
    const render::FrameSize window = windowSize();
    const Point p = windowCamera_.toPixels(pt(world), window);
    return {p.x, static_cast<float>(window.height) - p.y};
}

std::optional<ItemKind> InventoryBar::slotAt(Point pixel) const {
    const float top = static_cast<float>(levelFrame_.height + kMargin);
    if (pixel.y < top || pixel.y > top + kSlotHeight) return std::nullopt;
    for (const Slot& slot : slots_)
        if (pixel.x >= static_cast<float>(slot.left) && pixel.x <= static_cast<float>(slot.left + kSlotWidth))
            return slot.kind;
    return std::nullopt;
}

std::optional<Point> InventoryBar::slotCentre(ItemKind kind) const {
    for (const Slot& slot : slots_)
        if (slot.kind == kind)
            return Point{static_cast<float>(slot.left) + 0.5f * kSlotWidth,
                         static_cast<float>(levelFrame_.height + kMargin) + 0.5f * kSlotHeight};
    return std::nullopt;
}

std::string InventoryBar::fitted(std::string_view text, int width, int scale) {
    std::string line(text);
    if (render::textWidth(line, scale) <= width) return line;
    while (!line.empty() && render::textWidth(line + "...", scale) > width) line.pop_back();
    return line + "...";
}

void InventoryBar::draw(render::DrawList& list, const std::function<int(ItemKind)>& remaining,
                        std::string_view modeLine, std::string_view message, render::Color messageColor,
                        std::string_view corner) const {
    const Palette& palette = Palette::greybox();
    const render::FrameSize window = windowSize();
    const float ppm = windowCamera_.pixelsPerMetre(window);
    // The bar's panel covers whatever of the level would spill below the level area.
    const Point low = worldOf(0.0f, static_cast<float>(window.height));
    const Point high = worldOf(static_cast<float>(window.width), static_cast<float>(levelFrame_.height));
    list.box({0.5f * (low.x + high.x), 0.5f * (low.y + high.y)}, {0.5f * (high.x - low.x), 0.5f * (high.y - low.y)},
             0.0f, look("box", "box_outline", 2.0f));
    const float top = static_cast<float>(levelFrame_.height + kMargin);
    for (const Slot& slot : slots_) {
        const int left = remaining(slot.kind);
        const Point a = worldOf(static_cast<float>(slot.left), top + kSlotHeight);
        const Point b = worldOf(static_cast<float>(slot.left + kSlotWidth), top);
        list.box({0.5f * (a.x + b.x), 0.5f * (a.y + b.y)}, {0.5f * (b.x - a.x), 0.5f * (b.y - a.y)}, 0.0f,
                 look(left > 0 ? "background" : "box", "box_outline"));
        const Point icon = worldOf(static_cast<float>(slot.left) + 0.5f * kSlotWidth, top + 24.0f);
        drawItemIcon(slot.kind, {icon.x, icon.y}, 36.0 / ppm, left > 0, list);
        const std::string label = std::string(itemKindName(slot.kind)) + " x" + std::to_string(left);
        list.text(slot.left + 6, static_cast<int>(top) + kSlotHeight - 14, label, palette["hud_text"], 1);
    }
    const int width = window.width - 2 * kMargin;
    list.text(kMargin, levelFrame_.height + kModeLineY, fitted(modeLine, width, kTextScale), palette["hud_text"],
              kTextScale);
    list.text(kMargin, levelFrame_.height + kMessageLineY, fitted(message, width, kTextScale), messageColor,
              kTextScale);
    if (!corner.empty()) {
        // Right of the slots when there is room, else in the margin above them.
        const int x = window.width - kMargin - render::textWidth(corner, 1);
        const int slotsEnd = slots_.empty() ? 0 : slots_.back().left + kSlotWidth;
        list.text(x, x > slotsEnd + kMargin ? static_cast<int>(top) + 4 : levelFrame_.height + 1, corner,
                  palette["hud_text"], 1);
    }
}

void drawItemIcon(ItemKind kind, Vec2 centre, double size, bool available, render::DrawList& list) {
    kind->drawIcon(centre, size, available, list);
}

} // namespace rube::game
