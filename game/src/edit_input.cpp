// The editor's input: a click places the selected kind (Tab picks it) or picks up a part to move;
// Z draws zones; [ ] and the wheel turn; right-click or Delete removes; P marks a part as the
// player's; T makes the goal; Ctrl+Z, Ctrl+Y, Ctrl+S; Space tries the level, R or Esc comes back.
#include "edit_session.hpp"

#include "play_internal.hpp"
#include "toml_writer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace rube::game {

namespace {

using play::normalDegrees;
using play::snap;
using render::Key;
using render::KeyAction;
using render::MouseButton;

constexpr double kTurnStep = 15.0;     // degrees
constexpr double kSmallestZone = 0.1;  // m: a click without a drag makes no zone
constexpr double kSmallestView = 1.0;  // m: nor a view
constexpr double kZoomStep = 1.25;     // C's wider window, per notch of the wheel

Vec2 snapped(Vec2 v) { return {snap(v.x, kPlacementGridPerMetre), snap(v.y, kPlacementGridPerMetre)}; }

} // namespace

void EditSession::cursorMoved(float x, float y) {
    if (trying_) return trying_->cursorMoved(x, y);
    cursor_ = {x, y};
    cursorWorld_ = bar_.toWorld(cursor_);
    if (dragging_) moveDragged();
    if (resizing_) {
        // The corner follows the cursor; the opposite corner stays, and the box keeps min below max.
        Aabb& box = state_.level.level.zones[resizing_->first].box;
        const Vec2 to = snapped(cursorWorld_);
        const int corner = resizing_->second;
        (corner & 1 ? box.max.x : box.min.x) = to.x;
        (corner & 2 ? box.max.y : box.min.y) = to.y;
        if (box.min.x > box.max.x) {
            std::swap(box.min.x, box.max.x);
            resizing_->second ^= 1;
        }
        if (box.min.y > box.max.y) {
            std::swap(box.min.y, box.max.y);
            resizing_->second ^= 2;
        }
    }
}

std::optional<std::pair<std::size_t, int>> EditSession::zoneCornerAtCursor() const {
    const float ppm = bar_.windowCamera().pixelsPerMetre(bar_.windowSize());
    const double reach = 8.0 / ppm;
    const std::vector<Zone>& zones = state_.level.level.zones;
    for (std::size_t z = zones.size(); z-- > 0;)
        for (int corner = 0; corner < 4; ++corner) {
            const Vec2 at{corner & 1 ? zones[z].box.max.x : zones[z].box.min.x,
                          corner & 2 ? zones[z].box.max.y : zones[z].box.min.y};
            if (cursorWorld_.distance(at) <= reach) return std::pair{z, corner};
        }
    return std::nullopt;
}

void EditSession::changeSpare(int by) {
    const std::string kind(selectedKind()->name());
    if (!selectedKind()->placeable()) return say("a " + kind + " cannot be in the inventory", "magnet");
    const int now = state_.spare.count(kind) ? state_.spare.at(kind) : 0;
    if (now + by < 0) return say("no spare " + kind + " to take away", "magnet");
    edit();
    if (now + by == 0) state_.spare.erase(kind);
    else state_.spare[kind] = now + by;
    const auto stock = inventory();
    say("inventory: " + kind + " x" + std::to_string(stock.count(kind) ? stock.at(kind) : 0) + " (" +
        std::to_string(now + by) + " spare beyond the player's parts)");
}

void EditSession::moveDragged() {
    const Vec2 to = snapped(cursorWorld_ + dragOffset_);
    if (dragging_->what == Hit::What::item) state_.level.level.items[dragging_->index].position = to;
    else state_.players[dragging_->index].position = to;
}

void EditSession::mouseButton(MouseButton button, bool pressed) {
    if (trying_) return trying_->mouseButton(button, pressed);
    hintPicked_.reset();
    if (button == MouseButton::right && pressed) return removeAtCursor();
    if (button != MouseButton::left) return;
    if (!pressed) {
        if (zoneStart_) {
            const Vec2 end = snapped(cursorWorld_);
            const Aabb box{{std::min(zoneStart_->x, end.x), std::min(zoneStart_->y, end.y)},
                           {std::max(zoneStart_->x, end.x), std::max(zoneStart_->y, end.y)}};
            zoneStart_.reset();
            if (viewMode_) {
                if (box.max.x - box.min.x >= kSmallestView && box.max.y - box.min.y >= kSmallestView) setView(box);
                else say("a view is at least 1 m each way: drag a bigger one", "magnet");
            } else if (box.max.x - box.min.x >= kSmallestZone && box.max.y - box.min.y >= kSmallestZone) {
                edit();
                state_.level.level.zones.push_back({box, {}});
                say("zone " + formatPair(box.min.x, box.min.y) + " to " + formatPair(box.max.x, box.max.y));
            }
        }
        dragging_.reset();
        resizing_.reset();
        return;
    }
    if (bar_.contains(cursor_)) return;
    if (viewMode_) {
        zoneStart_ = snapped(cursorWorld_);
        return;
    }
    if (zoneMode_) {
        // On a zone's corner, a drag resizes the zone; elsewhere it draws a new one.
        if ((resizing_ = zoneCornerAtCursor())) edit();
        else zoneStart_ = snapped(cursorWorld_);
        return;
    }
    const Hit hit = hitAtCursor();
    edit();
    if (hit.what == Hit::What::item || hit.what == Hit::What::player) {
        const Vec2 at = hit.what == Hit::What::item ? state_.level.level.items[hit.index].position
                                                    : state_.players[hit.index].position;
        dragging_ = hit;
        dragOffset_ = at - cursorWorld_;
        return;
    }
    ItemDesc item = defaultItem(selectedKind(), snapped(cursorWorld_));
    item.name = nameFor(selectedKind());
    state_.level.level.items.push_back(item);
    dragging_ = Hit{Hit::What::item, state_.level.level.items.size() - 1};
    dragOffset_ = {};
    say("placed " + item.name + " at " + formatPair(item.position.x, item.position.y) +
        " (P: the player's, T: the goal)");
}

void EditSession::typed(char32_t codePoint) {
    if (trying_ || !field_) return;
    field_->text.typed(codePoint);
    say(field_->text.line());
}

void EditSession::scrolled(float notches) {
    if (trying_) return trying_->scrolled(notches);
    if (viewMode_) {
        // Away from the user zooms in, as maps do.
        const Vec2 centre = (wideView_.min + wideView_.max) * 0.5;
        const Vec2 half = (wideView_.max - wideView_.min) * (0.5 * std::pow(kZoomStep, -notches));
        wideView_ = {centre - half, centre + half};
        return refreshCamera();
    }
    if (const int clicks = static_cast<int>(std::lround(notches)); clicks != 0) turnAtCursor(clicks * kTurnStep);
}

void EditSession::turnAtCursor(double degrees) {
    const Hit hit = hitAtCursor();
    if (hit.what != Hit::What::item && hit.what != Hit::What::player) return;
    edit();
    if (hit.what == Hit::What::player) {
        Placement& p = state_.players[hit.index];
        p.angleDegrees = normalDegrees(p.angleDegrees + degrees);
        p.angle = scriptRadians(p.angleDegrees);
        return say(std::string(p.kind->name()) + " turned to " + play::number(p.angleDegrees) + " degrees");
    }
    ItemDesc& item = state_.level.level.items[hit.index];
    const double now = item.angleDegrees.value_or(item.angle * 180.0 / std::numbers::pi);
    item.angleDegrees = normalDegrees(play::snap(now, 2.0) + degrees);
    item.angle = *item.angleDegrees * std::numbers::pi / 180.0; // as the level reader converts
    say(item.name + " turned to " + play::number(*item.angleDegrees) + " degrees");
}

void EditSession::removeAtCursor() {
    const Hit hit = hitAtCursor();
    if (hit.what == Hit::What::none) return;
    edit();
    LevelDesc& level = state_.level.level;
    if (hit.what == Hit::What::player) {
        state_.players.erase(state_.players.begin() + static_cast<std::ptrdiff_t>(hit.index));
    } else if (hit.what == Hit::What::zone) {
        level.zones.erase(level.zones.begin() + static_cast<std::ptrdiff_t>(hit.index));
    } else {
        // The goal's own item taken away takes the goal (not an unnamed item's: "" is "any" to a goal).
        if (level.goal && !level.goal->item.empty() && level.goal->item == level.items[hit.index].name)
            level.goal.reset();
        level.items.erase(level.items.begin() + static_cast<std::ptrdiff_t>(hit.index));
        // Every target with none left is no goal (the reader refuses it).
        if (level.goal && level.goal->kind == GoalKind::allTargets &&
            std::none_of(level.items.begin(), level.items.end(),
                         [](const ItemDesc& item) { return item.kind->plays(PartRole::goalTarget); }))
            level.goal.reset();
    }
    say("removed");
}

void EditSession::markAtCursor() {
    const Hit hit = hitAtCursor();
    LevelDesc& level = state_.level.level;
    if (hit.what == Hit::What::player) {
        edit();
        ItemDesc item = partOf(hit); // its own keys too
        state_.players.erase(state_.players.begin() + static_cast<std::ptrdiff_t>(hit.index));
        item.name = nameFor(item.kind);
        level.items.push_back(item);
        return say(item.name + " is a fixed part again");
    }
    if (hit.what != Hit::What::item) return;
    const ItemDesc& item = level.items[hit.index];
    if (!item.kind->placeable())
        return say("a " + std::string(item.kind->name()) + " cannot be placed by the player", "magnet");
    edit();
    Placement p;
    p.kind = item.kind;
    p.position = item.position;
    p.angleDegrees = item.angleDegrees.value_or(0.0);
    p.angle = scriptRadians(p.angleDegrees);
    p.name = item.name;
    markOwnKeys(p, item); // the solution's [[place]] gives them, as a script may
    state_.players.push_back(p);
    if (level.goal && !level.goal->item.empty() && level.goal->item == item.name) level.goal.reset();
    level.items.erase(level.items.begin() + static_cast<std::ptrdiff_t>(hit.index));
    say(std::string(p.kind->name()) + " is the player's: it goes into the inventory and the solution");
}

// L on a switch: its `triggers` goes to the next item it may trigger (or named rope), in level order.
void EditSession::linkAtCursor() {
    const Hit hit = hitAtCursor();
    if (hit.what != Hit::What::item || !state_.level.level.items[hit.index].kind->plays(PartRole::toggle) ||
        !std::any_of(state_.level.level.items[hit.index].kind->keys().begin(),
                     state_.level.level.items[hit.index].kind->keys().end(),
                     [](const PartKey& key) { return key.key == "triggers"; }))
        return say("L: point at a switch", "magnet");
    std::vector<std::string> names;
    for (const ItemDesc& item : state_.level.level.items)
        if (item.kind->plays(PartRole::triggered) && !item.name.empty()) names.push_back(item.name);
    for (const std::string& rope : state_.level.ropeNames)
        if (!rope.empty()) names.push_back(rope);
    if (names.empty()) {
        // The kinds as their descriptors say, so a new kind a switch may name is listed too.
        std::string kinds;
        for (ItemKind kind : partKindsPlaying(PartRole::triggered)) kinds += std::string(kind->name()) + ", ";
        return say("L: nothing a switch can trigger yet (" + kinds + "or a named rope)", "magnet");
    }
    ItemDesc& item = state_.level.level.items[hit.index];
    const auto now = std::find_if(item.ownLines.begin(), item.ownLines.end(),
                                  [](const std::string& line) { return line.starts_with("triggers = "); });
    std::size_t next = 0;
    if (now != item.ownLines.end())
        for (std::size_t i = 0; i < names.size(); ++i)
            if (*now == "triggers = " + tomlQuoted(names[i])) next = (i + 1) % names.size();
    // As E would set it: read by the level reader before it counts.
    if (const std::string name = item.name; setKeys(hit, {{"triggers", tomlQuoted(names[next])}}))
        say(name + " triggers " + names[next]);
}

namespace {

// The text T gives a goal; a text typed with O is kept when T changes the goal.
std::string goalText(const Goal& goal) {
    switch (goal.kind) {
    case GoalKind::targetHit: return "hit the " + goal.item;
    case GoalKind::ballInBucket: return "get a ball into the " + goal.item;
    case GoalKind::allTargets: return "hit every target";
    case GoalKind::reachArea:
        return goal.item.empty() ? "get a ball into the area" : "get the " + goal.item + " into the area";
    }
    return "";
}

} // namespace

// T on a target: hit it; T again on the goal's own target: hit every target; again: that one.
// T on a bucket: a ball in it. T on a placement zone: its rectangle becomes the goal's area (reach-area,
// any ball, or the ball the goal named). With a reach-area goal, T on a ball, crate, domino or rocket:
// that one must reach the area; T on it again: any ball.
void EditSession::goalAtCursor() {
    const Hit hit = hitAtCursor();
    const std::optional<Goal>& now = state_.level.level.goal;
    const bool reaching = now && now->kind == GoalKind::reachArea;
    if (hit.what != Hit::What::item && hit.what != Hit::What::zone)
        return say(reaching ? "T: point at a target, a bucket, a zone or what must reach the area"
                            : "T: point at a target, a bucket or a zone",
                   "magnet");
    Goal goal;
    goal.timeLimit = now ? now->timeLimit : std::optional<double>(10.0);
    if (hit.what == Hit::What::zone) {
        goal.kind = GoalKind::reachArea;
        goal.item = reaching ? now->item : std::string();
        goal.area = state_.level.level.zones[hit.index].box;
    } else {
        const ItemDesc& item = state_.level.level.items[hit.index];
        goal.item = item.name;
        if (item.kind->plays(PartRole::goalTarget)) {
            goal.kind = GoalKind::targetHit;
            if (now && now->kind == GoalKind::targetHit && now->item == item.name) {
                goal.kind = GoalKind::allTargets;
                goal.item.clear();
            }
        } else if (item.kind->plays(PartRole::goalBucket)) {
            goal.kind = GoalKind::ballInBucket;
        } else if (reaching && item.kind->plays(PartRole::goalMover)) {
            goal.kind = GoalKind::reachArea;
            goal.area = now->area;
            if (now->item == item.name) goal.item.clear();
        } else {
            return say(
                "T: a " + std::string(item.kind->name()) + " cannot be a goal" +
                    (item.kind->plays(PartRole::goalMover) ? " (T on a zone first: the area it must reach)" : ""),
                "magnet");
        }
    }
    goal.text = now && now->text != goalText(*now) ? now->text : goalText(goal);
    edit();
    // The zone is the goal's area now, not a place for the player's parts.
    if (hit.what == Hit::What::zone)
        state_.level.level.zones.erase(state_.level.level.zones.begin() + static_cast<std::ptrdiff_t>(hit.index));
    state_.level.level.goal = goal;
    sayGoal();
}

void EditSession::sayGoal() {
    const Goal& goal = *state_.level.level.goal;
    std::string limit = goal.timeLimit ? " within " + play::number(*goal.timeLimit) + " s" : std::string();
    say("goal " + std::string(conditionName(goal.kind)) + ": " + goal.text + limit);
}

void EditSession::key(Key key, KeyAction action) {
    if (key == Key::control) control_ = action != KeyAction::release;
    if (trying_) {
        if ((key == Key::r || key == Key::escape) && action == KeyAction::press) {
            trying_.reset();
            return say("back to editing");
        }
        return trying_->key(key, action);
    }
    if (action == KeyAction::release) return;
    if (field_) return fieldKey(key, action);
    // J's pick lasts one key: Enter changes that hint, Delete removes it, J picks the next.
    const std::optional<std::size_t> hint = std::exchange(hintPicked_, std::nullopt);
    if (hint && action == KeyAction::press) {
        if (key == Key::enter) return changeHint(*hint);
        if (key == Key::deleteKey || key == Key::backspace) return removeHint(*hint);
        if (key == Key::j) return pickHint(*hint + 1);
    }
    if (key == Key::leftBracket || key == Key::rightBracket)
        return turnAtCursor(key == Key::leftBracket ? kTurnStep : -kTurnStep);
    if (action == KeyAction::repeat) return;
    switch (key) {
    case Key::tab:
        selected_ = (selected_ + 1) % allPartKinds().size();
        say("click to place a " + std::string(selectedKind()->name()) + "; Tab picks another kind");
        break;
    case Key::z:
        if (control_ && history_.undo(state_)) {
            refreshCamera();
            say("undone");
        } else if (!control_) {
            if (std::exchange(viewMode_, false)) refreshCamera();
            zoneMode_ = !zoneMode_;
            say(zoneMode_ ? "zones: drag to draw a placement zone, Z again to place parts" : "placing parts");
        }
        break;
    case Key::y:
        if (control_ && history_.redo(state_)) {
            refreshCamera();
            say("redone");
        }
        break;
    case Key::s:
        if (control_) save();
        break;
    case Key::up:
    case Key::down:
        if (!state_.level.level.goal) {
            say("T sets a goal first; then Up and Down set its time limit", "magnet");
            break;
        }
        edit();
        {
            Goal& goal = *state_.level.level.goal;
            goal.timeLimit = std::max(1.0, std::round(goal.timeLimit.value_or(10.0)) + (key == Key::up ? 1.0 : -1.0));
            sayGoal();
        }
        break;
    case Key::v: fitView(); break;
    case Key::c: toggleViewMode(); break;
    case Key::l: linkAtCursor(); break;
    case Key::h: addHint(); break;
    case Key::j: pickHint(0); break;
    case Key::i: changeSpare(1); break;
    case Key::k: changeSpare(-1); break;
    case Key::p: markAtCursor(); break;
    case Key::t: goalAtCursor(); break;
    case Key::o: typeGoalText(); break;
    case Key::e: editKeysAtCursor(); break;
    case Key::deleteKey:
    case Key::backspace: removeAtCursor(); break;
    case Key::space: tryIt(); break;
    case Key::escape: quit_ = true; break;
    default: break;
    }
}

} // namespace rube::game
