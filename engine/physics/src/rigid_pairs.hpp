#pragma once
// Internal: the rigid bodies' broadphase. Not part of the public API.
//
// Finds every pair of a rigid body with another rigid body or a circle whose boxes overlap, through
// a uniform grid of cells about one typical rigid body wide, so a pyramid's pairs cost what touches
// rather than n^2 box tests. The pairs come out sorted as the brute-force double loop visits them
// (body, then the other rigid bodies by index, then the circles by index), so the contacts built from
// them, and everything the solver does with those contacts, are bit-identical to the n^2 search's.

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

/// The grid, kept between steps so its buffers are warm.
class RigidPairFinder {
public:
    /// Replaces `pairs` with every (rigid, rigid) and (rigid, circle) pair whose boxes overlap, once
    /// each, in brute-force order. Pairs of two circles are never listed.
    void find(std::span<const BoundingBox> rigidBoxes, std::span<const BoundingBox> circleBoxes,
              std::vector<RigidPair>& pairs);

private:
    struct Entry {
        std::uint64_t cell; // the cell's key, column and row offset to be non-negative
        int item;           // rigid bodies first, then circles
        friend bool operator<(const Entry& a, const Entry& b) {
            return a.cell != b.cell ? a.cell < b.cell : a.item < b.item;
        }
    };
    std::vector<BoundingBox> boxes_; // every item's box: rigid bodies, then circles
    std::vector<Entry> entries_;
    std::vector<int> large_; // items whose box spans too many cells to file: tested against every item
};

} // namespace rube
