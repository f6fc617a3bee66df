// The solver's uniform-grid broadphase: cells of about one circle's box, rebuilt every step.
#include "broadphase_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rube {

namespace {

/// The x-extent of segment pq clipped to the horizontal band lo <= y <= hi, merged into [xMin, xMax].
void mergeClippedExtent(Vec2 p, Vec2 q, double lo, double hi, double& xMin, double& xMax) {
    double t0 = 0.0, t1 = 1.0;
    const double dy = q.y - p.y;
    if (dy == 0.0) {
        if (p.y < lo || p.y > hi) return;
    } else {
        // Parameters where the line crosses the band's edges: y(t) = p.y + t dy.
        const double ta = (lo - p.y) / dy, tb = (hi - p.y) / dy;
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
        if (t0 > t1) return;
    }
    const double xa = p.x + (q.x - p.x) * t0, xb = p.x + (q.x - p.x) * t1;
    xMin = std::min(xMin, std::min(xa, xb));
    xMax = std::max(xMax, std::max(xa, xb));
}

} // namespace

void BroadphaseGrid::cellRange(const BoundingBox& box, int& x0, int& y0, int& x1, int& y1) const {
    // clamp(floor(x), 0, n - 1) without floor, which is a library call on the build's x86-64 target:
    // for 0 <= x < n - 1 truncation is floor, and both ends are compared in double, so a far-away
    // body never overflows the int (a NaN, which the old form cast undefined, goes to cell 0).
    const auto cell = [this](double v, int n) {
        const double x = v * invCellSize_;
        return x >= static_cast<double>(n - 1) ? n - 1 : x > 0.0 ? static_cast<int>(x) : 0;
    };
    x0 = cell(box.min.x - origin_.x, nx_);
    x1 = cell(box.max.x - origin_.x, nx_);
    y0 = cell(box.min.y - origin_.y, ny_);
    y1 = cell(box.max.y - origin_.y, ny_);
}

int BroadphaseGrid::cellOf(Vec2 p) const {
    int x0, y0, x1, y1;
    cellRange(BoundingBox{p, p}, x0, y0, x1, y1);
    return y0 * nx_ + x0;
}

void BroadphaseGrid::fillTable(CellTable& table) const {
    // Counting sort by cell: stable, so each cell lists its items in the order they were filed.
    const std::size_t cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
    std::vector<int>& start = table.start;
    start.assign(cells + 1, 0);
    for (std::uint32_t c : entryCells_) ++start[c + 1];
    for (std::size_t c = 0; c < cells; ++c) start[c + 1] += start[c];
    table.items.resize(entryItems_.size());
    for (std::size_t e = 0; e < entryCells_.size(); ++e) table.items[start[entryCells_[e]]++] = entryItems_[e];
    for (std::size_t c = cells; c > 0; --c) start[c] = start[c - 1];
    start[0] = 0;
}

bool BroadphaseGrid::firstVisit(std::vector<int>& stamps, int k, int stamp) {
    if (stamps[k] == stamp) return false;
    stamps[k] = stamp;
    return true;
}

void BroadphaseGrid::build(std::span<const BoundingBox> filingBoxes, std::span<const SweptSegment> segments,
                           BoundingBox region, double cellSize, int maxCells) {
    const double w = std::max(region.max.x - region.min.x, 0.0);
    const double h = std::max(region.max.y - region.min.y, 0.0);
    // Start no smaller than what maxCells allows, then grow until the ceilings fit too.
    double c = std::max({cellSize, std::sqrt(w * h / maxCells), std::max(w, h) / maxCells, 1e-9});
    while (std::ceil(w / c) * std::ceil(h / c) > maxCells) c *= 1.25;
    cellSize_ = c;
    invCellSize_ = 1.0 / c;
    nx_ = std::max(1, static_cast<int>(std::ceil(w / c)));
    ny_ = std::max(1, static_cast<int>(std::ceil(h / c)));
    origin_ = region.min;
    bounds_ = BoundingBox{origin_, origin_ + Vec2{nx_ * c, ny_ * c}};

    const std::size_t circleCount = filingBoxes.size();
    isSmall_.resize(circleCount);
    homeCell_.resize(circleCount);
    entryCells_.clear();
    entryItems_.clear();
    for (std::size_t i = 0; i < circleCount; ++i) {
        const BoundingBox& box = filingBoxes[i];
        isSmall_[i] = box.max.x - box.min.x <= c && box.max.y - box.min.y <= c;
        homeCell_[i] = cellOf((box.min + box.max) * 0.5);
        if (!isSmall_[i]) continue;
        entryCells_.push_back(static_cast<std::uint32_t>(homeCell_[i]));
        entryItems_.push_back(static_cast<int>(i));
    }
    fillTable(small_);

    entryCells_.clear();
    entryItems_.clear();
    for (std::size_t i = 0; i < circleCount; ++i) {
        if (isSmall_[i]) continue;
        int x0, y0, x1, y1;
        cellRange(filingBoxes[i], x0, y0, x1, y1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                entryCells_.push_back(static_cast<std::uint32_t>(y * nx_ + x));
                entryItems_.push_back(static_cast<int>(i));
            }
    }
    fillTable(large_);

    entryCells_.clear();
    entryItems_.clear();
    for (std::size_t s = 0; s < segments.size(); ++s) {
        const SweptSegment& seg = segments[s];
        const double r = seg.reach;
        // The swept capsule is the convex hull of the four end positions, fattened by r.
        const Vec2 pts[4] = {seg.a, seg.b, seg.a + seg.motion, seg.b + seg.motion};
        BoundingBox box{pts[0], pts[0]};
        for (const Vec2& p : pts) {
            box.min = {std::min(box.min.x, p.x), std::min(box.min.y, p.y)};
            box.max = {std::max(box.max.x, p.x), std::max(box.max.y, p.y)};
        }
        box.min -= Vec2{r, r};
        box.max += Vec2{r, r};
        if (!box.overlaps(bounds_)) continue;
        int x0, y0, x1, y1;
        cellRange(box, x0, y0, x1, y1);
        for (int y = y0; y <= y1; ++y) {
            // A point of the fattened hull in this row lies within r of a hull point in the row band
            // widened by r; that band's x-extent is reached on the hull's edges, all among the 6 chords.
            const double lo = origin_.y + y * c - r, hi = origin_.y + (y + 1) * c + r;
            double xMin = std::numeric_limits<double>::infinity(), xMax = -xMin;
            for (int i = 0; i < 4; ++i)
                for (int j = i + 1; j < 4; ++j) mergeClippedExtent(pts[i], pts[j], lo, hi, xMin, xMax);
            if (xMin > xMax) continue;
            int rx0, ry0, rx1, ry1;
            cellRange(BoundingBox{{xMin - r, lo}, {xMax + r, hi}}, rx0, ry0, rx1, ry1);
            for (int x = rx0; x <= rx1; ++x) {
                entryCells_.push_back(static_cast<std::uint32_t>(y * nx_ + x));
                entryItems_.push_back(static_cast<int>(s));
            }
        }
    }
    fillTable(segments_);

    circleStamp_.assign(circleCount, 0);
    segmentStamp_.assign(segments.size(), 0);
    stamp_ = 0;
}

void BroadphaseGrid::findPairs(std::span<const BoundingBox> circleBoxes, std::span<const BoundingBox> segmentBoxes,
                               std::span<const std::uint8_t> isDynamic, std::vector<CandidatePair>& pairs) {
    pairs.clear();
    const int circleCount = static_cast<int>(circleBoxes.size());
    // Only dynamic circles look; of two dynamic circles the lower index leads the pair, so its key is
    // the same every step. Who reports which pair, so that each is reported once:
    //   small-small: the lower dynamic index, from the 3x3 cells around its centre;
    //   small-large: the small one when it is dynamic, else the large one;
    //   large-large: the lower dynamic index.
    for (int i = 0; i < circleCount; ++i) {
        if (!isDynamic[i]) continue;
        const BoundingBox& box = circleBoxes[i];
        const int stamp = ++stamp_;
        int x0, y0, x1, y1;
        cellRange(box, x0, y0, x1, y1);
        const bool small = isSmall_[i];
        if (small) {
            // Two small circles whose boxes overlap have their centres in neighbouring cells.
            const int hx = homeCell_[i] % nx_, hy = homeCell_[i] / nx_;
            for (int y = std::max(hy - 1, 0); y <= std::min(hy + 1, ny_ - 1); ++y)
                for (int x = std::max(hx - 1, 0); x <= std::min(hx + 1, nx_ - 1); ++x) {
                    const int cell = y * nx_ + x;
                    for (int k = small_.start[cell]; k < small_.start[cell + 1]; ++k) {
                        const int j = small_.items[k];
                        if (j == i || (isDynamic[j] && j < i) || !box.overlaps(circleBoxes[j])) continue;
                        pairs.push_back({i, j});
                    }
                }
        } else {
            // Small circles reaching into this box have their centres at most one cell outside it.
            for (int y = std::max(y0 - 1, 0); y <= std::min(y1 + 1, ny_ - 1); ++y)
                for (int x = std::max(x0 - 1, 0); x <= std::min(x1 + 1, nx_ - 1); ++x) {
                    const int cell = y * nx_ + x;
                    for (int k = small_.start[cell]; k < small_.start[cell + 1]; ++k) {
                        const int j = small_.items[k];
                        if (!isDynamic[j] && box.overlaps(circleBoxes[j])) pairs.push_back({i, j});
                    }
                }
        }
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const int cell = y * nx_ + x;
                for (int k = large_.start[cell]; k < large_.start[cell + 1]; ++k) {
                    const int j = large_.items[k];
                    if (j == i || !firstVisit(circleStamp_, j, stamp)) continue;
                    if (!small && isDynamic[j] && j < i) continue;
                    if (!box.overlaps(circleBoxes[j])) continue;
                    if (isDynamic[j] && j < i) pairs.push_back({j, i});
                    else pairs.push_back({i, j});
                }
                for (int k = segments_.start[cell]; k < segments_.start[cell + 1]; ++k) {
                    const int s = segments_.items[k];
                    if (firstVisit(segmentStamp_, s, stamp) && box.overlaps(segmentBoxes[s]))
                        pairs.push_back({i, circleCount + s});
                }
            }
    }
}

bool BroadphaseGrid::query(const BoundingBox& box, int maxCellsPerAxis, std::vector<int>& circles,
                           std::vector<int>& segments) {
    circles.clear();
    segments.clear();
    // Outside the grid, shapes were clipped away when filed: the caller must look at all of them.
    if (box.min.x < bounds_.min.x || box.min.y < bounds_.min.y || box.max.x > bounds_.max.x ||
        box.max.y > bounds_.max.y)
        return false;
    int x0, y0, x1, y1;
    cellRange(box, x0, y0, x1, y1);
    if (x1 - x0 >= maxCellsPerAxis || y1 - y0 >= maxCellsPerAxis) return false;
    const int stamp = ++stamp_;
    // Small circles are filed by centre: those reaching into the box sit at most one cell outside it.
    for (int y = std::max(y0 - 1, 0); y <= std::min(y1 + 1, ny_ - 1); ++y)
        for (int x = std::max(x0 - 1, 0); x <= std::min(x1 + 1, nx_ - 1); ++x) {
            const int cell = y * nx_ + x;
            for (int k = small_.start[cell]; k < small_.start[cell + 1]; ++k) circles.push_back(small_.items[k]);
        }
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const int cell = y * nx_ + x;
            for (int k = large_.start[cell]; k < large_.start[cell + 1]; ++k)
                if (firstVisit(circleStamp_, large_.items[k], stamp)) circles.push_back(large_.items[k]);
            for (int k = segments_.start[cell]; k < segments_.start[cell + 1]; ++k)
                if (firstVisit(segmentStamp_, segments_.items[k], stamp)) segments.push_back(segments_.items[k]);
        }
    return true;
}

} // namespace rube
