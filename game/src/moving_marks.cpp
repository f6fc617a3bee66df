// Marks that show what moves where the bodies alone would not: a conveyor's belt running along its
// segment, and water as a band over the pool. Shared by the scene view and the level view, and a
// function of the World alone (its time, never the wall clock), so every frame is reproducible.
#include "scene_view.hpp"

#include "rube/render/palette.hpp"

#include <algorithm>
#include <cmath>

namespace rube::game {

namespace {

constexpr double kChevronSpacing = 0.5; // m between a belt's chevrons
constexpr double kChevronMinHalf = 0.1; // m: a chevron's half-height on a thin belt (it is at least the belt's radius)
constexpr float kChevronWidth = 2.0f;   // pixels
constexpr float kWaterEdgeWidth = 2.0f; // pixels: the pool's outline, its top line the surface

render::Point toPoint(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

// One belt: chevrons ">" along a->b pointing the way its surface runs, each moved on by
// surfaceSpeed * time (mod the spacing), so the chevrons travel with the belt at its speed.
void drawBelt(const Segment& s, double time, render::Color color, render::DrawList& list) {
    const Vec2 ab = s.b - s.a;
    const double length = ab.length();
    if (length <= 0.0) return;
    const Vec2 along = ab / length * (s.surfaceSpeed > 0.0 ? 1.0 : -1.0);
    const Vec2 across = along.perpendicular();
    const double half = std::max(s.radius, kChevronMinHalf);
    // The phase in [0, spacing): fmod keeps the sign of its argument, so a belt running b->a is wrapped too.
    double phase = std::fmod(std::abs(s.surfaceSpeed) * time, kChevronSpacing);
    if (phase < 0.0) phase += kChevronSpacing;
    // Distances measured from the end the belt runs from, so the chevrons come in there and leave at the other.
    const Vec2 from = s.surfaceSpeed > 0.0 ? s.a : s.b;
    for (double d = phase + half; d <= length; d += kChevronSpacing) {
        const Vec2 tip = from + along * d;
        const Vec2 tail = tip - along * half;
        list.line(toPoint(tail + across * half), toPoint(tip), kChevronWidth, color);
        list.line(toPoint(tail - across * half), toPoint(tip), kChevronWidth, color);
    }
}

} // namespace

void drawConveyors(const World& world, render::DrawList& list) {
    const render::Color color = render::Palette::greybox()["arrow"];
    for (const Segment& s : world.segments())
        if (s.surfaceSpeed != 0.0) drawBelt(s, world.time(), color, list);
}

void drawWaters(const World& world, render::DrawList& list) {
    const render::Palette& palette = render::Palette::greybox();
    for (const Water& water : world.fields().waters) {
        const Vec2 centre = (water.min + water.max) * 0.5, half = (water.max - water.min) * 0.5;
        list.box(toPoint(centre), toPoint(half), 0.0f, {palette["water"], palette["water"].withAlpha(0xc0), kWaterEdgeWidth});
    }
}

} // namespace rube::game
