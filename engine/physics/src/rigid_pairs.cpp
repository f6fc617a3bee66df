// The rigid bodies' broadphase: a uniform grid of fat boxes, filed by sorting (cell, item) entries, so
// the work and the order of the pairs depend only on the boxes, never on a hash table's layout.
#include "rigid_pairs.hpp"

#include <algorithm>
#include <cmath>

namespace rube {

namespace {

/// An item whose box covers more cells than this (a long floor box, a huge wheel) is not filed; it is
/// tested against every item instead, which costs n per such item rather than its cells' worth.
constexpr double kMaxCellsPerItem = 64.0;
/// Cells per axis at the most, so a key stays within 32 bits a coordinate however far apart boxes are.
constexpr double kMaxCellsPerAxis = 1 << 30;
/// A fat box is the box grown on every side by this fraction of its larger side: a resting body's box
/// (which breathes with its speed by micrometres) never leaves it, and a falling crate (a tenth of its
/// size a step at 6 m/s for a 1 m crate) refiles the grid every few steps. Wider margins keep the
/// candidates longer but list more of them to test every step.
constexpr double kFatMargin = 0.1;

bool holds(const BoundingBox& outer, const BoundingBox& inner) {
    return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y && inner.max.x <= outer.max.x &&
           inner.max.y <= outer.max.y;
}

BoundingBox fatten(const BoundingBox& b) {
    const double m = kFatMargin * std::max(b.max.x - b.min.x, b.max.y - b.min.y);
    return {{b.min.x - m, b.min.y - m}, {b.max.x + m, b.max.y + m}};
}

} // namespace

void RigidPairFinder::find(std::span<const BoundingBox> rigidBoxes, std::span<const BoundingBox> circleBoxes,
                           std::vector<RigidPair>& pairs) {
    pairs.clear();
    const int rigidCount = static_cast<int>(rigidBoxes.size());
    if (rigidCount == 0) return;
    boxes_.assign(rigidBoxes.begin(), rigidBoxes.end());
    boxes_.insert(boxes_.end(), circleBoxes.begin(), circleBoxes.end());

    // The candidates stand while every box is inside its fat box: a pair whose boxes overlap has fat
    // boxes that overlap, and so was listed when the grid was filed.
    bool refile = rigidCount != rigidCount_ || fat_.size() != boxes_.size();
    if (refile) fat_.clear();
    for (std::size_t i = 0; i < boxes_.size(); ++i) {
        if (i >= fat_.size()) {
            fat_.push_back(fatten(boxes_[i]));
        } else if (!holds(fat_[i], boxes_[i])) {
            fat_[i] = fatten(boxes_[i]);
            refile = true;
        }
    }
    if (refile) file(rigidCount);

    // The candidates in order, kept when their boxes overlap this step: the brute-force order.
    for (const RigidPair& p : candidates_)
        if (boxes_[static_cast<std::size_t>(p.body)].overlaps(boxes_[static_cast<std::size_t>(p.other)]))
            pairs.push_back(p);
}

void RigidPairFinder::file(int rigidCount) {
    ++refilings_;
    rigidCount_ = rigidCount;
    candidates_.clear();
    const int count = static_cast<int>(fat_.size());

    // Cells as wide as the items' mean fat side, and the grid's origin at the lowest corner.
    double side = 0.0;
    BoundingBox region = fat_[0];
    for (int i = 0; i < count; ++i) {
        const BoundingBox& b = fat_[static_cast<std::size_t>(i)];
        side += std::max(b.max.x - b.min.x, b.max.y - b.min.y);
        region.min = {std::min(region.min.x, b.min.x), std::min(region.min.y, b.min.y)};
        region.max = {std::max(region.max.x, b.max.x), std::max(region.max.y, b.max.y)};
    }
    const double span = std::max(region.max.x - region.min.x, region.max.y - region.min.y);
    const double cell = std::max({side / count, span / kMaxCellsPerAxis, 1e-9});
    const double inverse = 1.0 / cell;
    // Monotonic in the coordinate, so two boxes that overlap (share a point) share a cell.
    const auto column = [&](double x) { return static_cast<std::int64_t>(std::floor((x - region.min.x) * inverse)); };
    const auto row = [&](double y) { return static_cast<std::int64_t>(std::floor((y - region.min.y) * inverse)); };

    entries_.clear();
    large_.clear();
    for (int i = 0; i < count; ++i) {
        const BoundingBox& b = fat_[static_cast<std::size_t>(i)];
        const std::int64_t x0 = column(b.min.x), x1 = column(b.max.x), y0 = row(b.min.y), y1 = row(b.max.y);
        if (static_cast<double>(x1 - x0 + 1) * static_cast<double>(y1 - y0 + 1) > kMaxCellsPerItem) {
            large_.push_back(i);
            continue;
        }
        for (std::int64_t x = x0; x <= x1; ++x)
            for (std::int64_t y = y0; y <= y1; ++y)
                entries_.push_back({static_cast<std::uint64_t>(x) << 32 | static_cast<std::uint64_t>(y), i});
    }
    std::sort(entries_.begin(), entries_.end());

    // A pair lists the rigid body first; two circles never pair here (the circle solver's broadphase has them).
    const auto consider = [&](int a, int b) {
        if (a > b) std::swap(a, b);
        if (a >= rigidCount || a == b) return;
        if (!fat_[static_cast<std::size_t>(a)].overlaps(fat_[static_cast<std::size_t>(b)])) return;
        candidates_.push_back({a, b});
    };
    for (std::size_t begin = 0; begin < entries_.size();) {
        std::size_t end = begin + 1;
        while (end < entries_.size() && entries_[end].cell == entries_[begin].cell) ++end;
        // Items are sorted within the cell, so once the first is a circle the rest are too.
        for (std::size_t p = begin; p < end && entries_[p].item < rigidCount; ++p)
            for (std::size_t q = p + 1; q < end; ++q) consider(entries_[p].item, entries_[q].item);
        begin = end;
    }
    for (const int l : large_)
        for (int i = 0; i < count; ++i) consider(l, i);

    // A pair filed in several shared cells (or met through two large items) is listed once.
    std::sort(candidates_.begin(), candidates_.end());
    candidates_.erase(std::unique(candidates_.begin(), candidates_.end()), candidates_.end());
}

} // namespace rube
