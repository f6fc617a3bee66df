// The play session: the editing rules (drag from the bar, turn, move, remove, aim) checked with
// the same checkPlacements() a script's placements pass, and the run driven through the same
// LevelRun and takeAction() that `rube run` uses, so what the player did replays to the same frames.
#include "play_session.hpp"

#include "scene_framing.hpp"

#include "rube/render/palette.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rube::game {

namespace {

using render::Key;
using render::KeyAction;
using render::MouseButton;
using render::Palette;
using render::Point;

constexpr double kGridPerMetre = 20.0;  // placements snap to 5 cm, so scripts read as round numbers
constexpr double kTurnStep = 15.0;      // degrees per wheel notch or [ ] press
constexpr double kAimStepsPerDegree = 2.0; // aims by mouse snap to half degrees
constexpr float kPickPixels = 6.0f;     // how near the cursor must be to an item to pick it
constexpr int kMostStepsPerCall = 8;    // advance() drops time beyond this many steps
constexpr double kSlowMotion = 0.1;     // S: the fraction of real time the machine runs at
constexpr double kTrailSeconds = 2.0;
constexpr std::size_t kTrailPoints = 512;

render::Point pt(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

// To the nearest 1/perUnit: dividing the whole count gives the double nearest k / perUnit, which
// prints as the short decimal a person would write (0.3, not 0.30000000000000004).
double snap(double value, double perUnit) { return std::round(value * perUnit) / perUnit; }

// Into (-180, 180]: an angle keeps one spelling however often it is turned.
double normalDegrees(double degrees) {
    while (degrees > 180.0) degrees -= 360.0;
    while (degrees <= -180.0) degrees += 360.0;
    return degrees;
}

// The levels' items a cursor picks: cannons to aim, and what a click uses while running.
bool aimable(ItemKind kind) { return kind->plays(PartRole::fire); }
bool usable(ItemKind kind) { return kind->clickAction().has_value(); }

double pointSegmentDistance(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 ab = b - a;
    const double l2 = ab.lengthSquared();
    const double t = l2 > 0.0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    return p.distance(a + ab * t);
}

// Messages spell numbers as scripts do, so the bar says what a recording will hold.
std::string number(double value) { return scriptNumber(value); }

render::Camera levelCamera(const SceneDesc& level, render::FrameSize frame) {
    const LevelRun start(level, {});
    return sceneCamera(frameScene(level, start.world()), frame);
}

std::vector<ItemKind> stockOf(const SceneDesc& level) {
    std::vector<ItemKind> kinds;
    for (ItemKind kind : allPartKinds())
        if (level.level.inventory.count(std::string(kind->name())) != 0) kinds.push_back(kind);
    return kinds;
}

} // namespace

PlaySession::PlaySession(SceneDesc level, std::string levelPath, render::FrameSize levelFrame)
    : level_(std::move(level)),
      levelPath_(std::move(levelPath)),
      bar_(levelCamera(level_, levelFrame), levelFrame, stockOf(level_)),
      view_(level_.name, levelCamera(level_, levelFrame), levelFrame),
      messageColor_(Palette::greybox()["hud_text"]) {
    rebuildPreview();
    say(level_.description.empty() ? "place items from the bar, then press Space" : level_.description);
}

void PlaySession::say(std::string text, const char* colour) {
    message_ = std::move(text);
    messageColor_ = Palette::greybox()[colour];
}

void PlaySession::load(const ScriptDesc& script) {
    placements_ = script.placements;
    aims_.clear();
    scripted_.clear();
    for (const Action& a : script.actions) {
        if (a.frame == 0 && (a.kind == ActionKind::aim || a.kind == ActionKind::rotate)) aims_[level_.level.find(a.item)] = a;
        else scripted_.push_back(a);
    }
    rebuildPreview();
    say("loaded " + std::to_string(placements_.size()) + " placements and " + std::to_string(aims_.size()) + " aims" +
        (scripted_.empty() ? std::string() : "; the script's " + std::to_string(scripted_.size()) + " other actions play as it runs"));
}

void PlaySession::rebuildPreview() {
    preview_ = std::make_unique<LevelRun>(level_, placements_);
    for (const auto& [item, action] : aims_) takeAction(action, *preview_);
}

int PlaySession::remaining(ItemKind kind) const {
    const auto stock = level_.level.inventory.find(itemKindName(kind));
    int left = stock == level_.level.inventory.end() ? 0 : stock->second;
    left -= static_cast<int>(std::count_if(placements_.begin(), placements_.end(), [&](const Placement& p) { return p.kind == kind; }));
    if (drag_ && drag_->placement.kind == kind) --left;
    return left;
}

render::Point PlaySession::pixelOf(Vec2 world) const { return bar_.toPixel(world); }

// ---------------------------------------------------------------------------------------------
// Input

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
            aims_[cannon] = a;
            takeAction(a, *preview_);
            say("aim " + a.item + ": " + number(a.angleDegrees) + " degrees");
            return;
        }
    }
    turn(clicks * kTurnStep);
}

void PlaySession::key(Key key, KeyAction action) {
    if (action == KeyAction::release) return;
    // Turning repeats while the key is held; every other key acts once per press.
    if (key == Key::leftBracket || key == Key::rightBracket) {
        if (!run_) turn(key == Key::leftBracket ? kTurnStep : -kTurnStep);
        return;
    }
    if (action == KeyAction::repeat) return;
    switch (key) {
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
            drag_.reset();
            rebuildPreview();
        } else if (const int i = placedItemAtCursor(); i >= 0) {
            removeAt(static_cast<std::size_t>(i));
        }
        break;
    case Key::escape:
        if (drag_) {
            // Escape while dragging cancels the drag: a lifted item goes back where it was.
            if (drag_->liftedFrom) placements_.insert(placements_.begin() + static_cast<std::ptrdiff_t>(*drag_->liftedFrom), drag_->original);
            drag_.reset();
            rebuildPreview();
        } else {
            quit_ = true;
        }
        break;
    default: break;
    }
}

// ---------------------------------------------------------------------------------------------
// Editing

void PlaySession::updateDrag() {
    Placement& p = drag_->placement;
    p.position = {snap(cursorWorld_.x, kGridPerMetre), snap(cursorWorld_.y, kGridPerMetre)};
    drag_->refusal.reset();
    if (bar_.contains(cursor_)) {
        say("release on the bar to put the " + std::string(itemKindName(p.kind)) + " back");
        return;
    }
    std::vector<Placement> candidate = placements_;
    candidate.push_back(p);
    drag_->refusal = checkPlacements(level_, candidate);
    if (drag_->refusal) say(drag_->refusal->message, "magnet");
    else say(std::string(itemKindName(p.kind)) + " at " + formatPair(p.position.x, p.position.y) + ": release to place");
}

void PlaySession::drop() {
    Drag drag = std::move(*drag_);
    drag_.reset();
    const std::string kind(itemKindName(drag.placement.kind));
    if (bar_.contains(cursor_)) {
        say("put back: " + kind);
    } else if (drag.refusal) {
        // A refused move puts the item back where it was; a refused new item goes back to the bar.
        if (drag.liftedFrom) placements_.insert(placements_.begin() + static_cast<std::ptrdiff_t>(*drag.liftedFrom), drag.original);
        say("not placed: " + drag.refusal->message, "magnet");
    } else {
        const auto at = drag.liftedFrom ? placements_.begin() + static_cast<std::ptrdiff_t>(*drag.liftedFrom) : placements_.end();
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
    p->angleDegrees = normalDegrees(p->angleDegrees + degrees);
    p->angle = scriptRadians(p->angleDegrees);
    if (drag_) {
        updateDrag();
        return;
    }
    // A placed item turns only where it still fits.
    if (const auto refusal = checkPlacements(level_, placements_)) {
        *p = before;
        say("cannot turn: " + refusal->message, "magnet");
        return;
    }
    rebuildPreview();
    say(std::string(itemKindName(p->kind)) + " turned to " + number(p->angleDegrees) + " degrees");
}

void PlaySession::removeAt(std::size_t index) {
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
// Running

void PlaySession::start() {
    if (drag_) {
        if (drag_->liftedFrom) placements_.insert(placements_.begin() + static_cast<std::ptrdiff_t>(*drag_->liftedFrom), drag_->original);
        drag_.reset();
    }
    aiming_ = -1;
    run_ = std::make_unique<LevelRun>(level_, placements_);
    // The aims are the script's frame-0 actions, taken the way `rube run` takes them.
    for (const auto& [item, action] : aims_) takeAction(action, *run_);
    actions_.clear();
    nextScripted_ = 0;
    paused_ = false;
    owedSeconds_ = 0.0;
    trails_ = std::make_unique<Trails>(run_->world(), kTrailSeconds, kTrailPoints);
    say("running: click a cannon, bomb or switch to use it");
    takeScripted();
}

// A loaded script's actions for the frame the run has reached, taken as soon as it is reached,
// so the frame drawn next shows them, as `rube run` records a frame after its actions.
void PlaySession::takeScripted() {
    for (; nextScripted_ < scripted_.size() && scripted_[nextScripted_].frame <= run_->frame(); ++nextScripted_) {
        Action a = scripted_[nextScripted_];
        a.frame = run_->frame();
        if (const std::string why = takeAction(a, *run_); !why.empty()) {
            say("the script's " + std::string(actionVerb(a.kind)) + " " + a.item + " at frame " + std::to_string(a.frame) + ": " + why, "magnet");
            continue;
        }
        actions_.push_back(a);
    }
}

void PlaySession::reset() {
    run_.reset();
    trails_.reset();
    actions_.clear();
    paused_ = false;
    rebuildPreview();
    say("back to editing: every placement kept");
}

void PlaySession::step() {
    if (!run_) return;
    const bool reachedBefore = run_->goalFrame().has_value();
    run_->step();
    trails_->record(run_->world());
    takeScripted();
    if (!reachedBefore && run_->goalFrame())
        say("GOAL REACHED at frame " + std::to_string(*run_->goalFrame()) + " - R edits again, Esc quits", "goal");
}

void PlaySession::advance(double seconds) {
    if (!run_ || paused_) return;
    owedSeconds_ += seconds * (slow_ ? kSlowMotion : 1.0);
    const double dt = run_->world().def().timeStep;
    // The nudge keeps 0.05 s at a 0.01 s step five steps, not 4.999... rounded down to four.
    auto due = static_cast<std::int64_t>(std::floor(owedSeconds_ / dt + 1e-9));
    if (due > kMostStepsPerCall) {
        due = kMostStepsPerCall;
        owedSeconds_ = 0.0;
    } else {
        owedSeconds_ -= static_cast<double>(due) * dt;
    }
    for (std::int64_t i = 0; i < due; ++i) step();
}

void PlaySession::takeByHand(ActionKind kind, int item) {
    Action a;
    a.frame = run_->frame();
    a.kind = kind;
    a.item = level_.level.items[static_cast<std::size_t>(item)].name;
    takeAction(a, *run_);
    actions_.push_back(a);
    say(std::string(actionVerb(kind)) + " " + a.item + " at frame " + std::to_string(a.frame));
}

void PlaySession::useItemAtCursor() {
    const int item = levelItemAtCursor(usable);
    if (item < 0) return;
    const ItemDesc& desc = level_.level.items[static_cast<std::size_t>(item)];
    const ItemState& state = run_->states()[static_cast<std::size_t>(item)];
    if (desc.name.empty()) {
        say("this " + std::string(itemKindName(desc.kind)) + " has no name, so a script cannot use it: name it in the level", "magnet");
        return;
    }
    if (const std::string spent = desc.kind->spent(desc, state); !spent.empty()) say(spent, "magnet");
    else takeByHand(*desc.kind->clickAction(), item);
}

// ---------------------------------------------------------------------------------------------
// Drawing

void PlaySession::drawEditing(render::DrawList& list) const {
    const Palette& palette = Palette::greybox();
    for (const Zone& zone : level_.level.zones) {
        const Point centre = pt((zone.box.min + zone.box.max) * 0.5);
        const Point half = pt((zone.box.max - zone.box.min) * 0.5);
        list.box(centre, half, 0.0f, {palette["goal"].withAlpha(0x30), palette["goal"], 1.5f});
    }
    const auto outlineBodies = [&](const Placement& p, render::Style look) {
        const ItemBodies bodies = itemBodies(placedItem(p));
        for (const CircleDef& c : bodies.circles) list.circle(pt(c.position), static_cast<float>(c.radius), look);
        for (const SegmentDef& s : bodies.segments) list.capsule(pt(s.a), pt(s.b), static_cast<float>(s.radius), look);
    };
    if (!drag_) {
        if (const int i = placedItemAtCursor(); i >= 0)
            outlineBodies(placements_[static_cast<std::size_t>(i)], {render::Color::transparent(), palette["highlight"], 3.0f});
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
        view_.draw(*run_, run_->frame(), list);
        if (showTrails_) trails_->draw(list, palette["trail"], 2.0f);
        modeLine = "RUN step " + std::to_string(run_->frame()) + (paused_ ? " PAUSED" : "") + (slow_ ? " SLOW" : "") +
                   "  P pause S slow D trails C clear R edit Esc quit";
    } else {
        view_.draw(*preview_, 0, list);
        drawEditing(list);
        modeLine = "EDIT  drag items in, [ ] turns, right-click removes, drag a cannon to aim, Space runs";
    }
    bar_.draw(list, [this](ItemKind kind) { return remaining(kind); }, modeLine, message_, messageColor_);
}

// ---------------------------------------------------------------------------------------------
// The script

std::string PlaySession::recordedScript() const {
    ScriptDesc script;
    script.level = level_.name;
    script.size = bar_.levelFrame();
    script.every = 1;
    script.placements = placements_;
    for (const auto& [item, action] : aims_) {
        script.actions.push_back(action);
        script.actions.back().frame = 0;
    }
    script.actions.insert(script.actions.end(), actions_.begin(), actions_.end());
    if (run_ && run_->goalFrame()) {
        Expectation goal;
        goal.kind = EventKind::goal;
        goal.beforeFrame = *run_->goalFrame() + 1;
        script.expectations.push_back(goal);
    }
    return writeScript(script, "# Recorded by `rube play` at level '" + level_.name + "'. Replay it off-screen, frame for frame:\n"
                                   "#   rube run " + levelPath_ + " --script THIS_FILE --out DIR\n");
}

} // namespace rube::game
