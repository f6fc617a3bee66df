// The editor's state: a new level, the level saved (its inventory counted from the player's parts),
// saving the level and its solution, trying the level, and undo. Input is in edit_input.cpp, the
// picture in edit_drawing.cpp.
#include "edit_session.hpp"

#include "level_writer.hpp"
#include "play_internal.hpp"
#include "scene_file.hpp"
#include "solution_nudges.hpp"

#include "rube/render/palette.hpp"

#include <algorithm>
#include <cmath>

namespace rube::game {

SceneDesc EditSession::newLevel(const std::string& name) {
    const SceneLoad load = parseScene("name = \"" + name + R"("
description = "A level made with rube edit."
[world]
time_step = 0.01
bounds = { min = [-20, -5], max = [20, 30] }
[[segment]]
name = "floor"
a = [-8, 0]
b = [8, 0]
[view]
min = [-8, -1]
max = [8, 8]
)",
                                      name + ".toml");
    return *load.scene; // the text is fixed and valid; tests/edit read it
}

EditSession::EditSession(SceneDesc level, std::filesystem::path file, render::FrameSize levelFrame,
                         const std::vector<Placement>& solution)
    : state_{std::move(level), solution, {}}, file_(std::move(file)),
      bar_(play::levelCamera(state_.level, levelFrame), levelFrame, {}),
      view_(state_.level.name, play::levelCamera(state_.level, levelFrame), levelFrame),
      messageColor_(render::Palette::greybox()["hud_text"]) {
    // What the inventory gives beyond the solution's parts stays spare.
    state_.spare = state_.level.level.inventory;
    for (const Placement& p : solution) --state_.spare[std::string(p.kind->name())];
    std::erase_if(state_.spare, [](const auto& kindCount) { return kindCount.second <= 0; });
    say("click to place a " + std::string(selectedKind()->name()) + "; Tab picks another kind");
}

void EditSession::say(std::string text, const char* colour) {
    message_ = std::move(text);
    messageColor_ = render::Palette::greybox()[colour];
}

void EditSession::edit() { history_.record(state_); }

// The camera follows the level's [view]: after V, and after an undo or redo that changed it.
// While C draws a view, the camera shows the wider box around it instead.
void EditSession::refreshCamera() {
    SceneDesc shown = state_.level;
    if (viewMode_) shown.view = wideView_;
    const render::Camera camera = play::levelCamera(shown, bar_.levelFrame());
    bar_ = InventoryBar(camera, bar_.levelFrame(), {});
    view_ = LevelView(state_.level.name, camera, bar_.levelFrame());
}

// V: the view becomes the box around every part and zone, with a metre's margin.
void EditSession::fitView() {
    std::optional<Aabb> box;
    const auto add = [&](const Aabb& b) {
        box = box ? Aabb{{std::min(box->min.x, b.min.x), std::min(box->min.y, b.min.y)},
                         {std::max(box->max.x, b.max.x), std::max(box->max.y, b.max.y)}}
                  : b;
    };
    for (const ItemDesc& item : state_.level.level.items) add(itemExtent(item));
    for (const Placement& p : state_.players) add(itemExtent(placedItem(p)));
    for (const Zone& zone : state_.level.level.zones) add(zone.box);
    if (!box) return say("V: nothing to fit the view to", "magnet");
    const double margin = 1.0;
    setView({{std::floor(box->min.x - margin), std::floor(box->min.y - margin)},
             {std::ceil(box->max.x + margin), std::ceil(box->max.y + margin)}});
}

void EditSession::setView(const Aabb& box) {
    edit();
    state_.level.view = box;
    viewMode_ = false;
    refreshCamera();
    say("view " + formatPair(box.min.x, box.min.y) + " to " + formatPair(box.max.x, box.max.y));
}

// C: the window shows three times the view's width and height around it (the wheel zooms), and a
// drag draws the new view, which the camera then follows; C again leaves the view as it was.
void EditSession::toggleViewMode() {
    viewMode_ = !viewMode_;
    zoneMode_ = false;
    zoneStart_.reset();
    if (!viewMode_) {
        refreshCamera();
        return say("the view is left as it was");
    }
    const render::FrameSize frame = bar_.levelFrame();
    const Vec2 a = bar_.toWorld({0.0f, 0.0f});
    const Vec2 b = bar_.toWorld({static_cast<float>(frame.width), static_cast<float>(frame.height)});
    const Vec2 centre = (a + b) * 0.5;
    const Vec2 half{std::abs(b.x - a.x) * 1.5, std::abs(b.y - a.y) * 1.5};
    wideView_ = {centre - half, centre + half};
    refreshCamera();
    say("view: drag the level's view (the wheel zooms out and in; C again leaves it as it was)");
}

std::string EditSession::nameFor(ItemKind kind) const {
    const auto taken = [&](const std::string& name) {
        return state_.level.level.find(name) >= 0 || std::any_of(state_.players.begin(), state_.players.end(),
                                                                 [&](const Placement& p) { return p.name == name; });
    };
    for (int n = 1;; ++n)
        if (std::string name = std::string(kind->name()) + std::to_string(n); !taken(name)) return name;
}

// The level as saved: the fixed parts, and an inventory of the player's parts.
SceneDesc EditSession::savedLevel() const {
    SceneDesc level = state_.level;
    level.level.inventory = state_.spare;
    for (const Placement& p : state_.players) ++level.level.inventory[std::string(p.kind->name())];
    return level;
}

// Whether the solution holds with each part moved one grid step either way (solution_nudges.hpp):
// a designer should know when a level can be solved only on one point of the grid.
std::string EditSession::holdsWhenMoved(const SceneDesc& level, const ScriptDesc& script, std::int64_t steps) const {
    const std::vector<PlacementNudge> nudges = nudgePlacements(level, script, steps);
    ScriptDesc named = script; // the parts as the editor names them, for the message
    named.placements = state_.players;
    const PlacementNudge* first = nullptr;
    int misses = 0, tried = 0;
    for (const PlacementNudge& n : nudges) {
        tried += n.refused ? 0 : 1;
        if (!n.refused && !n.reached && misses++ == 0) first = &n;
    }
    const std::string step = gridStepWords();
    if (tried == 0) return ", and no part may move a " + step + " grid step (every move is refused)";
    if (!first) return ", and holds with each part moved one " + step + " grid step";
    std::string text = ", but misses with " + describeNudge(named, *first);
    if (misses > 1) text += " (and " + std::to_string(misses - 1) + " more moves)";
    return text;
}

bool EditSession::save() {
    const SceneDesc level = savedLevel();
    const std::string text = writeLevel(level,
                                        "# Made with `rube edit`; play it with `rube play " + file_.string() + "`.");
    // What is written must read back: a part missing a required key (a switch's triggers) is said here.
    const SceneLoad back = parseScene(text, file_.string());
    if (!back.ok()) {
        say("not saved: " + back.errors.front().format(), "magnet");
        return false;
    }
    ScriptDesc script;
    script.level = level.name;
    script.placements = state_.players;
    for (Placement& p : script.placements) p.name.clear(); // placed parts need no names
    // The solution's expectation: the goal at the step a headless run reaches it.
    LevelRun run(*back.scene, script.placements);
    std::int64_t steps = back.scene->defaultSteps();
    if (level.level.goal && level.level.goal->timeLimit)
        steps = static_cast<std::int64_t>(std::ceil(*level.level.goal->timeLimit / level.world.timeStep - 1e-9));
    while (level.level.goal && !run.goalStep() && run.steps() < steps) run.step();
    if (run.goalStep()) {
        Expectation goal;
        goal.kind = EventKind::goal;
        goal.beforeStep = *run.goalStep() + 1;
        script.expectations.push_back(goal);
    }
    std::filesystem::path solution = file_;
    solution.replace_extension(".solution.toml");
    std::string reason;
    if (!writeTextFileAtomically(file_, text, reason) ||
        !writeTextFileAtomically(solution,
                                 writeScript(script, "# The intended solution of " + file_.filename().string() +
                                                         ", from the parts marked as the player's in `rube edit`.\n"),
                                 reason)) {
        say("not saved: " + reason, "magnet");
        return false;
    }
    std::string how = run.goalStep() ? "the solution reaches the goal at step " + std::to_string(*run.goalStep())
                                      : std::string("the solution does not reach the goal yet");
    if (const auto refusal = checkPlacements(*back.scene, script.placements)) how = refusal->brief;
    else if (run.goalStep()) how += holdsWhenMoved(*back.scene, script, steps);
    say("saved " + file_.filename().string() + " and " + solution.filename().string() + ": " + how,
        run.goalStep() ? "goal" : "magnet");
    return true;
}

void EditSession::tryIt() {
    const SceneLoad back = parseScene(writeLevel(savedLevel()), file_.string());
    if (!back.ok()) {
        say("cannot try it: " + back.errors.front().format(), "magnet");
        return;
    }
    trying_ = std::make_unique<PlaySession>(*back.scene, file_.string(), bar_.levelFrame());
    ScriptDesc parts;
    parts.placements = state_.players;
    trying_->load(parts);
    trying_->start();
}

void EditSession::advance(double seconds) {
    if (trying_) trying_->advance(seconds);
}

EditSession::Hit EditSession::hitAtCursor() const {
    const float ppm = bar_.windowCamera().pixelsPerMetre(bar_.windowSize());
    const double tolerance = 6.0 / ppm;
    for (std::size_t i = state_.players.size(); i-- > 0;) {
        const ItemDesc item = placedItem(state_.players[i]);
        if (item.kind->picked(item, item.position, cursorWorld_, tolerance)) return {Hit::What::player, i};
    }
    const std::vector<ItemDesc>& items = state_.level.level.items;
    for (std::size_t i = items.size(); i-- > 0;)
        if (items[i].kind->pickedInLevel(items[i], state_.level.level, cursorWorld_, tolerance))
            return {Hit::What::item, i};
    const std::vector<Zone>& zones = state_.level.level.zones;
    for (std::size_t i = zones.size(); i-- > 0;) {
        const Aabb& box = zones[i].box;
        if (cursorWorld_.x >= box.min.x && cursorWorld_.x <= box.max.x && cursorWorld_.y >= box.min.y &&
            cursorWorld_.y <= box.max.y)
            return {Hit::What::zone, i};
    }
    return {};
}

} // namespace rube::game
