#pragma once
// Internal: the end of an exact step. Resting bodies fell into what they rest on for the rest of the
// step (g t^2 / 2, a millimetre or so): every touching pair is pushed back out and its approaching
// normal velocity removed, so resting never sinks. Pairs go from the ground up and the body nearer
// the ground counts as infinite mass against one above it (shock propagation): one pass settles a
// whole stack.

#include "block_pairs.hpp"
#include "exact_resting_pairs.hpp"
#include "exact_springs.hpp"
#include "magnet_pulls.hpp"
#include "step_method.hpp"

#include <vector>

namespace rube {

/// The exact method's end-of-step settle; keeps its buffers from step to step.
class ExactSettle {
public:
    /// Settles every touching pair of `ctx` after a step of `dt`: circles (a circle resting on a face
    /// keeps the side `resting` says it came from; a spring-held circle's threshold grows with the
    /// acceleration its spring gives it, a magnet-pulled one's with gravity and the pull `pulls` took
    /// back) and lecture 3's blocks (`blockResting`).
    void settle(StepContext& ctx, double dt, const RestingPairs& resting, const ExactSprings& springs,
                std::vector<BlockPair>& blockResting, const MagnetPulls& pulls);

private:
    // A pair touching (or nearly) at the end of a step; `side` is a segment face's side.
    struct Contact {
        int circle = -1;
        Other kind = Other::circle;
        int other = -1;
        Vec2 side;
        int support = 0; ///< +1: the other holds the circle up against gravity; -1: the reverse; 0: side by side
    };
    void collectContacts(const StepContext& ctx, double slop, const RestingPairs& resting);
    void orderFromTheGroundUp(const StepContext& ctx);
    double settle(StepContext& ctx, const Contact& contact, const ExactSprings& springs, const MagnetPulls& pulls,
                  double dt) const;

    std::vector<Contact> contacts_; ///< the settle's pairs
    std::vector<int> levels_;       ///< per circle: contacts between it and the ground
};

} // namespace rube
