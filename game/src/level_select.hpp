#pragma once
/// LevelSelect: the list `rube play` opens with when no level is given: the levels of
/// levels/index.toml in order, with their difficulty and which the player has solved. Chosen with
/// the arrows and Enter or a click; Escape leaves. Like PlaySession, it sees the window only as an
/// InputListener and a DrawList, so a test drives it with made-up events.

#include "level_index.hpp"
#include "progress.hpp"

#include "rube/render/camera.hpp"
#include "rube/render/draw_list.hpp"
#include "rube/render/window_input.hpp"

#include <optional>
#include <vector>

namespace rube::game {

class LevelSelect final : public render::InputListener {
public:
    /// The list of `levels`, marked solved as `progress` says, in a window of `window` pixels,
    /// with `selected` highlighted first.
    LevelSelect(std::vector<IndexedLevel> levels, const Progress& progress, render::FrameSize window,
                std::size_t selected = 0);

    void cursorMoved(float x, float y) override;
    void mouseButton(render::MouseButton button, bool pressed) override;
    void scrolled(float notches) override;
    void key(render::Key key, render::KeyAction action) override;

    /// Draws the list into `list`, in pixels (draw it through pixelCamera()).
    void draw(render::DrawList& list) const;
    /// A camera whose world units are the window's pixels, y up.
    render::Camera pixelCamera() const;

    /// The level chosen (Enter or a click), if any.
    std::optional<std::size_t> chosen() const { return chosen_; }
    /// The highlighted row.
    std::size_t selected() const { return selected_; }
    /// True once the player asked to quit (Escape).
    bool quitRequested() const { return quit_; }
    /// The centre of row `i` in pixels from the top-left, as the list is scrolled now.
    render::Point rowPixel(std::size_t i) const;
    /// How the row of level `i` reads: "3. Pins  **  solved".
    std::string rowText(std::size_t i) const;

private:
    int rowsShown() const;
    void select(std::size_t i);
    std::optional<std::size_t> rowAt(render::Point pixel) const;

    std::vector<IndexedLevel> levels_;
    std::vector<bool> solved_;
    render::FrameSize window_;
    std::size_t selected_ = 0;
    std::size_t first_ = 0; // the first row shown: the list scrolls to keep the selection in view
    render::Point cursor_;
    std::optional<std::size_t> chosen_;
    bool quit_ = false;
};

} // namespace rube::game
