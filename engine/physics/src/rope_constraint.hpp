#pragma once
// Internal: the rope pass the world runs around each step when it has ropes. Not part of the public API.

#include "rube/physics/body.hpp"
#include "rube/physics/rope.hpp"
#include "rube/physics/world.hpp"

#include <span>
#include <vector>

namespace rube {

/// A rope as it was before the method's step.
struct RopeStart {
    Vec2 offset;       ///< the circle's centre minus the far end (anchor or other circle)
    bool taut = false; ///< its ends were the rope's length apart: it was pulling
};

/// Records, for every rope, where its ends are and whether it is taut, before the method moves anything.
void recordRopeStarts(std::span<const Circle> circles, std::span<const Rope> ropes, std::vector<RopeStart>& starts);

/// After the method's step of `dt`: every uncut rope whose ends would end farther apart than its
/// length is made taut again, in position (back to exactly its length) and in velocity (turned with
/// the rope, which does no work, then nothing left that stretches it). `impacts` are the step's:
/// a circle that hit something keeps the position its method gave it.
void enforceRopes(std::span<Circle> circles, std::span<const Rope> ropes, std::span<const RopeStart> starts,
                  std::span<const Impact> impacts, double dt);

} // namespace rube
