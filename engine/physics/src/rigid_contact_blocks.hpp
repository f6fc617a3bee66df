#pragma once
// Internal: the rigid contacts as the substeps read them. Four contacts of one colour sit side by
// side in a block, every field the substeps touch stored lane by lane (a structure of arrays, as
// Box2D v3's wide contact constraints are), so the sweep's lanes load and store each field with
// one aligned access instead of gathering it from four contacts of ~400 bytes, most of which
// (anchors, feature ids, bounciness, the warm-start and event bookkeeping) the sweeps never read.
//
// The blocks are packed once a step from the coloured contact list, after which warm starting,
// the approach measure, the arms and the sweeps all work on them; before restitution they are
// unpacked into the list again, which restitution, the warm-start cache, the events and sleeping
// read. Every function here runs the operations of its one-contact-at-a-time form in
// rigid_contacts.cpp in the same order (those stay as the reference the tests compare against),
// so the results are the same bits. Not part of the public API.

#include "rigid_colours.hpp"
#include "rigid_contacts.hpp"

#include <span>
#include <vector>

namespace rube {

/// Contacts side by side in a block: four doubles fill a 256-bit AVX register, or two SSE2 ones.
constexpr int kBlockLanes = 4;
/// A field of a block's contacts, one lane each: a GCC/Clang vector, whose operators act lane by lane
/// with each lane's IEEE arithmetic exactly as on a double, so the compiler's choice of instructions
/// (AVX, SSE2, or scalar) never changes a bit. Aligned to its size on every target: GCC would give
/// it 16 where the build has no AVX, and the AVX sweep's aligned loads would fault.
using Lanes = double __attribute__((vector_size(kBlockLanes * sizeof(double)), aligned(kBlockLanes * sizeof(double))));
/// A lane-wise truth (all bits set or none): what the vectors' comparisons give.
using LaneMask = decltype(Lanes{} < Lanes{});

/// Point j of a block's contacts, lane by lane. A lane whose contact has fewer points is packed with
/// zeros there; the sweeps compute on it (and store what they get) but never apply it to a body, and
/// nothing else reads it.
struct RigidBlockPoint {
    Lanes anchorAx{}, anchorAy{}, anchorBx{}, anchorBy{}; ///< from each body's centre at the step's start
    Lanes armAx{}, armAy{}, armBx{}, armBy{};             ///< the anchors turned with their bodies this substep
    Lanes baseSeparation{}, normalMass{}, tangentMass{};
    Lanes normalImpulse{}, tangentImpulse{};
    Lanes deliveredNormal{}, deliveredTangent{}, maxNormalImpulse{};
};

/// kBlockLanes contacts of one colour (or one contact of the overflow and stand-ins).
struct RigidBlock {
    Lanes normalX{}, normalY{}, tangentX{}, tangentY{}, friction{};
    Lanes tangentSpeed{}; ///< RigidContact::tangentSpeed: a conveyor's belt under the lane's body
    /// The bodies' inverse masses and inertias, which hold for the step: packed once, not gathered
    /// from four bodies each sweep (a stand-in's are 0).
    Lanes inverseMassA{}, inverseMassB{}, inverseInertiaA{}, inverseInertiaB{};
    /// Which lanes have point j (all bits set: count > j), and which of those rub (friction > 0): the
    /// sweeps' masks, made once a step instead of lane by lane in every sweep.
    Lanes pointMask[2]{}, rubbingMask[2]{};
    RigidBlockPoint points[2];
    int bodyA[kBlockLanes] = {}, bodyB[kBlockLanes] = {};
    int contact[kBlockLanes] = {}; ///< the lane's place in the contact list; -1: a stand-in that writes nothing
    bool againstFixed[kBlockLanes] = {}, stacking[kBlockLanes] = {};
    /// Some real lane's contact is not stacking (RigidContact::stacking): the block takes every relax
    /// pass, as the joints do (solveBlocks' everyRelaxOnly).
    bool everyRelax = false;
    /// The masks above as bits (lane i: bit i), and which lanes may write their body A or B: a real
    /// lane whose body can move (movableBody).
    unsigned pointLanes[2] = {}, rubbingLanes[2] = {}, writesA = 0, writesB = 0;
};

/// The step's blocks, colour after colour: a colour of n contacts fills n / kBlockLanes blocks in
/// list order, rounded up, the last one's spare lanes stand-ins; each overflow contact has a block of
/// its own, so the overflow is solved one contact after the other as before.
class RigidBlocks {
public:
    /// Packs `contacts`, coloured by `colours`, with their current impulses and their `bodies`'
    /// masses (the arms are refreshBlockArms'), the blocks shared among `pool`'s workers when given.
    void pack(std::span<const RigidContact> contacts, const RigidColours& colours, std::span<const RigidState> bodies,
              WorkerPool* pool = nullptr);
    /// Writes the arms, impulses and what the points delivered back into `contacts` (the list packed).
    void unpack(std::span<RigidContact> contacts, WorkerPool* pool = nullptr) const;
    /// Blocks [start(c), start(c + 1)) hold colour c; colour kRigidColours is the overflow.
    std::size_t start(int colour) const { return starts_[static_cast<std::size_t>(colour)]; }
    std::span<RigidBlock> all() { return blocks_; }
    /// Whether some block takes every relax pass (RigidBlock::everyRelax).
    bool anyEveryRelax() const { return anyEveryRelax_; }

private:
    std::vector<RigidBlock> blocks_;
    bool anyEveryRelax_ = false;
    std::size_t starts_[kRigidColours + 2] = {};
};

/// Calls sweep(first, last) over the blocks [first, last) colour after colour, the overflow last and
/// whole; with `pool`, the colours' blocks are cut into chunks the workers share (sweepColours' rule:
/// a colour's blocks share no movable body, so any split gives the same bits).
template <class Sweep>
void sweepBlocks(WorkerPool* pool, const RigidBlocks& blocks, Sweep sweep) {
    static_assert(kContactChunk % kBlockLanes == 0, "a chunk is whole blocks");
    constexpr std::size_t kBlockChunk = kContactChunk / kBlockLanes;
    std::size_t sizes[kRigidColours + 1], chunks[kRigidColours + 1];
    bool shared = false;
    for (int colour = 0; colour <= kRigidColours; ++colour) {
        sizes[colour] = blocks.start(colour + 1) - blocks.start(colour);
        chunks[colour] = colour < kRigidColours ? kBlockChunk : std::max<std::size_t>(1, sizes[colour]);
        shared = shared || (colour < kRigidColours && worthSharing(pool, sizes[colour], kBlockChunk));
    }
    if (!shared) {
        for (int colour = 0; colour <= kRigidColours; ++colour)
            if (sizes[colour] > 0) sweep(blocks.start(colour), blocks.start(colour + 1));
        return;
    }
    auto work = [&](int colour, std::size_t first, std::size_t last) {
        sweep(blocks.start(colour) + first, blocks.start(colour) + last);
    };
    pool->run(kRigidColours + 1, sizes, chunks, work);
}

/// Which code the passes below run: the best this processor runs (AVX-512VL's registers where it
/// has them, else AVX), AVX (where the processor has it), or only what the build targets (SSE2 on
/// x86-64). The same bits every way; the tests hold each to the one-contact-at-a-time forms.
enum class LaneCode { best, avx, portable };
/// Whether LaneCode::avx is AVX here, and whether LaneCode::best is AVX-512VL.
bool blocksRunAvx();
bool blocksRunAvx512();

/// refreshArms for the blocks: every lane's anchors turned with its bodies as they stand now.
void refreshBlockArms(std::span<RigidBlock> blocks, std::span<RigidState> bodies, LaneCode code = LaneCode::best);

/// warmStartRigidContacts for the blocks.
void warmStartBlocks(std::span<RigidBlock> blocks, std::span<RigidState> bodies, double h, double maxTurn,
                     LaneCode code = LaneCode::best);

/// measureApproach for the blocks: the approach speed and touch substep go to `contacts` (the list
/// packed), the only fields of it written before unpack().
void measureBlockApproach(std::span<RigidBlock> blocks, std::span<RigidContact> contacts, std::span<RigidState> bodies,
                          int substep, LaneCode code = LaneCode::best);

/// solveRigidContacts for the blocks: one Gauss-Seidel sweep, the lanes of a block at once
/// (rigid_contact_lanes.hpp), the blocks in order; with `everyRelaxOnly`, only the blocks that
/// take every relax pass (RigidBlock::everyRelax).
void solveBlocks(std::span<RigidBlock> blocks, std::span<RigidState> bodies, const RigidContactSoftness& softness,
                 double h, bool useBias, bool everyRelaxOnly = false, LaneCode code = LaneCode::best);

static_assert(alignof(RigidBlock) == sizeof(Lanes), "the sweep loads a block's fields with aligned loads");

} // namespace rube
