// From a DrawList in world metres to shape instances in pixels. The camera is applied here, on
// the CPU, so the shaders work in pixels and every antialiased edge is one pixel wide at any zoom.
#include "shape_instance.hpp"

#include <algorithm>
#include <cmath>

namespace rube::render {
namespace {

struct Builder {
    const DrawList& list;
    const Camera& camera;
    FrameSize frame;
    float scale; // pixels per metre
    std::vector<ShapeInstance>& out;
    std::vector<Point> pixels;      // scratch: a chain's points in pixels
    std::vector<Point> chain;       // scratch: the same without near-duplicates
    std::vector<float> jointAngles; // scratch: bisector normal at each point of the chain

    Point px(Point world) const { return camera.toPixels(world, frame); }

    void disc(Point centre, float radius, float outlineWidth, Color fill, Color outline) {
        ShapeInstance s;
        s.kindAndFlags = static_cast<std::uint32_t>(ShapeKind::disc);
        s.geomA[0] = centre.x;
        s.geomA[1] = centre.y;
        s.geomA[2] = radius;
        s.outlineWidth = outlineWidth;
        s.fill = fill;
        s.outline = outline;
        out.push_back(s);
    }

    void capsule(Point a, Point b, float radius, float outlineWidth, Color fill, Color outline) {
        ShapeInstance s;
        s.kindAndFlags = static_cast<std::uint32_t>(ShapeKind::capsule);
        s.geomA[0] = a.x;
        s.geomA[1] = a.y;
        s.geomA[2] = b.x;
        s.geomA[3] = b.y;
        s.geomB[0] = radius;
        s.outlineWidth = outlineWidth;
        s.fill = fill;
        s.outline = outline;
        out.push_back(s);
    }

    // A stroke in pixels: a capsule of one colour.
    void stroke(Point a, Point b, float width, Color color) {
        capsule(a, b, 0.5f * std::max(width, 0.0f), 0.0f, color, color);
    }

    // Strokes through `points` (pixels), the pieces cut at the bisector of each joint so that
    // they tile the chain's outline without overlap (translucent trails stay even); the round
    // caps of two pieces make a round join. Points closer than half a pixel to the previous one
    // are skipped: such slivers add nothing and make the bisectors unstable. Where the chain
    // turns back on itself within a stroke's width (a hairpin), neighbouring bisectors cross
    // inside the stroke and a pixel or two may be drawn twice or not at all; trails tolerate it.
    template <class ColourOfPiece>
    void strokeChain(std::span<const Point> points, bool closed, float width, ColourOfPiece colourOfPiece) {
        chain.clear();
        for (Point p : points) {
            if (chain.empty() || std::hypot(p.x - chain.back().x, p.y - chain.back().y) >= 0.5f) chain.push_back(p);
        }
        if (closed && chain.size() > 2 &&
            std::hypot(chain.front().x - chain.back().x, chain.front().y - chain.back().y) < 0.5f) {
            chain.pop_back();
        }
        const std::size_t n = chain.size();
        if (n == 1) {
            stroke(chain[0], chain[0], width, colourOfPiece(0, 1)); // a dot
            return;
        }
        if (n == 2) closed = false;
        const std::size_t pieces = closed ? n : n - 1;
        auto direction = [&](std::size_t piece) {
            Point a = chain[piece];
            Point b = chain[(piece + 1) % n];
            float length = std::hypot(b.x - a.x, b.y - a.y);
            return Point{(b.x - a.x) / length, (b.y - a.y) / length};
        };
        // jointAngle[k]: direction of the bisector normal at chain[k], between pieces k-1 and k.
        jointAngles.assign(n, 0.0f);
        for (std::size_t k = 0; k < n; ++k) {
            if (!closed && (k == 0 || k == n - 1)) continue;
            Point in = direction((k + pieces - 1) % pieces);
            Point out = direction(k);
            Point normal{in.x + out.x, in.y + out.y};
            if (std::hypot(normal.x, normal.y) < 1e-4f) normal = out; // a hairpin: any cut will do
            jointAngles[k] = std::atan2(normal.y, normal.x);
        }
        for (std::size_t piece = 0; piece < pieces; ++piece) {
            std::size_t next = (piece + 1) % n;
            Color colour = colourOfPiece(piece, pieces);
            capsule(chain[piece], chain[next], 0.5f * std::max(width, 0.0f), 0.0f, colour, colour);
            ShapeInstance& s = out.back();
            bool clipStart = closed || piece > 0;
            bool clipEnd = closed || piece + 1 < pieces;
            s.geomB[1] = jointAngles[piece];
            s.geomB[2] = jointAngles[next];
            s.kindAndFlags |= (clipStart ? 1u << 8 : 0u) | (clipEnd ? 1u << 9 : 0u);
        }
    }

    void triangle(Point p0, Point p1, Point p2, std::uint8_t boundaryEdges, Color color) {
        ShapeInstance s;
        s.kindAndFlags = static_cast<std::uint32_t>(ShapeKind::triangle) |
                         (static_cast<std::uint32_t>(boundaryEdges & 7u) << 8);
        s.geomA[0] = p0.x;
        s.geomA[1] = p0.y;
        s.geomA[2] = p1.x;
        s.geomA[3] = p1.y;
        s.geomB[0] = p2.x;
        s.geomB[1] = p2.y;
        s.fill = color;
        s.outline = color;
        out.push_back(s);
    }

    void operator()(const primitive::Circle& c) {
        Point centre = px(c.centre);
        float radius = c.radius * scale;
        disc(centre, radius, c.style.outlineWidth, c.style.fill, c.style.outline);
        if (c.spoke) {
            // Stop the spoke's round cap at the rim rather than past it.
            float width = std::max(c.style.outlineWidth, 1.0f);
            float length = std::max(radius - 0.5f * width, 0.0f);
            Point rim{centre.x + length * std::cos(c.angle), centre.y + length * std::sin(c.angle)};
            stroke(centre, rim, width, c.style.outline);
        }
    }

    void operator()(const primitive::Capsule& c) {
        // Never thinner than its outline (a zero-radius segment is a hairline in the outline
        // colour) nor than half a pixel (so it never vanishes).
        float radius = std::max({c.radius * scale, 0.5f * c.style.outlineWidth, 0.5f});
        capsule(px(c.a), px(c.b), radius, c.style.outlineWidth, c.style.fill, c.style.outline);
    }

    void operator()(const primitive::Line& l) { stroke(px(l.a), px(l.b), l.width, l.color); }

    void operator()(const primitive::Box& b) {
        ShapeInstance s;
        s.kindAndFlags = static_cast<std::uint32_t>(ShapeKind::box);
        Point centre = px(b.centre);
        float hx = std::abs(b.halfExtents.x) * scale;
        float hy = std::abs(b.halfExtents.y) * scale;
        s.geomA[0] = centre.x;
        s.geomA[1] = centre.y;
        s.geomA[2] = hx;
        s.geomA[3] = hy;
        s.geomB[0] = std::cos(b.angle);
        s.geomB[1] = std::sin(b.angle);
        s.geomB[2] = std::clamp(b.cornerRadius * scale, 0.0f, std::min(hx, hy));
        s.outlineWidth = b.style.outlineWidth;
        s.fill = b.style.fill;
        s.outline = b.style.outline;
        out.push_back(s);
    }

    void operator()(const primitive::Polygon& p) {
        auto points = list.points();
        auto triangles = list.triangles().subspan(p.firstTriangle, p.triangleCount);
        for (const Triangle& t : triangles) {
            triangle(px(points[t.index[0]]), px(points[t.index[1]]), px(points[t.index[2]]), t.boundaryEdges,
                     p.style.fill);
        }
        // The outline is centred on the edges: a polygon has no cheap exact inward offset.
        if (p.style.outlineWidth > 0.0f && p.pointCount >= 2) {
            toPixels(points.subspan(p.firstPoint, p.pointCount));
            strokeChain(pixels, true, p.style.outlineWidth, [&](std::size_t, std::size_t) { return p.style.outline; });
        }
    }

    // Fills `pixels` with the world points mapped through the camera.
    void toPixels(std::span<const Point> world) {
        pixels.clear();
        for (Point w : world) pixels.push_back(px(w));
    }

    static std::uint8_t lerp(std::uint8_t a, std::uint8_t b, float t) {
        return static_cast<std::uint8_t>(
            std::lround(static_cast<float>(a) + (static_cast<float>(b) - static_cast<float>(a)) * t));
    }

    void operator()(const primitive::Polyline& p) {
        if (p.pointCount == 0) return;
        toPixels(list.points().subspan(p.firstPoint, p.pointCount));
        strokeChain(pixels, false, p.width, [&](std::size_t piece, std::size_t pieces) {
            // Each piece takes the colour at its middle, from `first` at the first point to `last`.
            float t = (static_cast<float>(piece) + 0.5f) / static_cast<float>(pieces);
            return Color{lerp(p.first.r, p.last.r, t), lerp(p.first.g, p.last.g, t), lerp(p.first.b, p.last.b, t),
                         lerp(p.first.a, p.last.a, t)};
        });
    }

    void operator()(const primitive::Arrow& a) {
        Point tail = px(a.tail);
        Point tip = px(a.tip);
        float dx = tip.x - tail.x;
        float dy = tip.y - tail.y;
        float length = std::sqrt(dx * dx + dy * dy);
        if (length < 1e-3f) return;
        Point u{dx / length, dy / length};
        Point n{-u.y, u.x};
        // The head grows with the stroke but never outgrows a short arrow.
        float head = std::min(3.0f * a.width + 6.0f, length);
        float halfWidth = 0.6f * head;
        // The shaft stops inside the head so its round cap does not poke out of the tip.
        Point shaftEnd{tip.x - u.x * 0.6f * head, tip.y - u.y * 0.6f * head};
        if (length > head) stroke(tail, shaftEnd, a.width, a.color);
        Point base{tip.x - u.x * head, tip.y - u.y * head};
        triangle(tip, {base.x + n.x * halfWidth, base.y + n.y * halfWidth},
                 {base.x - n.x * halfWidth, base.y - n.y * halfWidth}, 7, a.color);
    }

    void operator()(const primitive::Ring& r) {
        disc(px(r.centre), r.radius * scale, std::max(r.width, 0.0f), Color::transparent(), r.color);
    }

    void operator()(const primitive::Text& t) {
        appendTextInstances(list.textOf(t), t.x, t.y, t.scale, t.color, frame, out);
    }
};

} // namespace

void buildInstances(const DrawList& list, const Camera& camera, FrameSize frame, std::vector<ShapeInstance>& out) {
    out.clear();
    out.reserve(list.size() + list.size() / 2);
    Builder builder{list, camera, frame, camera.pixelsPerMetre(frame), out, {}, {}, {}};
    for (const Primitive& p : list.primitives()) std::visit(builder, p);
}

} // namespace rube::render
