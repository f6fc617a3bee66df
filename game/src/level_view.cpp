// LevelView: the greybox look of a level (each item kind draws itself, in game/src/items). Colours come from the
// palette by role; strokes are in pixels so they read at any zoom, shapes in metres so they sit where the physics says.
#include "level_view.hpp"

#include "scene_view.hpp"
#include "script_file.hpp"

#include "rube/render/palette.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rube::game {

namespace {

using render::Color;
using render::Palette;
using render::Point;
using render::Style;

constexpr float kOutline = 1.5f;       // pixels
constexpr float kThinLine = 3.0f;      // pixels: a zero-thickness wall
constexpr double kArrowSeconds = 0.15; // a projectile's arrow shows where it will be this much later
constexpr int kHudMargin = 8;
constexpr int kHudScale = 2;
constexpr int kHudLineHeight = 18; // pixels between the HUD's lines
constexpr int kGoalLines = 2;      // the goal's text wraps onto at most this many lines
constexpr int kLabelScale = 1;     // item labels: small, beside the item

Point pt(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

Style style(const char* fill, const char* outline, float width = kOutline) {
    const Palette& p = Palette::greybox();
    return {p[fill], p[outline], width};
}

} // namespace

void drawZones(const LevelDesc& level, render::DrawList& list) {
    const Palette& palette = Palette::greybox();
    for (const Zone& zone : level.zones) {
        const Point centre = pt((zone.box.min + zone.box.max) * 0.5);
        const Point half = pt((zone.box.max - zone.box.min) * 0.5);
        list.box(centre, half, 0.0f, {palette["goal"].withAlpha(0x30), palette["goal"], 1.5f});
    }
}

namespace {

// A reach-area goal's area: always drawn, behind the bodies, in the goal's colour with a heavier
// edge than a placement zone's, so the player sees where the ball must come.
void drawGoalArea(const LevelDesc& level, render::DrawList& list) {
    if (!level.goal || level.goal->kind != GoalKind::reachArea) return;
    const Palette& palette = Palette::greybox();
    const Aabb& area = level.goal->area;
    list.box(pt((area.min + area.max) * 0.5), pt((area.max - area.min) * 0.5), 0.0f,
             {palette["goal"].withAlpha(0x48), palette["goal"], 3.0f});
}

} // namespace

std::vector<std::string> wrapText(const std::string& text, int width, int scale, int maxLines) {
    std::vector<std::string> lines;
    std::string line;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t space = text.find(' ', at);
        const std::string word = text.substr(at, space == std::string::npos ? std::string::npos : space - at);
        at = space == std::string::npos ? text.size() : space + 1;
        const std::string longer = line.empty() ? word : line + " " + word;
        if (line.empty() || render::textWidth(longer, scale) <= width) {
            line = longer;
            continue;
        }
        lines.push_back(line);
        line = word;
    }
    if (!line.empty() || lines.empty()) lines.push_back(line);
    if (static_cast<int>(lines.size()) <= maxLines &&
        std::all_of(lines.begin(), lines.end(),
                    [&](const std::string& l) { return render::textWidth(l, scale) <= width; }))
        return lines;
    // Too long: keep what fits and say so with "..." at the end of the last line kept.
    lines.resize(std::min<std::size_t>(lines.size(), static_cast<std::size_t>(std::max(1, maxLines))));
    std::string& last = lines.back();
    while (!last.empty() && render::textWidth(last + "...", scale) > width) last.pop_back();
    while (!last.empty() && last.back() == ' ') last.pop_back();
    last += "...";
    return lines;
}

LevelView::LevelView(std::string levelName, render::Camera camera, render::FrameSize frame, LevelViewOptions options)
    : levelName_(std::move(levelName)), camera_(camera), frame_(frame), options_(options) {}

void LevelView::drawBodies(const LevelRun& run, render::DrawList& list) const {
    const World& world = run.world();
    const float ppm = camera_.pixelsPerMetre(frame_);
    for (const Segment& s : world.segments()) {
        const bool thin = s.radius * ppm < 0.5 * kThinLine;
        list.capsule(pt(s.a), pt(s.b), static_cast<float>(s.radius),
                     style("ground", "ground_outline", thin ? kThinLine : kOutline));
    }
    drawConveyors(world, list);
    drawRopes(world, list);
    drawJoints(world, list);
    drawRigidBodies(world, list);
    drawAirDrag(world, list);
    // Items' circles are drawn by drawItems; the plain ones here, projectiles with their arrow.
    for (std::size_t i = 0; i < world.circles().size(); ++i) {
        const CircleId id = world.circleId(static_cast<int>(i));
        if (run.itemOf(id) >= 0) continue;
        const Circle& c = world.circles()[i];
        const Style look = c.motion == Motion::dynamic     ? style("ball", "ball_outline")
                           : c.motion == Motion::kinematic ? style("kinematic", "kinematic_outline")
                                                           : style("ground", "ground_outline");
        list.circleWithSpoke(pt(c.position), static_cast<float>(c.radius), static_cast<float>(c.velocity.angle()),
                             look);
        if (run.isProjectile(id))
            list.arrow(pt(c.position), pt(c.position + c.velocity * kArrowSeconds), 2.0f, Palette::greybox()["arrow"]);
    }
    drawJointPins(world, list);
}

// Each item as its kind draws it.
void LevelView::drawItems(const LevelRun& run, render::DrawList& list) const {
    for (std::size_t i = 0; i < run.items().size(); ++i) run.items()[i].kind->draw({run, static_cast<int>(i), list});
}

std::string LevelView::goalLine(const LevelRun& run) const {
    if (!run.goal()) return "no goal";
    // The status first, so a long goal text cut off at the frame's edge never hides it.
    if (run.goalStep()) return "REACHED at step " + std::to_string(*run.goalStep()) + ": " + run.goal()->text;
    if (run.timeUp()) return timeUpLine(*run.goal());
    return "goal: " + run.goal()->text;
}

std::string LevelView::timeUpLine(const Goal& goal) {
    return "TIME UP after " + scriptNumber(*goal.timeLimit) + " s: " + goal.text;
}

std::vector<std::string> LevelView::goalLines(const LevelRun& run) const {
    return wrapText(goalLine(run), frame_.width - 2 * kHudMargin, kHudScale, kGoalLines);
}

void LevelView::drawHud(const LevelRun& run, std::int64_t step, render::DrawList& list) const {
    const Palette& palette = Palette::greybox();
    const std::vector<std::string> goal = goalLines(run);
    const float band = static_cast<float>(2 * kHudMargin + kHudLineHeight * static_cast<int>(goal.size()) +
                                          7 * kHudScale);
    const Point low = camera_.toWorld({0.0f, static_cast<float>(frame_.height) - band}, frame_);
    const Point high = camera_.toWorld({static_cast<float>(frame_.width), static_cast<float>(frame_.height)}, frame_);
    list.box({0.5f * (low.x + high.x), 0.5f * (low.y + high.y)}, {0.5f * (high.x - low.x), 0.5f * (high.y - low.y)},
             0.0f, {palette["background"].withAlpha(0xd8), render::Color::transparent(), 0.0f});
    // The top line, as much of it as fits: the time goes first, then the level's name; the step stays.
    char time[64];
    std::snprintf(time, sizeof time, "   t = %.3f s", run.world().time());
    const std::string stepWords = "step " + std::to_string(step);
    std::string line = levelName_ + "   " + stepWords + time;
    for (const std::string& shorter : {levelName_ + "   " + stepWords, stepWords})
        if (render::textWidth(line, kHudScale) > frame_.width - 2 * kHudMargin) line = shorter;
    list.text(kHudMargin, kHudMargin, line, palette["hud_text"], kHudScale);
    for (std::size_t i = 0; i < goal.size(); ++i)
        list.text(kHudMargin, kHudMargin + kHudLineHeight * static_cast<int>(i + 1), goal[i],
                  run.goalStep()  ? palette["goal"]
                  : run.timeUp() ? palette["magnet"]
                                 : palette["hud_text"],
                  kHudScale);
}

// Each named item's name just above its right shoulder, from its position now (a moving target's
// label moves with it); in pixels from the top-left corner, as HUD text is.
void LevelView::drawLabels(const LevelRun& run, render::DrawList& list) const {
    const Palette& palette = Palette::greybox();
    const float ppm = camera_.pixelsPerMetre(frame_);
    for (std::size_t i = 0; i < run.items().size(); ++i) {
        const ItemDesc& item = run.items()[i];
        if (item.name.empty()) continue;
        const int index = static_cast<int>(i);
        const ItemState& state = run.states()[i];
        const double radius = state.circle.isNull() ? 0.2 : run.world().circle(state.circle).radius;
        const Point at = camera_.toPixels(pt(run.itemPosition(index)), frame_);
        const int x = static_cast<int>(std::lround(at.x + static_cast<float>(radius) * ppm * 0.7f + 2.0f));
        const int y = static_cast<int>(
            std::lround(static_cast<float>(frame_.height) - at.y - static_cast<float>(radius) * ppm * 0.7f - 9.0f));
        list.text(x, y, item.name, palette["hud_text"], kLabelScale);
    }
}

void LevelView::draw(const LevelRun& run, std::int64_t step, render::DrawList& list) const {
    list.clear();
    list.background = Palette::greybox()["background"];
    if (options_.zones) drawZones(run.scene().level, list);
    drawGoalArea(run.scene().level, list);
    drawBodies(run, list);
    drawItems(run, list);
    // Water in front of balls and items, as in the scene view: a floating ball shows how deep it sits.
    drawWaters(run.world(), list);
    if (options_.labels) drawLabels(run, list);
    drawHud(run, step, list);
}

} // namespace rube::game
