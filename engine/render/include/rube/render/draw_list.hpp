#pragma once
/// DrawList: what one frame shows, as a plain list of shapes in world units (metres, y up).
/// It knows nothing of physics or the game: the game fills it, the renderer draws it in order.

#include "rube/render/camera.hpp"
#include "rube/render/palette.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace rube::render {

/// How a closed shape is painted: its fill, and an outline drawn inside its edge so the
/// shape covers exactly its true extent.
struct Style {
    Color fill;
    Color outline;
    float outlineWidth = 1.5f; ///< pixels, so outlines stay crisp at any zoom; 0 for none
};

/// One triangle of a polygon: indices into DrawList::points(), counter-clockwise, and which
/// of its edges (bit i: from vertex i to i+1) lie on the polygon's boundary and are antialiased.
struct Triangle {
    std::uint32_t index[3] = {0, 0, 0};
    std::uint8_t boundaryEdges = 0;
};

/// The kinds of primitive. Geometry is in metres; strokes (lines, rings, outlines) in pixels.
namespace primitive {
/// A filled disc; with `spoke`, a line in the outline colour from the centre to the rim at
/// `angle` radians shows how far it has turned.
struct Circle {
    Point centre;
    float radius = 0;
    Style style;
    bool spoke = false;
    float angle = 0;
};
/// A segment a-b thickened by `radius` metres with rounded caps (a capsule); radius 0 gives
/// a hairline of the outline's width.
struct Capsule {
    Point a;
    Point b;
    float radius = 0;
    Style style;
};
/// A straight stroke `width` pixels wide with rounded ends.
struct Line {
    Point a;
    Point b;
    float width = 1;
    Color color;
};
/// A box of half extents `halfExtents` metres turned by `angle` radians about its centre.
struct Box {
    Point centre;
    Point halfExtents;
    float angle = 0;
    float cornerRadius = 0;
    Style style;
};
/// A simple polygon (any winding), stored as points and its triangulation.
struct Polygon {
    std::uint32_t firstPoint = 0, pointCount = 0, firstTriangle = 0, triangleCount = 0;
    Style style;
};
/// An open chain of strokes `width` pixels wide, its colour blending from `first` to `last`.
struct Polyline {
    std::uint32_t firstPoint = 0, pointCount = 0;
    float width = 1;
    Color first;
    Color last;
};
/// A stroke from tail to tip with a triangular head at the tip; sizes in pixels.
struct Arrow {
    Point tail;
    Point tip;
    float width = 2;
    Color color;
};
/// A circle's outline only, `width` pixels wide inside `radius` metres (explosions, highlights).
struct Ring {
    Point centre;
    float radius = 0;
    float width = 2;
    Color color;
};
/// A line of text at a pixel position measured from the frame's top-left corner (a HUD).
struct Text {
    int x = 0, y = 0;
    int scale = 2;
    Color color;
    std::uint32_t firstChar = 0, charCount = 0;
};
} // namespace primitive

/// Any one primitive.
using Primitive =
    std::variant<primitive::Circle, primitive::Capsule, primitive::Line, primitive::Box, primitive::Polygon,
                 primitive::Polyline, primitive::Arrow, primitive::Ring, primitive::Text>;

/// The shapes of one frame, drawn back to front in the order they were added. Reuse one list
/// across frames (clear() keeps its memory) to avoid allocating every frame.
class DrawList {
public:
    Color background{212, 212, 212, 255}; ///< the frame is cleared to this (palette "background")

    /// Forgets every primitive, keeping the memory for the next frame.
    void clear();

    /// A filled, outlined disc.
    void circle(Point centre, float radius, const Style& style);
    /// A disc with a spoke at `angle` radians (counter-clockwise from +x) showing its rotation.
    void circleWithSpoke(Point centre, float radius, float angle, const Style& style);
    /// A thick segment with rounded caps: everything within `radius` metres of a-b.
    void capsule(Point a, Point b, float radius, const Style& style);
    /// A stroke `width` pixels wide.
    void line(Point a, Point b, float width, Color color);
    /// A box turned by `angle` radians, optionally with corners rounded by `cornerRadius` metres.
    void box(Point centre, Point halfExtents, float angle, const Style& style, float cornerRadius = 0.0f);
    /// A simple polygon (no self-intersections, either winding), triangulated when added; its
    /// outline, unlike other shapes', is centred on the edges.
    void polygon(std::span<const Point> points, const Style& style);
    /// A trail: strokes through `points`, `width` pixels wide, one colour throughout.
    void polyline(std::span<const Point> points, float width, Color color);
    /// A trail whose colour blends from `first` (at points.front()) to `last`, e.g. to fade out.
    void polyline(std::span<const Point> points, float width, Color first, Color last);
    /// An arrow from tail to tip, e.g. a velocity; `width` pixels, the head scaled to match.
    void arrow(Point tail, Point tip, float width, Color color);
    /// An expanding explosion or a highlight: a ring `width` pixels wide inside `radius` metres.
    void ring(Point centre, float radius, float width, Color color);
    /// A HUD line at (x, y) pixels from the top-left corner, `scale` pixels per font unit
    /// (glyphs are about 7 units tall); characters outside printable ASCII show as '?'.
    void text(int x, int y, std::string_view text, Color color, int scale = 2);

    /// The primitives in drawing order.
    std::span<const Primitive> primitives() const { return primitives_; }
    /// The points of every polygon and polyline.
    std::span<const Point> points() const { return points_; }
    /// The triangles of every polygon.
    std::span<const Triangle> triangles() const { return triangles_; }
    /// The characters of every text, back to back.
    std::string_view characters() const { return characters_; }
    /// The text of one Text primitive.
    std::string_view textOf(const primitive::Text& text) const;
    /// How many primitives the list holds.
    std::size_t size() const { return primitives_.size(); }

private:
    std::vector<Primitive> primitives_;
    std::vector<Point> points_;
    std::vector<Triangle> triangles_;
    std::string characters_;
};

/// How wide `text` is drawn at `scale`, in pixels: for laying out HUD lines within a frame (the
/// font is proportional; a newline starts a new line, and the widest line counts).
int textWidth(std::string_view text, int scale = 2);

} // namespace rube::render
