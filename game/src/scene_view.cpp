// SceneView: the game's picture of the physics. Colours come from the palette by role (static,
// kinematic, dynamic), never as numbers; sizes meant to be seen (strokes, markers, text) are in
// pixels so they stay readable at any zoom, and bodies in metres so they are where the physics says.
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

constexpr float kOutlineWidth = 1.5f; // pixels: the greybox outline
// A thin line (radius 0) has no area to fill: drawn as a 3-pixel stroke, so it reads as a wall
// and not as a hairline the eye misses (the renderer's zero-radius capsule is its outline alone).
constexpr float kThinLineWidth = 3.0f;
// Below this radius in pixels a spoke and a 1.5-pixel outline would paint the disc solid, so
// small balls (a pile seen whole) get a thinner outline and no spoke.
constexpr float kSpokeMinRadius = 4.0f;
constexpr float kSmallOutlineWidth = 1.0f;
constexpr float kTrailWidth = 2.0f;     // pixels
constexpr float kRopeWidth = 2.0f;      // pixels: thinner than a wall's 3, so a rope never reads as one
constexpr float kRopePinRadius = 0.06f; // m: the anchor's pin
// A trail keeps a point per step and per impact; past this many a trail of tiny steps stops growing.
constexpr std::size_t kMaxTrailPoints = 2000;
// Impact markers kept at most: a pile resolves hundreds of contacts per step.
constexpr std::size_t kMaxImpactsShown = 4096;
constexpr int kHudMargin = 8; // pixels from the top-left corner
// The HUD sits on a band of the background colour, a little see-through, so that it stays
// readable over walls and balls and the scene still shows through.
constexpr std::uint8_t kHudBandAlpha = 0xd8;
constexpr int kGlyphHeight = 7; // stb_easy_font units

Point toPoint(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

// The palette's fill and outline for a body that moves this way.
Style styleFor(Motion motion, float outlineWidth) {
    const Palette& palette = Palette::greybox();
    switch (motion) {
    case Motion::dynamic: return {palette["ball"], palette["ball_outline"], outlineWidth};
    case Motion::kinematic: return {palette["kinematic"], palette["kinematic_outline"], outlineWidth};
    case Motion::fixed: break;
    }
    return {palette["ground"], palette["ground_outline"], outlineWidth};
}

// HUD glyphs are about 7 font units tall: 2 pixels per unit up to 1080 rows, then 3.
int hudScale(render::FrameSize frame) { return frame.height >= 1080 ? 3 : 2; }

} // namespace

SceneView::SceneView(std::string sceneName, const World& world, render::Camera camera, render::FrameSize frame,
                     const ViewOptions& options)
    : sceneName_(std::move(sceneName)), camera_(camera), frame_(frame), options_(options) {
    if (options_.trails) trails_.emplace(world, options_.trailSeconds, kMaxTrailPoints);
    if (options_.impacts) impacts_.emplace(options_.impactSeconds, kMaxImpactsShown);
}

void SceneView::afterStep(const World& world) {
    if (trails_) trails_->record(world);
    if (impacts_) impacts_->record(world);
}

std::string SceneView::hudLine(const World& world) const {
    // The step, not the frame's number: frame n of a run with --every K shows step n x K.
    char line[256];
    std::snprintf(line, sizeof line, "%s   step %lld   t = %.3f s   %s", sceneName_.c_str(),
                  static_cast<long long>(world.stats().steps), world.time(),
                  std::string(methodName(world.def().method)).c_str());
    return line;
}

void drawRopes(const World& world, render::DrawList& list) {
    const Palette& palette = Palette::greybox();
    for (const Rope& rope : world.ropes()) {
        if (rope.cut) continue; // a cut rope is gone from the picture as from the physics
        const Vec2 ball = world.circles()[static_cast<std::size_t>(rope.circle)].position;
        const Vec2 end = rope.other >= 0 ? world.circles()[static_cast<std::size_t>(rope.other)].position : rope.anchor;
        list.line(toPoint(end), toPoint(ball), kRopeWidth, palette["rope"]);
        if (rope.other < 0) list.circle(toPoint(end), kRopePinRadius, styleFor(Motion::fixed, kSmallOutlineWidth));
    }
}

void drawRigidBodies(const World& world, render::DrawList& list) {
    for (const RigidBody& b : world.bodies()) {
        const Style style = styleFor(b.motion, kSmallOutlineWidth);
        const Vec2 axis{std::cos(b.angle), std::sin(b.angle)};
        const Vec2 a = b.position - axis * b.halfExtents.x, e = b.position + axis * b.halfExtents.x;
        if (b.shape == BodyShape::box)
            list.box(toPoint(b.position), toPoint(b.halfExtents), static_cast<float>(b.angle), style);
        else list.capsule(toPoint(a), toPoint(e), static_cast<float>(b.halfExtents.y), style);
        // A line from the centre along the body's own x axis: turning reads at a glance.
        list.line(toPoint(b.position), toPoint(e), kRopeWidth, style.outline);
    }
    for (const Pivot& pivot : world.pivots())
        list.circle(toPoint(pivot.worldAnchor), kRopePinRadius, styleFor(Motion::fixed, kSmallOutlineWidth));
}

void SceneView::drawSegments(const World& world, render::DrawList& list) const {
    for (const Segment& s : world.segments()) {
        const bool thin = s.radius * camera_.pixelsPerMetre(frame_) < 0.5 * kThinLineWidth;
        list.capsule(toPoint(s.a), toPoint(s.b), static_cast<float>(s.radius),
                     styleFor(s.motion(), thin ? kThinLineWidth : kOutlineWidth));
    }
}

void SceneView::drawCircles(const World& world, render::DrawList& list) const {
    const float scale = camera_.pixelsPerMetre(frame_);
    for (const Circle& c : world.circles()) {
        const float radius = static_cast<float>(c.radius);
        if (radius * scale < kSpokeMinRadius) {
            list.circle(toPoint(c.position), radius, styleFor(c.motion, kSmallOutlineWidth));
        } else {
            // The spoke turns with the body, so rolling reads differently from sliding.
            list.circleWithSpoke(toPoint(c.position), radius, static_cast<float>(c.angle),
                                 styleFor(c.motion, kOutlineWidth));
        }
    }
}

void SceneView::drawHud(const std::string& line, render::DrawList& list) const {
    const Palette& palette = Palette::greybox();
    const int scale = hudScale(frame_);
    // The band is a box in world metres: the corners of its pixel rectangle through the camera.
    const float bandPixels = static_cast<float>(2 * kHudMargin + kGlyphHeight * scale);
    const float width = static_cast<float>(frame_.width);
    const float height = static_cast<float>(frame_.height);
    const Point low = camera_.toWorld({0.0f, height - bandPixels}, frame_);
    const Point high = camera_.toWorld({width, height}, frame_);
    list.box({0.5f * (low.x + high.x), 0.5f * (low.y + high.y)}, {0.5f * (high.x - low.x), 0.5f * (high.y - low.y)},
             0.0f, {palette["background"].withAlpha(kHudBandAlpha), Color::transparent(), 0.0f});
    list.text(kHudMargin, kHudMargin, line, palette["hud_text"], scale);
}

void SceneView::draw(const World& world, render::DrawList& list) const {
    const Palette& palette = Palette::greybox();
    list.clear();
    list.background = palette["background"];
    // Back to front: walls, then where balls have been, the balls, and the debug marks on top.
    drawSegments(world, list);
    drawConveyors(world, list);
    drawRopes(world, list);
    drawJoints(world, list);
    drawRigidBodies(world, list);
    drawAirDrag(world, list);
    if (trails_) trails_->draw(list, palette["trail"], kTrailWidth);
    drawCircles(world, list);
    drawJointPins(world, list);
    // Water in front of the balls, translucent, so a floating ball shows how deep it sits.
    drawWaters(world, list);
    if (impacts_)
        impacts_->draw(list, world.time(), camera_.pixelsPerMetre(frame_), palette["impact"], palette["arrow"]);
    drawHud(hudLine(world), list);
}

} // namespace rube::game
