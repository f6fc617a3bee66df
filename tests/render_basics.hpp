#pragma once
// The render-basics scene shared by the off-screen and the window screenshot tests: one of each
// primitive in the greybox palette, 16 m x 9 m, compared with screenshots/render-basics_0000.png.

#include "rube/render/draw_list.hpp"
#include "rube/render/palette.hpp"

namespace rube::render {

// The render-basics scene: one of each primitive, in the greybox palette. `ballShift` moves
// the big ball to the right, in metres (0.1 m is 3 pixels).
inline DrawList renderBasics(float ballShift = 0.0f) {
    const Palette& palette = Palette::greybox();
    const Style ground{palette["ground"], palette["ground_outline"], 1.5f};
    const Style ball{palette["ball"], palette["ball_outline"], 1.5f};
    DrawList list;
    list.background = palette["background"];
    const Point ramp[] = {{-8.0f, -4.5f}, {-3.0f, -4.5f}, {-3.0f, -4.0f}, {-5.0f, -3.7f}, {-8.0f, -2.5f}};
    list.polygon(ramp, ground);
    list.capsule({-7.0f, -3.2f}, {7.0f, -3.6f}, 0.2f, ground);
    list.capsule({5.5f, 3.8f}, {7.5f, 0.5f}, 0.0f, ground); // a zero-thickness segment: a hairline
    const Point trail[] = {{-6.4f, 2.6f}, {-5.2f, 3.1f}, {-4.0f, 3.2f}, {-3.0f, 2.8f}, {-2.4f, 2.2f}};
    list.polyline(trail, 4.0f, palette["trail"].withAlpha(0), palette["trail"]);
    list.circleWithSpoke({-5.0f + ballShift, 0.0f}, 1.0f, 0.5f, ball);
    list.circleWithSpoke({-2.0f, 1.5f}, 0.6f, 2.0f, ball);
    list.circleWithSpoke({1.0f, -1.0f}, 0.8f, -1.0f, ball);
    list.box({4.5f, -2.0f}, {0.9f, 0.6f}, 0.3f, {palette["box"], palette["box_outline"], 1.5f}, 0.05f);
    list.arrow({1.0f, -1.0f}, {3.2f, 0.6f}, 3.0f, palette["arrow"]);
    list.ring({3.8f, 2.4f}, 1.1f, 3.0f, palette["explosion"]);
    list.text(8, 8, "render-basics  t = 1.25 s  3 balls", palette["hud_text"], 2);
    return list;
}

} // namespace rube::render
