#pragma once
/// InventoryBar: the strip under the level in the play window, with one slot per kind of item the
/// level gives (its icon and how many are left) and two lines of text, the mode and a message. It
/// also owns the window's geometry: the level area on top is exactly a `rube run` frame.

#include "level.hpp"

#include "rube/render/camera.hpp"
#include "rube/render/draw_list.hpp"

#include <functional>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace rube::game {

class InventoryBar {
public:
    /// The bar under a level area of `levelFrame` pixels shown through `levelCamera`, with a slot
    /// for each kind of `stock` in order.
    InventoryBar(render::Camera levelCamera, render::FrameSize levelFrame, std::vector<ItemKind> stock);

    /// The level area's size (the top of the window).
    render::FrameSize levelFrame() const { return levelFrame_; }
    /// The whole window: the level area and the bar.
    render::FrameSize windowSize() const { return {levelFrame_.width, levelFrame_.height + kHeight}; }
    /// The camera for the whole window: the level camera's scale and top edge, so the level area
    /// shows exactly what a `rube run` frame shows, pixel for pixel, and the bar hangs below it.
    const render::Camera& windowCamera() const { return windowCamera_; }

    /// True when a pixel (from the top-left) lies in the bar rather than the level.
    bool contains(render::Point pixel) const { return pixel.y >= static_cast<float>(levelFrame_.height); }
    /// The kind whose slot is under a pixel, if any.
    std::optional<ItemKind> slotAt(render::Point pixel) const;
    /// The centre of a kind's slot in pixels from the top-left, if the bar has one.
    std::optional<render::Point> slotCentre(ItemKind kind) const;
    /// The world point under a pixel given from the top-left.
    Vec2 toWorld(render::Point pixel) const;
    /// The pixel (from the top-left) a world point lands on.
    render::Point toPixel(Vec2 world) const;

    /// Draws the bar over the bottom of the window: the slots with `remaining(kind)` each (empty
    /// ones greyed), `modeLine`, and `message` in `messageColor`.
    /// `corner` (the cursor's coordinates) goes to the top right. A line too long for the window is
    /// cut short with "...".
    void draw(render::DrawList& list, const std::function<int(ItemKind)>& remaining, std::string_view modeLine,
              std::string_view message, render::Color messageColor, std::string_view corner = {}) const;

    /// `text` as drawn at `scale` in a line `width` pixels wide: whole, or cut short with "...".
    static std::string fitted(std::string_view text, int width, int scale);

    /// The bar's height in pixels.
    static constexpr int kHeight = 112;

private:
    struct Slot {
        ItemKind kind;
        int left = 0; // pixels from the window's left edge
    };
    render::Point worldOf(float x, float y) const;

    render::FrameSize levelFrame_;
    render::Camera windowCamera_;
    std::vector<Slot> slots_;
};

/// Draws a small picture of an item of `kind` centred on `centre`, about `size` metres across:
/// the bar's icons, in the look LevelView gives the item in the level.
void drawItemIcon(ItemKind kind, Vec2 centre, double size, bool available, render::DrawList& list);

} // namespace rube::game
