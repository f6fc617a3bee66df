#pragma once
// Internal: the exact method's resting pairs. A pair whose approach is slower than the resting
// speed is resolved with C = 0 and left out of the earliest-collision search for the rest of the
// step (else it would be found again at t = 0 for ever); a circle resting on a segment's face keeps
// the side of its line it came from. Memory O(n + resting pairs): a table of every pair's state was
// n x (n + segments) bytes, 10 GB for 100,000 circles, and clearing it cost O(n^2) every step.

#include "step_method.hpp"

#include <cstdint>
#include <vector>

namespace rube {

/// A pair's state: searched, or resting for the rest of the step (and, for a segment, on which side
/// of its line the circle rests: the line normal's side, or the other).
enum PairState : std::uint8_t { kSearched = 0, kRestingPlus = 1, kRestingMinus = 2 };

/// Every circle's resting pairs for the rest of one step.
class RestingPairs {
public:
    /// Forgets every pair, for a step over `circles` circles (capacity kept: no allocation once grown).
    void reset(int circles);
    /// The pair's state (kSearched unless it was set resting this step).
    std::uint8_t state(int circle, Other kind, int other) const;
    /// Whether the pair rests for the rest of the step.
    bool resting(int circle, Other kind, int other) const { return state(circle, kind, other) != kSearched; }
    /// Records the pair in the circle's list and, for two circles, in the other's too.
    void set(int circle, Other kind, int other, std::uint8_t state);
    /// Every pair with this circle is searched again (its own list, and its entry in each resting partner's).
    void forgetCircle(int circle);
    /// The circle's pair with the segment is searched again (a held face's circle past its end).
    void forgetSegment(int circle, int segment);

private:
    // A pair in one circle's list: the other circle's index, or circleCount_ + a segment's.
    struct Entry {
        int column = 0;
        std::uint8_t state = kSearched;
    };
    int columnOf(Other kind, int other) const { return kind == Other::circle ? other : circleCount_ + other; }

    int circleCount_ = 0;
    std::vector<std::vector<Entry>> of_; ///< per circle: the pairs it rests in
};

} // namespace rube
