// The play session: its state and modes, the run driven through the same LevelRun and takeAction()
// that `rube run` uses (so what the player did replays to the same frames), a loaded script's
// actions, the bar's message, and the session recorded as a script. What the mouse and keys do is
// in play_input.cpp, the editing rules in play_editing.cpp, the picture in play_drawing.cpp.
#include "play_session.hpp"

#include "play_internal.hpp"
#include "scene_framing.hpp"

#include "rube/render/palette.hpp"

#include <cmath>

namespace rube::game {

namespace {

using play::kTrailPoints;
using play::kTrailSeconds;
using render::Palette;

constexpr int kMostStepsPerCall = 8; // advance() drops time beyond this many steps
constexpr double kSlowMotion = 0.1;  // S: the fraction of real time the machine runs at

// The levels' items a click uses while running.
bool usable(ItemKind kind) { return kind->clickAction().has_value(); }

std::vector<ItemKind> stockOf(const SceneDesc& level) {
    std::vector<ItemKind> kinds;
    for (ItemKind kind : allPartKinds())
        if (level.level.inventory.count(std::string(kind->name())) != 0) kinds.push_back(kind);
    return kinds;
}

} // namespace

render::Camera play::levelCamera(const SceneDesc& level, render::FrameSize frame) {
    const LevelRun start(level, {});
    return sceneCamera(frameScene(level, start.world()), frame);
}

PlaySession::PlaySession(SceneDesc level, std::string levelPath, render::FrameSize levelFrame)
    : level_(std::move(level)), levelPath_(std::move(levelPath)),
      bar_(play::levelCamera(level_, levelFrame), levelFrame, stockOf(level_)),
      view_(level_.name, play::levelCamera(level_, levelFrame), levelFrame),
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
        if (a.step == 0 && (a.kind == ActionKind::aim || a.kind == ActionKind::rotate))
            aims_[level_.level.find(a.item)] = a;
        else scripted_.push_back(a);
    }
    rebuildPreview();
    say("loaded " + std::to_string(placements_.size()) + " placements and " + std::to_string(aims_.size()) + " aims" +
        (scripted_.empty() ? std::string()
                           : "; the script's " + std::to_string(scripted_.size()) + " other actions play as it runs"));
}

void PlaySession::rebuildPreview() {
    preview_ = std::make_unique<LevelRun>(level_, placements_);
    for (const auto& [item, action] : aims_) takeAction(action, *preview_);
}

render::Point PlaySession::pixelOf(Vec2 world) const { return bar_.toPixel(world); }

// ---------------------------------------------------------------------------------------------
// Running

void PlaySession::start() {
    cancelDrag();
    aiming_ = -1;
    timeUpSaid_ = false;
    run_ = std::make_unique<LevelRun>(level_, placements_);
    // The aims are the script's step-0 actions, taken the way `rube run` takes them.
    for (const auto& [item, action] : aims_) takeAction(action, *run_);
    actions_.clear();
    nextScripted_ = 0;
    paused_ = false;
    owedSeconds_ = 0.0;
    trails_ = std::make_unique<Trails>(run_->world(), kTrailSeconds, kTrailPoints);
    say("running: click a cannon, bomb or switch to use it");
    takeScripted();
}

// A loaded script's actions for the step the run has reached, taken as soon as it is reached,
// so the frame drawn next shows them, as `rube run` records a frame after its actions.
void PlaySession::takeScripted() {
    for (; nextScripted_ < scripted_.size() && scripted_[nextScripted_].step <= run_->steps(); ++nextScripted_) {
        Action a = scripted_[nextScripted_];
        a.step = run_->steps();
        if (const std::string why = takeAction(a, *run_); !why.empty()) {
            say("the script's " + std::string(actionVerb(a.kind)) + " " + a.item + " at step " +
                    std::to_string(a.step) + ": " + why,
                "magnet");
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
    if (!run_ || (stopAt_ && run_->steps() >= *stopAt_)) return;
    const bool reachedBefore = run_->goalStep().has_value();
    run_->step();
    trails_->record(run_->world());
    takeScripted();
    goalMessages(reachedBefore);
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
    a.step = run_->steps();
    a.kind = kind;
    a.item = level_.level.items[static_cast<std::size_t>(item)].name;
    takeAction(a, *run_);
    actions_.push_back(a);
    say(std::string(actionVerb(kind)) + " " + a.item + " at step " + std::to_string(a.step));
}

void PlaySession::useItemAtCursor() {
    const int item = levelItemAtCursor(usable);
    if (item < 0) return;
    const ItemDesc& desc = level_.level.items[static_cast<std::size_t>(item)];
    const ItemState& state = run_->states()[static_cast<std::size_t>(item)];
    if (desc.name.empty()) {
        say("this " + std::string(itemKindName(desc.kind)) +
                " has no name, so a script cannot use it: name it in the level",
            "magnet");
        return;
    }
    if (!level_.level.clickable(desc.name)) say("this level lets no click act on '" + desc.name + "'", "magnet");
    else if (const std::string spent = desc.kind->spent(desc, state); !spent.empty()) say(spent, "magnet");
    else takeByHand(*desc.kind->clickAction(), item);
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
        script.actions.back().step = 0;
    }
    script.actions.insert(script.actions.end(), actions_.begin(), actions_.end());
    if (run_ && run_->goalStep()) {
        Expectation goal;
        goal.kind = EventKind::goal;
        goal.beforeStep = *run_->goalStep() + 1;
        script.expectations.push_back(goal);
    }
    return writeScript(script, "# Recorded by `rube play` at level '" + level_.name +
                                   "'. Replay it off-screen, step for step:\n"
                                   "#   rube run " +
                                   levelPath_ + " --script THIS_FILE --out DIR\n");
}

} // namespace rube::game
