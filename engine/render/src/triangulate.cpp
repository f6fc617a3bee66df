// Ear clipping: repeatedly cut off a convex corner whose triangle holds no other vertex.
// O(n^2) to O(n^3) in the number of points, fine for the handful of points a level polygon has.
#include "triangulate.hpp"

namespace rube::render {
namespace {

double cross(Point o, Point a, Point b) {
    return (static_cast<double>(a.x) - o.x) * (static_cast<double>(b.y) - o.y) -
           (static_cast<double>(a.y) - o.y) * (static_cast<double>(b.x) - o.x);
}

// Inside or on the edge of the counter-clockwise triangle abc.
bool inTriangle(Point p, Point a, Point b, Point c) {
    return cross(a, b, p) >= 0.0 && cross(b, c, p) >= 0.0 && cross(c, a, p) >= 0.0;
}

bool samePoint(Point a, Point b) { return a.x == b.x && a.y == b.y; }

} // namespace

void triangulatePolygon(std::span<const Point> points, std::uint32_t firstIndex, std::vector<Triangle>& out) {
    const std::size_t n = points.size();
    if (n < 3) return;

    // Shoelace area: work counter-clockwise whatever the caller's winding.
    double twiceArea = 0.0;
    for (std::size_t i = 0; i < n; ++i) twiceArea += cross({0, 0}, points[i], points[(i + 1) % n]);
    std::vector<std::uint32_t> ring(n);
    for (std::size_t i = 0; i < n; ++i) ring[i] = static_cast<std::uint32_t>(twiceArea >= 0.0 ? i : n - 1 - i);
    // onBoundary[i]: the edge from ring[i] to ring[i+1] is part of the polygon's outline; edges
    // made by cutting ears are diagonals inside it, drawn without antialiasing.
    std::vector<bool> onBoundary(n, true);

    auto emit = [&](std::size_t a, std::size_t b, std::size_t c, bool ab, bool bc, bool ca) {
        if (cross(points[ring[a]], points[ring[b]], points[ring[c]]) <= 0.0) return; // no area
        Triangle t;
        t.index[0] = firstIndex + ring[a];
        t.index[1] = firstIndex + ring[b];
        t.index[2] = firstIndex + ring[c];
        t.boundaryEdges = static_cast<std::uint8_t>((ab ? 1 : 0) | (bc ? 2 : 0) | (ca ? 4 : 0));
        out.push_back(t);
    };

    while (ring.size() > 3) {
        const std::size_t m = ring.size();
        std::size_t ear = m;
        std::size_t fallback = m; // a convex corner, used when no clean ear exists (bad input)
        for (std::size_t i = 0; i < m && ear == m; ++i) {
            Point a = points[ring[(i + m - 1) % m]];
            Point b = points[ring[i]];
            Point c = points[ring[(i + 1) % m]];
            double turn = cross(a, b, c);
            if (turn == 0.0) {
                ear = i; // collinear or repeated point: removing it changes nothing
                break;
            }
            if (turn < 0.0) continue; // reflex corner
            if (fallback == m) fallback = i;
            bool empty = true;
            for (std::size_t j = 0; j < m && empty; ++j) {
                Point p = points[ring[j]];
                if (samePoint(p, a) || samePoint(p, b) || samePoint(p, c)) continue;
                empty = !inTriangle(p, a, b, c);
            }
            if (empty) ear = i;
        }
        if (ear == m) ear = fallback;
        if (ear == m) return; // nothing convex left: the input was not a simple polygon

        std::size_t prev = (ear + m - 1) % m;
        std::size_t next = (ear + 1) % m;
        emit(prev, ear, next, onBoundary[prev], onBoundary[ear], false);
        // The new edge prev-next replaces two; it is outline only if both were (a collinear point).
        onBoundary[prev] = onBoundary[prev] && onBoundary[ear] &&
                           cross(points[ring[prev]], points[ring[ear]], points[ring[next]]) == 0.0;
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(ear));
        onBoundary.erase(onBoundary.begin() + static_cast<std::ptrdiff_t>(ear));
    }
    emit(0, 1, 2, onBoundary[0], onBoundary[1], onBoundary[2]);
}

} // namespace rube::render
