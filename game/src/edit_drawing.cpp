// The editor's picture: the level as the play window draws it (the player's parts placed), the
// zones, the player's parts outlined, the zone (or view) being drawn, the view while C draws one,
// and the bar's lines.
#include "edit_session.hpp"

#include "rube/render/palette.hpp"

#include <cstdio>

namespace rube::game {

namespace {

render::Point pt(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

void zoneBox(const Aabb& box, render::Style look, render::DrawList& list) {
    list.box(pt((box.min + box.max) * 0.5), pt((box.max - box.min) * 0.5), 0.0f, look);
}

} // namespace

void EditSession::draw(render::DrawList& list) const {
    if (trying_) return trying_->draw(list);
    const render::Palette& palette = render::Palette::greybox();
    const LevelRun preview(state_.level, state_.players);
    view_.draw(preview, 0, list);
    for (const Zone& zone : state_.level.level.zones)
        zoneBox(zone.box, {palette["goal"].withAlpha(0x30), palette["goal"], 1.5f}, list);
    if (viewMode_ && state_.level.view)
        zoneBox(*state_.level.view, {render::Color::transparent(), palette["hud_text"], 2.0f}, list);
    if (zoneStart_) {
        const Vec2 end = cursorWorld_;
        zoneBox({{std::min(zoneStart_->x, end.x), std::min(zoneStart_->y, end.y)},
                 {std::max(zoneStart_->x, end.x), std::max(zoneStart_->y, end.y)}},
                {palette["highlight"].withAlpha(0x30), palette["highlight"], 2.0f}, list);
    }
    for (const Placement& p : state_.players) {
        const ItemBodies bodies = itemBodies(placedItem(p));
        const render::Style look{render::Color::transparent(), palette["highlight"], 3.0f};
        for (const CircleDef& c : bodies.circles) list.circle(pt(c.position), static_cast<float>(c.radius), look);
        for (const SegmentDef& s : bodies.segments) list.capsule(pt(s.a), pt(s.b), static_cast<float>(s.radius), look);
    }
    std::string mode = "EDIT ";
    mode += viewMode_ ? std::string_view("view") : zoneMode_ ? std::string_view("zones") : selectedKind()->name();
    mode += "  Tab kind Z zones P player's T goal Space try Ctrl+S save Ctrl+Z undo Esc quit";
    char corner[64];
    std::snprintf(corner, sizeof corner, "x %.2f  y %.2f", cursorWorld_.x + 0.0, cursorWorld_.y + 0.0);
    bar_.draw(
        list, [](ItemKind) { return 0; }, mode, message_, messageColor_, corner);
}

} // namespace rube::game
