// LevelView: the greybox look of a level (each item kind draws itself, in game/src/items). Colours come from the
// palette by role; strokes are in pixels so they read at any zoom, shapes in metres so they sit where the physics says.
#include "level_view.hpp"

#include "scene_view.hpp"

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
constexpr int kHudLineHeight = 18; // pixels between the HUD's two lines

Point pt(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

Style style(const char* fill, const char* outline, float width = kOutline) {
    const Palette& p = Palette::greybox();
    return {p[fill], p[outline], width};
}

} // namespace

LevelView::LevelView(std::string levelName, render::Camera camera, render::FrameSize frame)
    : levelName_(std::move(levelName)), camera_(camera), frame_(frame) {}

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
    if (run.goalFrame()) return "REACHED at frame " + std::to_string(*run.goalFrame()) + ": " + run.goal()->text;
    return "goal: " + run.goal()->text;
}

void LevelView::drawHud(const LevelRun& run, std::int64_t frame, render::DrawList& list) const {
    const Palette& palette = Palette::greybox();
    const float band = static_cast<float>(2 * kHudMargin + kHudLineHeight + 7 * kHudScale);
    const Point low = camera_.toWorld({0.0f, static_cast<float>(frame_.height) - band}, frame_);
    const Point high = camera_.toWorld({static_cast<float>(frame_.width), static_cast<float>(frame_.height)}, frame_);
    list.box({0.5f * (low.x + high.x), 0.5f * (low.y + high.y)}, {0.5f * (high.x - low.x), 0.5f * (high.y - low.y)},
             0.0f, {palette["background"].withAlpha(0xd8), render::Color::transparent(), 0.0f});
    char line[256];
    std::snprintf(line, sizeof line, "%s   frame %lld   t = %.3f s", levelName_.c_str(), static_cast<long long>(frame),
                  run.world().time());
    list.text(kHudMargin, kHudMargin, line, palette["hud_text"], kHudScale);
    list.text(kHudMargin, kHudMargin + kHudLineHeight, goalLine(run),
              run.goalFrame() ? palette["goal"] : palette["hud_text"], kHudScale);
}

void LevelView::draw(const LevelRun& run, std::int64_t frame, render::DrawList& list) const {
    list.clear();
    list.background = Palette::greybox()["background"];
    drawBodies(run, list);
    drawItems(run, list);
    // Water in front of balls and items, as in the scene view: a floating ball shows how deep it sits.
    drawWaters(run.world(), list);
    drawHud(run, frame, list);
}

} // namespace rube::game
