// The level list: a heading, then one row per level, the selected one on a highlight. Rows are
// laid out in pixels from the top, drawn through a camera whose unit is one pixel.
#include "level_select.hpp"

#include "rube/render/palette.hpp"

#include <algorithm>
#include <cmath>

namespace rube::game {

namespace {

using render::Key;
using render::KeyAction;
using render::MouseButton;
using render::Palette;

constexpr int kMargin = 16;
constexpr int kHeadingHeight = 64; // pixels above the first row: the title and the keys
constexpr int kRowHeight = 28;
constexpr int kTextScale = 2;

} // namespace

LevelSelect::LevelSelect(std::vector<IndexedLevel> levels, const Progress& progress, render::FrameSize window,
                         std::size_t selected)
    : levels_(std::move(levels)), window_(window) {
    for (const IndexedLevel& level : levels_) solved_.push_back(progress.solved(levelKey(level.file)));
    select(std::min(selected, levels_.empty() ? std::size_t{0} : levels_.size() - 1));
}

int LevelSelect::rowsShown() const { return std::max(1, (window_.height - kHeadingHeight - kMargin) / kRowHeight); }

void LevelSelect::select(std::size_t i) {
    selected_ = i;
    const auto shown = static_cast<std::size_t>(rowsShown());
    if (selected_ < first_) first_ = selected_;
    if (selected_ >= first_ + shown) first_ = selected_ + 1 - shown;
}

render::Point LevelSelect::rowPixel(std::size_t i) const {
    const float top = static_cast<float>(kHeadingHeight +
                                         (static_cast<int>(i) - static_cast<int>(first_)) * kRowHeight);
    return {0.5f * static_cast<float>(window_.width), top + 0.5f * kRowHeight};
}

std::optional<std::size_t> LevelSelect::rowAt(render::Point pixel) const {
    if (pixel.y < static_cast<float>(kHeadingHeight)) return std::nullopt;
    const auto row = static_cast<std::size_t>((pixel.y - static_cast<float>(kHeadingHeight)) / kRowHeight);
    if (row >= static_cast<std::size_t>(rowsShown()) || first_ + row >= levels_.size()) return std::nullopt;
    return first_ + row;
}

std::string LevelSelect::rowText(std::size_t i) const {
    const IndexedLevel& level = levels_[i];
    return std::to_string(i + 1) + ". " + level.title + "  " +
           std::string(static_cast<std::size_t>(level.difficulty), '*') + (solved_[i] ? "  solved" : "");
}

void LevelSelect::cursorMoved(float x, float y) {
    cursor_ = {x, y};
    if (const auto row = rowAt(cursor_)) select(*row);
}

void LevelSelect::mouseButton(MouseButton button, bool pressed) {
    if (button != MouseButton::left || !pressed) return;
    if (const auto row = rowAt(cursor_)) chosen_ = *row;
}

void LevelSelect::scrolled(float notches) {
    const long step = -std::lround(notches);
    if (levels_.empty() || step == 0) return;
    const long to = std::clamp(static_cast<long>(selected_) + step, 0L, static_cast<long>(levels_.size()) - 1);
    select(static_cast<std::size_t>(to));
}

void LevelSelect::key(Key key, KeyAction action) {
    if (action == KeyAction::release || levels_.empty()) {
        if (key == Key::escape && action == KeyAction::press) quit_ = true;
        return;
    }
    switch (key) {
    case Key::up:
        if (selected_ > 0) select(selected_ - 1);
        break;
    case Key::down:
        if (selected_ + 1 < levels_.size()) select(selected_ + 1);
        break;
    case Key::enter:
    case Key::space:
        if (action == KeyAction::press) chosen_ = selected_;
        break;
    case Key::escape:
        if (action == KeyAction::press) quit_ = true;
        break;
    default: break;
    }
}

render::Camera LevelSelect::pixelCamera() const {
    render::Camera camera;
    camera.viewHeight = static_cast<float>(window_.height);
    camera.centre = {0.5f * static_cast<float>(window_.width), 0.5f * static_cast<float>(window_.height)};
    return camera;
}

void LevelSelect::draw(render::DrawList& list) const {
    const Palette& palette = Palette::greybox();
    list.clear();
    list.background = palette["background"];
    const std::size_t solvedCount = static_cast<std::size_t>(std::count(solved_.begin(), solved_.end(), true));
    list.text(kMargin, kMargin,
              "rube: choose a level (" + std::to_string(solvedCount) + " of " + std::to_string(levels_.size()) +
                  " solved)",
              palette["hud_text"], kTextScale);
    list.text(kMargin, kMargin + 22, "Up/Down or the mouse picks, Enter or a click plays, Esc quits",
              palette["hud_text"], 1);
    const auto shown = static_cast<std::size_t>(rowsShown());
    const float height = static_cast<float>(window_.height);
    for (std::size_t i = first_; i < levels_.size() && i < first_ + shown; ++i) {
        const render::Point centre = rowPixel(i);
        if (i == selected_)
            list.box({centre.x, height - centre.y},
                     {0.5f * static_cast<float>(window_.width - 2 * kMargin), 0.5f * kRowHeight - 2.0f}, 0.0f,
                     {palette["highlight"].withAlpha(0x60), palette["highlight"], 2.0f});
        list.text(kMargin + 8, static_cast<int>(centre.y) - 7, rowText(i),
                  solved_[i] ? palette["goal"] : palette["hud_text"], kTextScale);
    }
}

} // namespace rube::game
