#pragma once
// Internal: lecture 3's blocks (fixed-rotation boxes) in the exact, turn-based and discrete methods:
// which bodies are blocks, their pairs' times of impact, Newton's resolve along the axis of impact,
// and the end-of-step settle. Not part of the public API. A world without bodies never calls these.

#include "rube/physics/block_collision.hpp"
#include "rube/physics/world.hpp"

#include <limits>
#include <span>
#include <vector>

namespace rube {

struct StepContext;

/// One predicted impact of block `block` against a circle, segment or block (`kind`, `other`).
struct BlockEvent {
    double time = std::numeric_limits<double>::infinity();
    int block = -1;
    Other kind = Other::body;
    int other = -1;
    Vec2 normal;       ///< unit, from the other towards the block
    Vec2 contactPoint; ///< where the surfaces touch
};

/// A block's pair left out of the search (resting for the rest of the step); `side` is a segment face's side.
struct BlockPair {
    int block = -1;
    Other kind = Other::body;
    int other = -1;
    Vec2 side;
};

/// How a method searches: the exact method moves bodies on parabolas (acceleration = gravity) and
/// visits each pair once; turn-based moves one body while the others stand still (unless scripted).
struct BlockSearch {
    Vec2 gravity;                       ///< the dynamic bodies' acceleration during the search (zero for turn-based)
    double horizon = 0.0;               ///< step time left, s
    bool eachPairOnce = true;           ///< block pairs only from the lower index
    bool othersStandStill = false;      ///< dynamic others are held still (turn-based); kinematic ones still move
    std::span<const BlockPair> resting; ///< pairs left out
};

/// The earliest impact of block i against the circles, segments and blocks within the horizon.
BlockEvent earliestBlockImpact(const StepContext& ctx, int i, const BlockSearch& search);

/// What a block's partner is, as a resolve sees it.
struct BlockPartner {
    Vec2 velocity;
    double inverseMass = 0.0; ///< 0 for fixed and kinematic bodies: infinite mass (lecture 3, walls)
    Material material;
    bool dynamic = false;
};

/// The partner `other` of kind `kind`: a circle, a segment (either kind) or a block.
BlockPartner blockPartner(const StepContext& ctx, Other kind, int other);

/// Newton's collision of the event's block with its partner along the event's normal, v' = u - C (v - u)
/// on that component only, the other kept (lecture 3); C = 0 when `resting`. With `record`, appends the
/// Impact at world time `time`. Returns the approach speed before.
double resolveBlockImpact(StepContext& ctx, const BlockEvent& event, double time, bool resting, bool record);

/// Moves every block over t: dynamic ones on p + v t + g t^2 / 2, kinematic ones linearly.
void advanceBlocks(StepContext& ctx, double t);

/// The discrete clean-up for blocks: every block pair with a dynamic body, against segments (on the side
/// the centre started, `startCentres`, the segment moved back by velocity x `sideDelay`), blocks and
/// circles: pushed out and reflected if approaching; each recorded as an Impact at `time`. Returns the count.
int separateBlockOverlaps(StepContext& ctx, std::span<const Vec2> startCentres, double sideDelay, double time);

/// The exact method's end-of-step settle: every block pair touching within `slop`, from the ground up,
/// pushed apart with its approach removed (C = 0) when resting; the body below holds still against the
/// one it carries (shock propagation), so one pass settles a stack. `resting` gives segment sides.
void settleBlockContacts(StepContext& ctx, double slop, std::span<const BlockPair> resting);

} // namespace rube
