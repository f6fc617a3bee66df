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

/// A cell's key: its column and row, each non-negative and below 2^32, in one sortable number.
std::uint64_t cellKey(std::int64_t x, std::int64_t y) {
    return static_cast<std::uint64_t>(x) << 32 | static_cast<std::uint64_t>(y);
}

} // namespace

void RigidPairFinder::fileRange(const Range& r, int item, std::vector<Entry>& into) {
    for (std::int64_t x = r.x0; x <= r.x1; ++x)
        for (std::int64_t y = r.y0; y <= r.y1; ++y) into.push_back({cellKey(x, y), item});
}

bool RigidPairFinder::Range::large() const {
    return static_cast<double>(x1 - x0 + 1) * static_cast<double>(y1 - y0 + 1) > kMaxCellsPerItem;
}

RigidPairFinder::Range RigidPairFinder::rangeOf(const BoundingBox& b) const {
    // Monotonic in the coordinate, so two boxes that overlap (share a point) share a cell.
    const auto cell = [&](double x, double origin) {
        return static_cast<std::int64_t>(std::floor((x - origin) * inverseCell_));
    };
    return {cell(b.min.x, origin_.x), cell(b.max.x, origin_.x), cell(b.min.y, origin_.y), cell(b.max.y, origin_.y)};
}

void RigidPairFinder::consider(int a, int b, int rigidCount, std::vector<RigidPair>& into) const {
    // A pair lists the rigid body first; two circles never pair here (the circle solver's broadphase has them).
    if (a > b) std::swap(a, b);
    if (a >= rigidCount || a == b) return;
    if (!fat_[static_cast<std::size_t>(a)].overlaps(fat_[static_cast<std::size_t>(b)])) return;
    into.push_back({a, b});
}

void RigidPairFinder::find(std::span<const BoundingBox> rigidBoxes, std::span<const BoundingBox> circleBoxes,
                           std::vector<RigidPair>& pairs) {
    pairs.clear();
    const int rigidCount = static_cast<int>(rigidBoxes.size());
    if (rigidCount == 0) return;
    boxes_.assign(rigidBoxes.begin(), rigidBoxes.end());
    boxes_.insert(boxes_.end(), circleBoxes.begin(), circleBoxes.end());

    // The candidates stand while every box is inside its fat box: a pair whose boxes overlap has fat
    // boxes that overlap, and so was listed when its items were filed.
    const bool changed = rigidCount != rigidCount_ || fat_.size() != boxes_.size();
    if (changed) fat_.clear();
    moved_.clear();
    for (std::size_t i = 0; i < boxes_.size(); ++i) {
        if (i >= fat_.size()) {
            fat_.push_back(fatten(boxes_[i]));
        } else if (!holds(fat_[i], boxes_[i])) {
            fat_[i] = fatten(boxes_[i]);
            moved_.push_back(static_cast<int>(i));
        }
    }
    // A few items moved: only they are filed again; many (or new items): the whole grid, sized afresh.
    if (changed || moved_.size() * 4 > boxes_.size() || (!moved_.empty() && !refile(rigidCount))) file(rigidCount);

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
    origin_ = region.min;
    inverseCell_ = 1.0 / cell;

    entries_.clear();
    large_.clear();
    ranges_.resize(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        const Range r = ranges_[static_cast<std::size_t>(i)] = rangeOf(fat_[static_cast<std::size_t>(i)]);
        if (r.large()) {
            large_.push_back(i);
            continue;
        }
        fileRange(r, i, entries_);
    }
    std::sort(entries_.begin(), entries_.end());

    for (std::size_t begin = 0; begin < entries_.size();) {
        std::size_t end = begin + 1;
        while (end < entries_.size() && entries_[end].cell == entries_[begin].cell) ++end;
        // Items are sorted within the cell, so once the first is a circle the rest are too.
        for (std::size_t p = begin; p < end && entries_[p].item < rigidCount; ++p)
            for (std::size_t q = p + 1; q < end; ++q)
                consider(entries_[p].item, entries_[q].item, rigidCount, candidates_);
        begin = end;
    }
    for (const int l : large_)
        for (int i = 0; i < count; ++i) consider(l, i, rigidCount, candidates_);

    // A pair filed in several shared cells (or met through two large items) is listed once.
    std::sort(candidates_.begin(), candidates_.end());
    candidates_.erase(std::unique(candidates_.begin(), candidates_.end()), candidates_.end());
}

bool RigidPairFinder::refile(int rigidCount) {
    // Each moved item's cells, on the grid as filed: a large item pairs with everything, and a cell
    // left of or below the origin has no key, so either asks for the whole grid again.
    isMoved_.assign(fat_.size(), 0);
    newEntries_.clear();
    for (const int m : moved_) {
        const Range was = ranges_[static_cast<std::size_t>(m)], now = rangeOf(fat_[static_cast<std::size_t>(m)]);
        if (was.large() || now.large() || now.x0 < 0 || now.y0 < 0 || now.x1 >= kMaxCellsPerAxis ||
            now.y1 >= kMaxCellsPerAxis)
            return false;
        ranges_[static_cast<std::size_t>(m)] = now;
        isMoved_[static_cast<std::size_t>(m)] = 1;
        fileRange(now, m, newEntries_);
    }
    ++refilings_;
    const auto moved = [&](int item) { return isMoved_[static_cast<std::size_t>(item)] != 0; };
    // The entries: the moved items' old ones out, their new ones merged in (both sorted).
    std::erase_if(entries_, [&](const Entry& e) { return moved(e.item); });
    std::sort(newEntries_.begin(), newEntries_.end());
    mergedEntries_.resize(entries_.size() + newEntries_.size());
    std::merge(entries_.begin(), entries_.end(), newEntries_.begin(), newEntries_.end(), mergedEntries_.begin());
    entries_.swap(mergedEntries_);
    // The candidates: the moved items' pairs out, and their pairs in their new cells (and with the
    // large items) merged in; a pair of two moved items is met from both, and kept once.
    std::erase_if(candidates_, [&](const RigidPair& p) { return moved(p.body) || moved(p.other); });
    newPairs_.clear();
    for (const Entry& e : newEntries_) {
        const auto first = std::lower_bound(entries_.begin(), entries_.end(), Entry{e.cell, -1});
        for (auto it = first; it != entries_.end() && it->cell == e.cell; ++it)
            if (it->item != e.item) consider(e.item, it->item, rigidCount, newPairs_);
    }
    for (const int m : moved_)
        for (const int l : large_) consider(l, m, rigidCount, newPairs_);
    std::sort(newPairs_.begin(), newPairs_.end());
    newPairs_.erase(std::unique(newPairs_.begin(), newPairs_.end()), newPairs_.end());
    mergedPairs_.resize(candidates_.size() + newPairs_.size());
    std::merge(candidates_.begin(), candidates_.end(), newPairs_.begin(), newPairs_.end(), mergedPairs_.begin());
    candidates_.swap(mergedPairs_);
    return true;
}

} // namespace rube
