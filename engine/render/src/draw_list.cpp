// DrawList: records primitives; polygons are triangulated here, once, rather than every frame.
#include "rube/render/draw_list.hpp"

#include "triangulate.hpp"

namespace rube::render {

void DrawList::clear() {
    primitives_.clear();
    points_.clear();
    triangles_.clear();
    characters_.clear();
}

void DrawList::circle(Point centre, float radius, const Style& style) {
    primitives_.emplace_back(primitive::Circle{centre, radius, style, false, 0.0f});
}

void DrawList::circleWithSpoke(Point centre, float radius, float angle, const Style& style) {
    primitives_.emplace_back(primitive::Circle{centre, radius, style, true, angle});
}

void DrawList::capsule(Point a, Point b, float radius, const Style& style) {
    primitives_.emplace_back(primitive::Capsule{a, b, radius, style});
}

void DrawList::line(Point a, Point b, float width, Color color) {
    primitives_.emplace_back(primitive::Line{a, b, width, color});
}

void DrawList::box(Point centre, Point halfExtents, float angle, const Style& style, float cornerRadius) {
    primitives_.emplace_back(primitive::Box{centre, halfExtents, angle, cornerRadius, style});
}

void DrawList::polygon(std::span<const Point> points, const Style& style) {
    primitive::Polygon polygon;
    polygon.firstPoint = static_cast<std::uint32_t>(points_.size());
    polygon.pointCount = static_cast<std::uint32_t>(points.size());
    polygon.firstTriangle = static_cast<std::uint32_t>(triangles_.size());
    polygon.style = style;
    points_.insert(points_.end(), points.begin(), points.end());
    triangulatePolygon(points, polygon.firstPoint, triangles_);
    polygon.triangleCount = static_cast<std::uint32_t>(triangles_.size()) - polygon.firstTriangle;
    primitives_.emplace_back(polygon);
}

void DrawList::polyline(std::span<const Point> points, float width, Color color) {
    polyline(points, width, color, color);
}

void DrawList::polyline(std::span<const Point> points, float width, Color first, Color last) {
    primitive::Polyline polyline;
    polyline.firstPoint = static_cast<std::uint32_t>(points_.size());
    polyline.pointCount = static_cast<std::uint32_t>(points.size());
    polyline.width = width;
    polyline.first = first;
    polyline.last = last;
    points_.insert(points_.end(), points.begin(), points.end());
    primitives_.emplace_back(polyline);
}

void DrawList::arrow(Point tail, Point tip, float width, Color color) {
    primitives_.emplace_back(primitive::Arrow{tail, tip, width, color});
}

void DrawList::ring(Point centre, float radius, float width, Color color) {
    primitives_.emplace_back(primitive::Ring{centre, radius, width, color});
}

void DrawList::text(int x, int y, std::string_view text, Color color, int scale) {
    primitive::Text entry;
    entry.x = x;
    entry.y = y;
    entry.scale = scale < 1 ? 1 : scale;
    entry.color = color;
    entry.firstChar = static_cast<std::uint32_t>(characters_.size());
    entry.charCount = static_cast<std::uint32_t>(text.size());
    // The font covers printable ASCII only (and reads outside its tables for anything else).
    for (char c : text) {
        bool printable = (c >= 32 && c <= 126) || c == '\n';
        characters_.push_back(printable ? c : '?');
    }
    primitives_.emplace_back(entry);
}

std::string_view DrawList::textOf(const primitive::Text& text) const {
    return std::string_view(characters_).substr(text.firstChar, text.charCount);
}

} // namespace rube::render
