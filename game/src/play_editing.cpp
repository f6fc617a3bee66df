// The play session's editing: the inventory stock, dragging an item from the bar or the level and
// dropping it, turning and removing placed items, aiming cannons, and which item the cursor is on.
// Every placement is checked with the same checkPlacements() a script's placements pass.
#include "play_session.hpp"

#include "play_internal.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rube::game {

namespace {

using play::kAimStepsPerDegree;
using play::normalDegrees;
using play::number;
using play::snap;

constexpr double kFinePerMetre = 1000.0; // with the grid (placement.hpp) off (G): 1 mm, still short in a script
constexpr float kPickPixels = 6.0f;    // how near the cursor must be to an item to pick it

double pointSegmentDistance(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 ab = b - a;
    const double l2 = ab.lengthSquared();
    const double t = l2 > 0.0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    return p.distance(a + ab * t);
}

} // namespace

int PlaySession::remaining(ItemKind kind) const {
    const auto stock = level_.level.inventory.find(itemKindName(kind));
    int left = stock == level_.level.inventory.end() ? 0 : stock->second;
    left -= static_cast<int>(
        std::count_if(placements_.begin(), placements_.end(), [&](const Placement& p) { return p.kind == kind; }));
    if (drag_ && drag_->placement.kind == kind) --left;
    return left;
}

void PlaySession::updateDrag() {
    Placement& p = drag_->placement;
    const double perMetre = grid_ ? kPlacementGridPerMetre : kFinePerMetre;
    p.position = {snap(cursorWorld_.x, perMetre), snap(cursorWorld_.y, perMetre)};
    drag_->refusal.reset();
    if (bar_.contains(cursor_)) {
        say("release on the bar to put the " + std::string(itemKindName(p.kind)) + " back");
        return;
    }
    std::vector<Placement> candidate = placements_;
    candidate.push_back(p);
    drag_->refusal = checkPlacements(level_, candidate);
    if (drag_->refusal) say(drag_->refusal->brief, "magnet");
    else
        say(std::string(itemKindName(p.kind)) + " at " + formatPair(p.position.x, p.position.y) + ": release to place");
}

void PlaySession::drop() {
    const Edits before = edits();
    Drag drag = std::move(*drag_);
    drag_.reset();
    const std::string kind(itemKindName(drag.placement.kind));
    if (bar_.contains(cursor_)) {
        if (drag.liftedFrom) history_.record(before); // a placed item back to the bar: an edit
        say("put back: " + kind);
    } else if (drag.refusal) {
        // A refused move puts the item back where it was; a refused new item goes back to the bar.
        if (drag.liftedFrom)
            placements_.insert(placements_.begin() + static_cast<std::ptrdiff_t>(*drag.liftedFrom), drag.original);
        say("not placed: " + drag.refusal->brief, "magnet");
    } else {
        history_.record(before);
        const auto at = drag.liftedFrom ? placements_.begin() + static_cast<std::ptrdiff_t>(*drag.liftedFrom)
                                        : placements_.end();
        placements_.insert(at, drag.placement);
        say("placed " + kind + " at " + formatPair(drag.placement.position.x, drag.placement.position.y));
    }
    rebuildPreview();
}

void PlaySession::turn(double degrees) {
    Placement* p = drag_ ? &drag_->placement : nullptr;
    const int hovered = p ? -1 : placedItemAtCursor();
    if (!p && hovered >= 0) p = &placements_[static_cast<std::size_t>(hovered)];
    if (!p) return;
    if (!p->kind->turns()) {
        say("a " + std::string(itemKindName(p->kind)) + " has no angle to turn", "magnet");
        return;
    }
    const Placement before = *p;
    const Edits edited = edits();
    p->angleDegrees = normalDegrees(p->angleDegrees + degrees);
    p->angle = scriptRadians(p->angleDegrees);
    if (drag_) {
        updateDrag();
        return;
    }
    // A placed item turns only where it still fits.
    if (const auto refusal = checkPlacements(level_, placements_)) {
        *p = before;
        say("cannot turn: " + refusal->brief, "magnet");
        return;
    }
    history_.record(edited);
    rebuildPreview();
    say(std::string(itemKindName(p->kind)) + " turned to " + number(p->angleDegrees) + " degrees");
}

void PlaySession::removeAt(std::size_t index) {
    recordEdit();
    say("removed " + std::string(itemKindName(placements_[index].kind)) + "; it is back in the bar");
    placements_.erase(placements_.begin() + static_cast<std::ptrdiff_t>(index));
    rebuildPreview();
}

void PlaySession::aimAtCursor() {
    const ItemDesc& cannon = level_.level.items[static_cast<std::size_t>(aiming_)];
    const Vec2 d = cursorWorld_ - cannon.position;
    if (d.lengthSquared() < 1e-12) return;
    Action a;
    a.kind = ActionKind::aim;
    a.item = cannon.name;
    a.angleDegrees = normalDegrees(snap(std::atan2(d.y, d.x) * 180.0 / std::numbers::pi, kAimStepsPerDegree));
    a.angle = scriptRadians(a.angleDegrees);
    aims_[aiming_] = a;
    takeAction(a, *preview_);
    say("aim " + cannon.name + ": " + number(a.angleDegrees) + " degrees (the arc shows where it goes)");
}

int PlaySession::placedItemAtCursor() const {
    const float ppm = bar_.windowCamera().pixelsPerMetre(bar_.windowSize());
    const double tolerance = kPickPixels / ppm;
    // The last placed is drawn on top, so it is picked first.
    for (std::size_t i = placements_.size(); i-- > 0;) {
        const ItemBodies bodies = itemBodies(placedItem(placements_[i]));
        for (const CircleDef& c : bodies.circles)
            if (cursorWorld_.distance(c.position) <= c.radius + tolerance) return static_cast<int>(i);
        for (const SegmentDef& s : bodies.segments)
            if (pointSegmentDistance(cursorWorld_, s.a, s.b) <= s.radius + tolerance) return static_cast<int>(i);
    }
    return -1;
}

int PlaySession::levelItemAtCursor(bool (*fits)(ItemKind)) const {
    const LevelRun& run = run_ ? *run_ : *preview_;
    const float ppm = bar_.windowCamera().pixelsPerMetre(bar_.windowSize());
    const double tolerance = kPickPixels / ppm;
    for (std::size_t i = 0; i < level_.level.items.size(); ++i) {
        const ItemDesc& item = level_.level.items[i];
        if (fits(item.kind) && item.kind->picked(item, run.itemPosition(static_cast<int>(i)), cursorWorld_, tolerance))
            return static_cast<int>(i);
    }
    return -1;
}

// ---------------------------------------------------------------------------------------------
// Undo and redo

PlaySession::Edits PlaySession::edits() const {
    Edits now{placements_, aims_, scripted_};
    if (drag_ && drag_->liftedFrom)
        now.placements.insert(now.placements.begin() + static_cast<std::ptrdiff_t>(*drag_->liftedFrom),
                              drag_->original);
    return now;
}

void PlaySession::recordEdit() { history_.record(edits()); }

void PlaySession::restore(Edits edits) {
    placements_ = std::move(edits.placements);
    aims_ = std::move(edits.aims);
    scripted_ = std::move(edits.scripted);
    rebuildPreview();
}

void PlaySession::cancelDrag() {
    if (!drag_) return;
    if (drag_->liftedFrom)
        placements_.insert(placements_.begin() + static_cast<std::ptrdiff_t>(*drag_->liftedFrom), drag_->original);
    drag_.reset();
}

bool PlaySession::undo() { return travel(true); }

bool PlaySession::redo() { return travel(false); }

bool PlaySession::travel(bool back) {
    if (run_) return false; // the machine runs what was placed; R first
    cancelDrag();
    aiming_ = -1;
    Edits now = edits();
    if (!(back ? history_.undo(now) : history_.redo(now))) {
        say(back ? "nothing to undo" : "nothing to redo");
        return false;
    }
    restore(std::move(now));
    say(back ? "undone (" + std::to_string(history_.undoable()) + " more to undo, Ctrl+Y redoes)"
             : "redone (" + std::to_string(history_.redoable()) + " more to redo)");
    return true;
}

} // namespace rube::game
