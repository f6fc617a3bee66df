#pragma once
// Internal: the rigid bodies' broadphase. Not part of the public API.
//
// Finds every pair of a rigid body with another rigid body or a circle whose boxes overlap, through
// a uniform grid of cells about one typical rigid body wide, so a pyramid's pairs cost what touches
// rather than n^2 box tests. The pairs come out sorted as the brute-force double loop visits them
// (body, then the other rigid bodies by index, then the circles by index), so the contacts built from
// them, and everything the solver does with those contacts, are bit-identical to the n^2 search's.
//
// Between steps the grid files each item by a fat box, its box grown by a margin (Box2D's fat
// AABBs), and keeps the candidate pairs, those whose fat boxes overlap. While every box stays inside
// its fat box the candidates stand, and a step only tests them against the new boxes, in order: a
// resting pyramid pays no filing and no sorting. An item whose box leaves its fat box is given a new
// one and filed again alone; when many moved, the whole grid is.

#include "broadphase_grid.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace rube {

/// A candidate pair: rigid body `body` and `other`, a rigid body index above `body` when
/// other < rigid count, else circle other - rigid count.
struct RigidPair {
    int body = 0;  ///< the rigid body with the lower index
    int other = 0; ///< a rigid body (above `body`), or the rigid count plus a circle's index
    friend bool operator<(const RigidPair& a, const RigidPair& b) {
        return a.body != b.body ? a.body < b.body : a.other < b.other;
    }
    friend bool operator==(const RigidPair&, const RigidPair&) = default;
};

/// The grid and its candidate pairs, kept between steps.
class RigidPairFinder {
public:
    /// Replaces `pairs` with every (rigid, rigid) and (rigid, circle) pair whose boxes overlap, once
    /// each, in brute-force order. Pairs of two circles are never listed.
    void find(std::span<const BoundingBox> rigidBoxes, std::span<const BoundingBox> circleBoxes,
              std::vector<RigidPair>& pairs);

    /// How many times find() has filed the grid again (a box left its fat box, or the items changed).
    long long refilings() const { return refilings_; }

private:
    /// Files every item by its fat box and lists the candidate pairs, sorted, once each.
    void file(int rigidCount);
    /// Files again only the items in `moved_`, whose fat boxes changed, on the grid as it stands;
    /// false when one of them is or was too large to file, or left the grid: then the whole grid
    /// must be filed (file()).
    bool refile(int rigidCount);

    /// The cells an item's fat box covers, on the grid of the last full filing.
    struct Range {
        std::int64_t x0, x1, y0, y1;
        bool large() const;
    };
    Range rangeOf(const BoundingBox& b) const;
    /// Lists (a, b) as a candidate when a is a rigid body and their fat boxes overlap.
    void consider(int a, int b, int rigidCount, std::vector<RigidPair>& into) const;

    struct Entry {
        std::uint64_t cell; // the cell's key, column and row offset to be non-negative
        int item;           // rigid bodies first, then circles
        friend bool operator<(const Entry& a, const Entry& b) {
            return a.cell != b.cell ? a.cell < b.cell : a.item < b.item;
        }
    };
    /// Appends an entry for each cell of `r`, filing `item`.
    static void fileRange(const Range& r, int item, std::vector<Entry>& into);
    std::vector<BoundingBox> boxes_; // every item's box this step: rigid bodies, then circles
    std::vector<BoundingBox> fat_;   // every item's fat box: holds its box, since the grid was filed
    int rigidCount_ = -1;            // the rigid count the candidates were filed for
    std::vector<Entry> entries_;
    std::vector<int> large_;              // items whose fat box spans too many cells to file: paired with every item
    std::vector<RigidPair> candidates_;   // pairs whose fat boxes overlap, sorted
    long long refilings_ = 0;
    // The grid of the last full filing: its origin and cell, and each item's cells.
    Vec2 origin_;
    double inverseCell_ = 0.0;
    std::vector<Range> ranges_;
    std::vector<int> moved_;            // items whose fat boxes changed this step
    std::vector<std::uint8_t> isMoved_; // per item: in moved_
    std::vector<Entry> newEntries_;
    std::vector<RigidPair> newPairs_;
    std::vector<Entry> mergedEntries_;
    std::vector<RigidPair> mergedPairs_;
};

} // namespace rube
