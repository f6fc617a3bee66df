// HUD text: stb_easy_font (public domain, from libstb-dev) turns a string into axis-aligned
// rectangles, one per stroke of each glyph; each becomes a box instance of the shape shader.
// At an integer scale and position the rectangles sit on pixel boundaries, so text is crisp.
#include "shape_instance.hpp"

#include "rube/render/draw_list.hpp"

#include <stb_easy_font.h>

#include <string>

namespace rube::render {

void appendTextInstances(std::string_view text, int x, int y, int scale, Color color, FrameSize frame,
                         std::vector<ShapeInstance>& out) {
    if (text.empty()) return;
    // stb wants a mutable, NUL-terminated string and writes 4 vertices of 16 bytes per
    // rectangle; glyphs have at most a dozen strokes, so 1 KB per character is ample.
    thread_local std::string buffer;
    thread_local std::vector<float> vertices; // floats: stb writes through float pointers
    buffer.assign(text);
    vertices.resize(text.size() * 256 + 64);
    int rectangles = stb_easy_font_print(0.0f, 0.0f, buffer.data(), nullptr, vertices.data(),
                                         static_cast<int>(vertices.size() * sizeof(float)));

    const float s = static_cast<float>(scale);
    const float height = static_cast<float>(frame.height);
    for (int i = 0; i < rectangles; ++i) {
        // Vertex 0 is the top-left corner, vertex 2 the bottom-right (font units, y down);
        // each vertex is 4 floats (x, y, z, packed colour).
        const float* v = vertices.data() + static_cast<std::size_t>(i) * 16;
        float left = static_cast<float>(x) + v[0] * s;
        float right = static_cast<float>(x) + v[8] * s;
        float top = height - (static_cast<float>(y) + v[1] * s);
        float bottom = height - (static_cast<float>(y) + v[9] * s);
        ShapeInstance box;
        box.kindAndFlags = static_cast<std::uint32_t>(ShapeKind::box);
        box.geomA[0] = 0.5f * (left + right);
        box.geomA[1] = 0.5f * (top + bottom);
        box.geomA[2] = 0.5f * (right - left);
        box.geomA[3] = 0.5f * (top - bottom);
        box.geomB[0] = 1.0f; // cos 0: not rotated
        box.geomB[1] = 0.0f;
        box.fill = color;
        box.outline = color;
        out.push_back(box);
    }
}

int textWidth(std::string_view text, int scale) {
    if (text.empty()) return 0;
    thread_local std::string buffer;
    buffer.assign(text);
    // stb_easy_font_width measures in font units; the printer draws each unit `scale` pixels wide.
    return stb_easy_font_width(buffer.data()) * (scale < 1 ? 1 : scale);
}

} // namespace rube::render
