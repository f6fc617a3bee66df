// LevelView: the greybox look of each item kind. Colours come from the palette by role; strokes
// are in pixels so they read at any zoom, shapes in metres so they sit where the physics says.
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

constexpr float kOutline = 1.5f;      // pixels
constexpr float kThinLine = 3.0f;     // pixels: a zero-thickness wall
constexpr float kArcWidth = 2.0f;     // pixels: the predicted arc
constexpr double kArcSeconds = 3.0;   // how far ahead the predicted arc looks
constexpr int kArcPoints = 60;
constexpr double kRingSeconds = 0.5;  // an explosion's ring grows to the blast radius in this time
constexpr double kBarrelLength = 0.6; // m
constexpr double kBarrelHalfWidth = 0.1;
constexpr double kArrowSeconds = 0.15; // a projectile's arrow shows where it will be this much later
constexpr double kWindSpacing = 0.8;  // m between a fan's arrows, along and across its column
constexpr double kWindArrow = 0.35;   // m: each arrow's length
constexpr double kFlameLength = 1.6;  // a rocket's flame, in its radii beyond the body ...
constexpr double kFlameFlicker = 0.4; // ... give or take this much ...
constexpr double kFlameRate = 37.0;   // ... at this many radians per second of world time
constexpr int kHudMargin = 8;
constexpr int kHudScale = 2;
constexpr int kHudLineHeight = 18;    // pixels between the HUD's two lines

Point pt(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

// A fan's air as rows of arrows drifting along the column at the air's speed, so a still frame
// shows where it blows and a sequence shows that it moves. The drift is a function of world time only.
void drawWind(const Wind& wind, double time, render::DrawList& list) {
    const Color color = render::Palette::greybox()["wind"];
    const Vec2 across = wind.direction.perpendicular();
    const int rows = std::max(1, static_cast<int>(wind.width / (0.6 * kWindSpacing)));
    const double drift = std::fmod(time * wind.speed, kWindSpacing);
    for (int row = 0; row < rows; ++row) {
        const double offset = (row + 0.5) * wind.width / rows - 0.5 * wind.width;
        for (double along = drift; along + kWindArrow <= wind.length; along += kWindSpacing) {
            const Vec2 tail = wind.origin + across * offset + wind.direction * along;
            list.arrow(pt(tail), pt(tail + wind.direction * kWindArrow), 2.0f, color);
        }
    }
}

// A rocket's flame while it burns: a triangle from the back of its body, pointing against the thrust,
// flickering in length with the world time (never the wall clock) so frames stay reproducible.
void drawFlame(Vec2 centre, double radius, Vec2 direction, double time, render::DrawList& list) {
    const double length = radius * (kFlameLength + kFlameFlicker * std::sin(kFlameRate * time));
    const Vec2 back = centre - direction * (0.6 * radius), across = direction.perpendicular() * (0.55 * radius);
    const Point flame[] = {pt(back + across), pt(back - direction * (0.4 * radius + length)), pt(back - across)};
    const Palette& p = Palette::greybox();
    list.polygon(flame, {p["flame"], p["explosion"], 1.0f});
}

Style style(const char* fill, const char* outline, float width = kOutline) {
    const Palette& p = Palette::greybox();
    return {p[fill], p[outline], width};
}

// Each ball kind by its look: heavy dark, steel mid grey, bouncy white, balloon blue.
Style ballStyle(ItemKind kind) {
    switch (kind) {
    case ItemKind::heavy: return style("ground", "ball_outline");
    case ItemKind::steel: return style("kinematic", "ball_outline");
    case ItemKind::balloon: return style("highlight", "ball_outline");
    default: return style("ball", "ball_outline");
    }
}

} // namespace

LevelView::LevelView(std::string levelName, render::Camera camera, render::FrameSize frame)
    : levelName_(std::move(levelName)), camera_(camera), frame_(frame) {}

void LevelView::drawBodies(const LevelRun& run, render::DrawList& list) const {
    const World& world = run.world();
    const float ppm = camera_.pixelsPerMetre(frame_);
    for (const Segment& s : world.segments()) {
        const bool thin = s.radius * ppm < 0.5 * kThinLine;
        list.capsule(pt(s.a), pt(s.b), static_cast<float>(s.radius), style("ground", "ground_outline", thin ? kThinLine : kOutline));
    }
    drawConveyors(world, list);
    drawRopes(world, list);
    drawRigidBodies(world, list);
    drawAirDrag(world, list);
    // Items' circles are drawn by drawItems; the plain ones here, projectiles with their arrow.
    std::vector<char> itemCircle(world.circles().size(), 0);
    for (std::size_t i = 0; i < run.items().size(); ++i)
        if (run.states()[i].firstCircle >= 0) itemCircle[static_cast<std::size_t>(run.states()[i].firstCircle)] = 1;
    for (std::size_t i = 0; i < world.circles().size(); ++i) {
        if (itemCircle[i]) continue;
        const Circle& c = world.circles()[i];
        const Style look = c.motion == Motion::dynamic ? style("ball", "ball_outline")
                         : c.motion == Motion::kinematic ? style("kinematic", "kinematic_outline")
                                                          : style("ground", "ground_outline");
        list.circleWithSpoke(pt(c.position), static_cast<float>(c.radius), static_cast<float>(c.velocity.angle()), look);
        if (run.isProjectile(static_cast<int>(i)))
            list.arrow(pt(c.position), pt(c.position + c.velocity * kArrowSeconds), 2.0f, Palette::greybox()["arrow"]);
    }
}

void LevelView::drawItems(const LevelRun& run, render::DrawList& list) const {
    const Palette& palette = Palette::greybox();
    const World& world = run.world();
    const auto& goal = run.goal();
    for (std::size_t i = 0; i < run.items().size(); ++i) {
        const ItemDesc& item = run.items()[i];
        const ItemState& state = run.states()[i];
        const Vec2 at = run.itemPosition(static_cast<int>(i));
        const float r = static_cast<float>(item.size);
        switch (item.kind) {
        case ItemKind::cannon: {
            // The barrel turns to the aim; before the shot, the arc it would fly is drawn.
            const Vec2 dir = Vec2::fromAngle(state.aim);
            if (!state.fired) {
                const auto arc = predictedArc(item.position, run.launchVelocity(static_cast<int>(i)), world.def().gravity,
                                              kArcSeconds, kArcPoints, world.def().bounds);
                std::vector<Point> points;
                for (Vec2 p : arc) points.push_back(pt(p));
                if (points.size() >= 2) list.polyline(points, kArcWidth, palette["arrow"], palette["arrow"].withAlpha(0));
            }
            list.box(pt(item.position + dir * (0.5 * kBarrelLength)), {static_cast<float>(0.5 * kBarrelLength), static_cast<float>(kBarrelHalfWidth)},
                     static_cast<float>(state.aim), style("box", "box_outline"));
            list.circle(pt(item.position), 0.25f, style("ground", "ground_outline"));
            break;
        }
        case ItemKind::target: {
            list.circle(pt(at), r, style(state.hit ? "highlight" : "goal", "ground_outline"));
            list.ring(pt(at), 0.55f * r, 2.0f, palette["background"]);
            break;
        }
        case ItemKind::switchItem:
            list.box(pt(at), {r, 0.6f * r}, 0.0f, style(state.hit ? "highlight" : "box", "box_outline"));
            break;
        case ItemKind::bomb:
            if (state.detonatedAt) {
                const double age = world.time() - *state.detonatedAt;
                if (age < kRingSeconds)
                    list.ring(pt(item.position), static_cast<float>(item.blastRadius * std::max(0.05, age / kRingSeconds)), 4.0f,
                              palette["explosion"]);
            } else {
                list.circle(pt(at), r, style("ground_outline", "ball_outline"));
                list.line(pt(at + Vec2{0.0, item.size}), pt(at + Vec2{0.4 * item.size, 1.5 * item.size}), 3.0f, palette["explosion"]);
            }
            break;
        case ItemKind::bumper:
            list.circle(pt(at), r, style("box", "arrow", 3.0f));
            break;
        case ItemKind::magnet: {
            // Red when pulling, grey when switched off; the faint ring is how far it reaches.
            const bool on = world.fields().magnets[static_cast<std::size_t>(state.field)].on;
            if (on && std::isfinite(item.reach)) list.ring(pt(at), static_cast<float>(item.reach), 1.5f, palette["magnet"].withAlpha(0x50));
            list.circle(pt(at), r, style(on ? "magnet" : "box", "ball_outline"));
            list.box(pt(at - Vec2{0.0, 0.5 * item.size}), {0.6f * r, 0.2f * r}, 0.0f, style("ball", "ball_outline"));
            break;
        }
        case ItemKind::fan: {
            const Wind& wind = world.fields().winds[static_cast<std::size_t>(state.field)];
            // The motor sits behind the housing (drawn with the segments), on the side the air comes from.
            const Vec2 back = item.position - wind.direction * 0.2;
            list.box(pt(back), {0.2f, static_cast<float>(0.25 * item.size)}, static_cast<float>(item.angle), style(wind.on ? "box" : "ground", "box_outline"));
            if (wind.on) drawWind(wind, world.time(), list);
            break;
        }
        case ItemKind::rocket: {
            const Circle& c = world.circles()[static_cast<std::size_t>(state.firstCircle)];
            const Thruster& thruster = world.fields().thrusters[static_cast<std::size_t>(state.field)];
            const Vec2 direction = Vec2::fromAngle(item.angle);
            const double t = world.time();
            if (t >= thruster.start && t < thruster.end) drawFlame(c.position, c.radius, direction, t, list);
            // Its body with an arrow through it: the way the thrust pushes, lit or not.
            list.circle(pt(c.position), static_cast<float>(c.radius), style("box", "ball_outline"));
            list.arrow(pt(c.position - direction * (0.7 * c.radius)), pt(c.position + direction * (0.9 * c.radius)), 2.5f, palette["explosion"]);
            break;
        }
        case ItemKind::bucket: {
            const bool isGoal = goal && goal->kind == GoalKind::ballInBucket && goal->item == item.name;
            const double h = 0.5 * item.size;
            // A tint inside the bucket marks where the ball must come to rest.
            if (isGoal)
                list.box(pt(item.position + Vec2{0.0, 0.5 * item.height}), {static_cast<float>(h), static_cast<float>(0.5 * item.height)}, 0.0f,
                         {palette["goal"].withAlpha(0x60), render::Color::transparent(), 0.0f});
            break;
        }
        default:
            if (isBall(item.kind) && state.firstCircle >= 0) {
                const Circle& c = world.circles()[static_cast<std::size_t>(state.firstCircle)];
                if (item.kind == ItemKind::balloon) list.line(pt(c.position - Vec2{0.0, c.radius}), pt(c.position - Vec2{0.0, 2.5 * c.radius}), 1.5f, palette["ball_outline"]);
                list.circleWithSpoke(pt(c.position), static_cast<float>(c.radius), static_cast<float>(c.velocity.angle()), ballStyle(item.kind));
                if (item.kind == ItemKind::bouncy) list.ring(pt(c.position), 0.6f * static_cast<float>(c.radius), 1.5f, palette["arrow"]);
            }
            break;
        }
    }
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
    list.box({0.5f * (low.x + high.x), 0.5f * (low.y + high.y)}, {0.5f * (high.x - low.x), 0.5f * (high.y - low.y)}, 0.0f,
             {palette["background"].withAlpha(0xd8), render::Color::transparent(), 0.0f});
    char line[256];
    std::snprintf(line, sizeof line, "%s   frame %lld   t = %.3f s", levelName_.c_str(), static_cast<long long>(frame), run.world().time());
    list.text(kHudMargin, kHudMargin, line, palette["hud_text"], kHudScale);
    list.text(kHudMargin, kHudMargin + kHudLineHeight, goalLine(run), run.goalFrame() ? palette["goal"] : palette["hud_text"], kHudScale);
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
