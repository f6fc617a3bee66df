// The play session's picture: the level as `rube run` draws it, the zones, the dragged or hovered
// item's outline while editing, and the inventory bar with its mode and message lines.
#include "play_session.hpp"

#include "rube/render/palette.hpp"

namespace rube::game {

namespace {

using render::Palette;
using render::Point;

render::Point pt(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

} // namespace

void PlaySession::drawEditing(render::DrawList& list) const {
    const Palette& palette = Palette::greybox();
    drawZones(level_.level, list);
    const auto outlineBodies = [&](const Placement& p, render::Style look) {
        const ItemBodies bodies = itemBodies(placedItem(p));
        for (const CircleDef& c : bodies.circles) list.circle(pt(c.position), static_cast<float>(c.radius), look);
        for (const SegmentDef& s : bodies.segments) list.capsule(pt(s.a), pt(s.b), static_cast<float>(s.radius), look);
    };
    if (!drag_) {
        if (const int i = placedItemAtCursor(); i >= 0)
            outlineBodies(placements_[static_cast<std::size_t>(i)],
                          {render::Color::transparent(), palette["highlight"], 3.0f});
        return;
    }
    if (bar_.contains(cursor_)) return;
    const char* colour = drag_->refusal ? "magnet" : "highlight";
    outlineBodies(drag_->placement, {palette[colour].withAlpha(0x90), palette[colour], 3.0f});
}

void PlaySession::draw(render::DrawList& list) const {
    const Palette& palette = Palette::greybox();
    std::string modeLine;
    if (run_) {
        view_.draw(*run_, run_->steps(), list);
        if (showTrails_) trails_->draw(list, palette["trail"], 2.0f);
        modeLine = "RUN step " + std::to_string(run_->steps()) + (paused_ ? " PAUSED" : "") + (slow_ ? " SLOW" : "") +
                   "  P pause S slow D trails C clear R edit Esc quit";
    } else {
        view_.draw(*preview_, 0, list);
        drawEditing(list);
        modeLine = "EDIT  drag items in, [ ] turns, right-click removes, drag a cannon to aim, Space runs";
    }
    bar_.draw(
        list, [this](ItemKind kind) { return remaining(kind); }, modeLine, message_, messageColor_);
}

} // namespace rube::game
