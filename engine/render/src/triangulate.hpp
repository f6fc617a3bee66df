#pragma once
// Internal: ear-clipping triangulation of simple polygons, for DrawList::polygon.

#include "rube/render/draw_list.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace rube::render {

/// Appends the triangles of the simple polygon `points` (either winding) to `out`, with
/// indices offset by `firstIndex`, each counter-clockwise and with its boundary edges marked.
/// Degenerate (zero-area) ears are dropped. Self-intersecting input gives some covering of
/// the points, never a crash.
void triangulatePolygon(std::span<const Point> points, std::uint32_t firstIndex, std::vector<Triangle>& out);

} // namespace rube::render
