// The play session's input: what the mouse, the wheel and the keys do while editing and while
// running. The editing itself (drag, drop, turn, remove, aim) is in play_editing.cpp.
#include "play_session.hpp"

#include "play_internal.hpp"

#include <cmath>
#include <numbers>

namespace rube::game {

namespace {

using play::kAimStepsPerDegree;
using play::kTrailPoints;
using play::kTrailSeconds;
using play::normalDegrees;
using play::number;
using play::snap;
using render::Key;
using render::KeyAction;
using render::MouseButton;

constexpr double kTurnStep = 15.0; // degrees per wheel notch or [ ] press

// The levels' items the cursor aims by dragging or the wheel: cannons.
bool aimable(ItemKind kind) { return kind->plays(PartRole::fire); }

} // namespace

void PlaySession::cursorMoved(float x, float y) {
    cursor_ = {x, y};
    cursorWorld_ = bar_.toWorld(cursor_);
    if (drag_) updateDrag();
    if (aiming_ >= 0) aimAtCursor();
}

void PlaySession::mouseButton(MouseButton button, bool pressed) {
    if (run_) {
        if (button == MouseButton::left && pressed && !bar_.contains(cursor_)) useItemAtCursor();
        return;
    }
    if (button == MouseButton::right && pressed) {
        if (drag_) {
            if (drag_->liftedFrom) recordEdit(); // a placed item goes back to the bar: an edit
            say("put back: " + std::string(itemKindName(drag_->placement.kind)));
            drag_.reset();
            rebuildPreview();
        } else if (const int i = placedItemAtCursor(); i >= 0) {
            removeAt(static_cast<std::size_t>(i));
        }
        return;
    }
    if (button != MouseButton::left) return;
    if (!pressed) {
        if (drag_) drop();
        aiming_ = -1;
        return;
    }
    if (bar_.contains(cursor_)) {
        const auto kind = bar_.slotAt(cursor_);
        if (!kind) return;
        if (remaining(*kind) <= 0) {
            say("no " + std::string(itemKindName(*kind)) + " left: the level gives " +
                    std::to_string(level_.level.inventory.find(itemKindName(*kind))->second),
                "magnet");
            return;
        }
        Placement p;
        p.kind = *kind;
        drag_ = Drag{p, std::nullopt, p, std::nullopt};
        updateDrag();
        return;
    }
    if (const int cannon = levelItemAtCursor(aimable); cannon >= 0) {
        recordEdit();
        aiming_ = cannon;
        aimAtCursor();
        return;
    }
    if (const int i = placedItemAtCursor(); i >= 0) {
        const std::size_t index = static_cast<std::size_t>(i);
        drag_ = Drag{placements_[index], index, placements_[index], std::nullopt};
        placements_.erase(placements_.begin() + i);
        rebuildPreview();
        updateDrag();
    }
}

void PlaySession::scrolled(float notches) {
    const int clicks = static_cast<int>(std::lround(notches));
    if (clicks == 0 || run_) return;
    if (!drag_) {
        // Over a cannon, the wheel fine-tunes its aim.
        if (const int cannon = levelItemAtCursor(aimable); cannon >= 0) {
            const double now = preview_->states()[static_cast<std::size_t>(cannon)].aim * 180.0 / std::numbers::pi;
            Action a;
            a.kind = ActionKind::aim;
            a.item = level_.level.items[static_cast<std::size_t>(cannon)].name;
            a.angleDegrees = normalDegrees(snap(now, kAimStepsPerDegree) + clicks);
            a.angle = scriptRadians(a.angleDegrees);
            recordEdit();
            aims_[cannon] = a;
            takeAction(a, *preview_);
            say("aim " + a.item + ": " + number(a.angleDegrees) + " degrees");
            return;
        }
    }
    turn(clicks * kTurnStep);
}

void PlaySession::key(Key key, KeyAction action) {
    if (key == Key::control) control_ = action != KeyAction::release;
    if (action == KeyAction::release) return;
    // Turning repeats while the key is held; every other key acts once per press.
    if (key == Key::leftBracket || key == Key::rightBracket) {
        if (!run_) turn(key == Key::leftBracket ? kTurnStep : -kTurnStep);
        return;
    }
    if (action == KeyAction::repeat) return;
    switch (key) {
    case Key::z:
        if (control_) undo();
        break;
    case Key::y:
        if (control_) redo();
        break;
    case Key::g:
        grid_ = !grid_;
        say(grid_ ? "grid on: items snap to 5 cm" : "grid off: items snap to 1 mm");
        if (drag_) updateDrag();
        break;
    case Key::h: showHint(); break;
    case Key::w: watchSolution(); break;
    case Key::n:
        if (run_ && run_->goalStep()) next_ = true;
        else say("reach the goal first: then N goes to the next level", "magnet");
        break;
    case Key::space:
        if (!run_) start();
        break;
    case Key::r:
        if (run_) reset();
        break;
    case Key::p:
        if (run_) paused_ = !paused_;
        break;
    case Key::s: slow_ = !slow_; break;
    case Key::d: showTrails_ = !showTrails_; break;
    case Key::c:
        if (run_) trails_ = std::make_unique<Trails>(run_->world(), kTrailSeconds, kTrailPoints);
        break;
    case Key::deleteKey:
    case Key::backspace:
        if (run_) break;
        if (drag_) {
            if (drag_->liftedFrom) recordEdit();
            drag_.reset();
            rebuildPreview();
        } else if (const int i = placedItemAtCursor(); i >= 0) {
            removeAt(static_cast<std::size_t>(i));
        }
        break;
    case Key::escape:
        if (drag_) {
            // Escape while dragging cancels the drag: a lifted item goes back where it was.
            cancelDrag();
            rebuildPreview();
        } else {
            quit_ = true;
        }
        break;
    default: break;
    }
}

} // namespace rube::game
