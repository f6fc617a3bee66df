// Marks that show what moves where the bodies alone would not: a conveyor's belt running along its
// segment, water as a band over the pool, and the air pushing back on balls that fly through drag. Shared by the scene
// view and the level view, and a function of the World alone (its time, never the wall clock), so every frame is
// reproducible.
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
constexpr double kStreakPerG =
    0.6; // m of air streak per g of drag deceleration: a ball at its terminal speed trails 0.6 m
constexpr double kStreakMax = 1.5;        // m: the longest streak, however fast the ball
constexpr double kStandardGravity = 9.81; // m/s^2: the streak's unit, so it reads the same in a world without gravity
constexpr float kStreakWidth = 2.0f;      // pixels

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

// Three streaks of air behind a ball, from its rim back along -v: as long as the air's push is strong.
void drawStreaks(const Circle& c, double length, render::Color color, render::DrawList& list) {
    const Vec2 back = c.velocity / -c.velocity.length();
    const Vec2 across = back.perpendicular();
    for (const double side : {-0.6, 0.0, 0.6}) {
        // A side streak starts on the rim (sqrt(1 - s^2) r behind the centre) and is a little shorter.
        const Vec2 start = c.position + across * (side * c.radius) + back * (std::sqrt(1.0 - side * side) * c.radius);
        const double reach = side == 0.0 ? length : 0.7 * length;
        list.line(toPoint(start), toPoint(start + back * reach), kStreakWidth, color);
    }
}

} // namespace

void drawAirDrag(const World& world, render::DrawList& list) {
    const AirDrag& drag = world.def().airDrag;
    if (!drag.active()) return;
    const render::Color color = render::Palette::greybox()["wind"];
    for (const Circle& c : world.circles()) {
        if (c.motion != Motion::dynamic || c.inverseMass == 0.0) continue;
        const double speed = c.velocity.length();
        // The drag's deceleration |F| / m = k_linear |v| + k_quadratic |v|^2 (fields.hpp), in g.
        const double inG = (drag.linearRate(c.radius, c.inverseMass) +
                            drag.quadraticRate(c.radius, c.inverseMass) * speed) *
                           speed / kStandardGravity;
        const double length = std::min(kStreakPerG * inG, kStreakMax);
        if (length * 1e3 < c.radius) continue; // a ball at rest feels no air: no streak, nor a direction for one
        drawStreaks(c, length, color, list);
    }
}

void drawConveyors(const World& world, render::DrawList& list) {
    const render::Color color = render::Palette::greybox()["arrow"];
    for (const Segment& s : world.segments())
        if (s.surfaceSpeed != 0.0) drawBelt(s, world.time(), color, list);
}

void drawWaters(const World& world, render::DrawList& list) {
    const render::Palette& palette = render::Palette::greybox();
    for (const Water& water : world.fields().waters) {
        const Vec2 centre = (water.min + water.max) * 0.5, half = (water.max - water.min) * 0.5;
        list.box(toPoint(centre), toPoint(half), 0.0f,
                 {palette["water"], palette["water"].withAlpha(0xc0), kWaterEdgeWidth});
    }
}

} // namespace rube::game
