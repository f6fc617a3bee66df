#pragma once
// Internal: the solver's uniform-grid broadphase. Not part of the public API.
//
// Every step the grid is laid over the region the dynamic circles can reach, with cells about one
// typical circle's box wide. A circle whose box fits in a cell is filed once, in the cell of its
// centre, and found from the 3x3 cells around; a larger circle is filed in every cell its box
// covers; a segment (however long) in every cell its swept capsule crosses, row by row, so a 20 m
// wall costs cells along its length, not its bounding box. Buffers only grow: no allocation once
// warmed up, and every list comes out in index order within a cell, so pairs are deterministic.

#include "rube/physics/vec2.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace rube {

/// An axis-aligned box by its corners.
struct BoundingBox {
    Vec2 min;
    Vec2 max;
    /// True when the two boxes share at least a point.
    bool overlaps(const BoundingBox& o) const {
        return min.x <= o.max.x && o.min.x <= max.x && min.y <= o.max.y && o.min.y <= max.y;
    }
};

/// A segment as the broadphase sees it: its ends at the start of the step, how far they move over the
/// step, and how far its surface reaches from its core line (its radius).
struct SweptSegment {
    Vec2 a;             ///< first end at the start of the step
    Vec2 b;             ///< second end at the start of the step
    Vec2 motion;        ///< how far both ends move over the step
    double reach = 0.0; ///< the segment's radius
};

/// A candidate pair: dynamic circle `circle` (the lower index when both are dynamic) and `other`, a
/// solver body index (circles first, then segments).
struct CandidatePair {
    int circle = 0; ///< dynamic circle index
    int other = 0;  ///< solver body index of the other body
};

/// Items per cell in compressed rows: cell c holds items[start[c] .. start[c + 1]).
struct CellTable {
    std::vector<int> start; ///< per cell, then one past the last: where its items begin
    std::vector<int> items; ///< item indices, cell after cell
};

/// The uniform grid: build it from this step's boxes, then ask it for candidate pairs.
class BroadphaseGrid {
public:
    /// Files circles (by the boxes they may sweep this step) and segments (by swept capsule) into a
    /// grid over `region` with cells of about `cellSize`, enlarged past `maxCells` cells.
    void build(std::span<const BoundingBox> filingBoxes, std::span<const SweptSegment> segments, BoundingBox region,
               double cellSize, int maxCells);

    /// Appends every pair whose contact boxes (within the filing boxes) overlap and in which a circle
    /// is dynamic, each pair once.
    void findPairs(std::span<const BoundingBox> circleBoxes, std::span<const BoundingBox> segmentBoxes,
                   std::span<const std::uint8_t> isDynamic, std::vector<CandidatePair>& pairs);

    /// Lists, once each, the circles and segments filed near `box` (a superset of those overlapping
    /// it). Returns false, listing nothing, when the box leaves the grid or spans more than
    /// `maxCellsPerAxis` cells: the caller must then look at every shape.
    bool query(const BoundingBox& box, int maxCellsPerAxis, std::vector<int>& circles, std::vector<int>& segments);

    /// The cell size the last build used (the requested one, or larger when capped).
    double cellSize() const { return cellSize_; }

private:
    /// The range of cells a box covers, clamped into the grid (clamping keeps overlaps overlapping).
    void cellRange(const BoundingBox& box, int& x0, int& y0, int& x1, int& y1) const;
    /// The cell holding point p, clamped into the grid.
    int cellOf(Vec2 p) const;
    /// Fills a cell table from the (cell, item) entries gathered, items in filing order per cell.
    void fillTable(CellTable& table) const;
    /// Stamps item k of a multi-cell list; false when this query has seen it already.
    static bool firstVisit(std::vector<int>& stamps, int k, int stamp);

    Vec2 origin_;
    double cellSize_ = 1.0;
    double invCellSize_ = 1.0;
    int nx_ = 1;
    int ny_ = 1;
    BoundingBox bounds_;                    // the grid's extent
    CellTable small_;                       // circles whose box fits a cell: by centre, once
    CellTable large_;                       // larger circles: every cell their box covers
    CellTable segments_;                    // segments: every cell their swept capsule crosses
    std::vector<std::uint8_t> isSmall_;     // per circle
    std::vector<int> homeCell_;             // per circle: its centre's cell
    std::vector<std::uint32_t> entryCells_; // scratch: (cell, item) entries before sorting
    std::vector<int> entryItems_;
    std::vector<int> circleStamp_, segmentStamp_; // last query that saw the item, to report it once
    int stamp_ = 0;
};

} // namespace rube
