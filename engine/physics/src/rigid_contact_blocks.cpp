// The rigid contacts in blocks of four, lane by lane, and the passes over them (see rigid_contact_blocks.hpp).
#include "rigid_contact_blocks.hpp"

#include "rigid_contact_lanes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

// The vectors of the sweep never cross a call (rigid_contact_lanes.hpp): GCC's note on the AVX ABI is moot.
#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace rube {

namespace {

/// Blocks in a worker's share of packing or unpacking (a block is about 30 copies).
constexpr std::size_t kPackChunk = 64;

/// All bits set (a lane of a mask) when `on`, none otherwise.
double maskLane(bool on) {
    const std::uint64_t bits = on ? ~std::uint64_t{0} : 0;
    double lane;
    std::memcpy(&lane, &bits, sizeof lane);
    return lane;
}

void packLane(RigidBlock& k, int lane, const RigidContact& c, int index, std::span<const RigidState> bodies) {
    const RigidState& a = bodies[static_cast<std::size_t>(c.bodyA)];
    const RigidState& b = bodies[static_cast<std::size_t>(c.bodyB)];
    k.inverseMassA[lane] = a.inverseMass;
    k.inverseMassB[lane] = b.inverseMass;
    k.inverseInertiaA[lane] = a.inverseInertia;
    k.inverseInertiaB[lane] = b.inverseInertia;
    const unsigned bit = 1u << lane;
    for (int j = 0; j < 2; ++j) {
        const bool has = j < c.count, rubs = has && c.friction > 0.0;
        k.pointMask[j][lane] = maskLane(has);
        k.rubbingMask[j][lane] = maskLane(rubs);
        if (has) k.pointLanes[j] |= bit;
        if (rubs) k.rubbingLanes[j] |= bit;
    }
    if (movableBody(a)) k.writesA |= bit;
    if (movableBody(b)) k.writesB |= bit;
    k.normalX[lane] = c.normal.x;
    k.normalY[lane] = c.normal.y;
    k.tangentX[lane] = c.tangent.x;
    k.tangentY[lane] = c.tangent.y;
    k.friction[lane] = c.friction;
    k.tangentSpeed[lane] = c.tangentSpeed;
    k.bodyA[lane] = c.bodyA;
    k.bodyB[lane] = c.bodyB;
    k.contact[lane] = index;
    k.againstFixed[lane] = c.againstFixed;
    k.stacking[lane] = c.stacking;
    for (int j = 0; j < c.count; ++j) {
        const RigidContactPoint& p = c.points[j];
        RigidBlockPoint& q = k.points[j];
        q.anchorAx[lane] = p.anchorA.x;
        q.anchorAy[lane] = p.anchorA.y;
        q.anchorBx[lane] = p.anchorB.x;
        q.anchorBy[lane] = p.anchorB.y;
        q.baseSeparation[lane] = p.baseSeparation;
        q.normalMass[lane] = p.normalMass;
        q.tangentMass[lane] = p.tangentMass;
        q.normalImpulse[lane] = p.normalImpulse;
        q.tangentImpulse[lane] = p.tangentImpulse;
        q.deliveredNormal[lane] = p.deliveredNormal;
        q.deliveredTangent[lane] = p.deliveredTangent;
        q.maxNormalImpulse[lane] = p.maxNormalImpulse;
    }
}

/// A lane filled with a stand-in: both sides the block's first body (read, never written); its
/// masks, lane bits and masses stay the zeros the block was reset to (no points, no friction).
void standIn(RigidBlock& k, int lane) {
    k.bodyA[lane] = k.bodyB[lane] = k.bodyA[0];
    k.contact[lane] = -1;
}

} // namespace

void RigidBlocks::pack(std::span<const RigidContact> contacts, const RigidColours& colours,
                       std::span<const RigidState> bodies, WorkerPool* pool) {
    // Where each colour's blocks begin, then every block filled on its own (any split, the same blocks).
    // The overflow's contacts may share bodies: one a block, solved one after the other.
    const auto step = [](int colour) { return colour < kRigidColours ? kBlockLanes : 1; };
    std::size_t blocks = 0;
    for (int colour = 0; colour <= kRigidColours; ++colour) {
        starts_[colour] = blocks;
        const int size = colours.start(colour + 1) - colours.start(colour);
        blocks += static_cast<std::size_t>((size + step(colour) - 1) / step(colour));
    }
    starts_[kRigidColours + 1] = blocks;
    blocks_.resize(blocks);
    forShares(pool, blocks, kPackChunk, [&](std::size_t first, std::size_t last) {
        int colour = 0;
        for (std::size_t b = first; b < last; ++b) {
            while (starts_[colour + 1] <= b) ++colour;
            const int lanes = step(colour);
            const int i = colours.start(colour) + static_cast<int>(b - starts_[colour]) * lanes;
            const int end = colours.start(colour + 1);
            RigidBlock& k = blocks_[b];
            k = RigidBlock{};
            packLane(k, 0, contacts[static_cast<std::size_t>(i)], i, bodies);
            k.everyRelax = !contacts[static_cast<std::size_t>(i)].stacking;
            for (int lane = 1; lane < kBlockLanes; ++lane) {
                if (lane < lanes && i + lane < end) {
                    const RigidContact& c = contacts[static_cast<std::size_t>(i + lane)];
                    packLane(k, lane, c, i + lane, bodies);
                    k.everyRelax = k.everyRelax || !c.stacking;
                } else {
                    standIn(k, lane);
                }
            }
        }
    });
    anyEveryRelax_ = std::any_of(blocks_.begin(), blocks_.end(), [](const RigidBlock& k) { return k.everyRelax; });
}

void RigidBlocks::unpack(std::span<RigidContact> contacts, WorkerPool* pool) const {
    // Each lane writes its own contact: any split gives the same list.
    forShares(pool, blocks_.size(), kPackChunk, [&](std::size_t first, std::size_t last) {
        for (std::size_t b = first; b < last; ++b) {
            const RigidBlock& k = blocks_[b];
            for (int lane = 0; lane < kBlockLanes; ++lane) {
                if (k.contact[lane] < 0) continue;
                RigidContact& c = contacts[static_cast<std::size_t>(k.contact[lane])];
                for (int j = 0; j < c.count; ++j) {
                    const RigidBlockPoint& q = k.points[j];
                    RigidContactPoint& p = c.points[j];
                    p.armA = {q.armAx[lane], q.armAy[lane]};
                    p.armB = {q.armBx[lane], q.armBy[lane]};
                    p.normalImpulse = q.normalImpulse[lane];
                    p.tangentImpulse = q.tangentImpulse[lane];
                    p.deliveredNormal = q.deliveredNormal[lane];
                    p.deliveredTangent = q.deliveredTangent[lane];
                    p.maxNormalImpulse = q.maxNormalImpulse[lane];
                }
            }
        }
    });
}

namespace {

/// One pass over blocks, as the dispatch below hands it to the form compiled for the processor.
struct Pass {
    enum Kind { arms, approach, warmStart, solve } kind;
    std::span<RigidBlock> blocks;
    std::span<RigidState> bodies;
    std::span<RigidContact> contacts = {};
    int substep = 0;
    const RigidContactSoftness* softness = nullptr;
    double h = 0.0;
    double maxTurn = 0.0;
    bool useBias = false;
    bool everyRelaxOnly = false;
};

/// The pass over its blocks with vector V: a whole block at once, or half of it at a time.
template <class V>
[[gnu::always_inline]] inline void run(const Pass& pass) {
    constexpr int W = kWidth<V>;
    switch (pass.kind) {
    case Pass::arms:
        for (RigidBlock& k : pass.blocks)
            for (int base = 0; base < kBlockLanes; base += W) refreshArmsOfSlice<V>(k, base, pass.bodies);
        break;
    case Pass::approach:
        for (const RigidBlock& k : pass.blocks)
            for (int base = 0; base < kBlockLanes; base += W)
                measureApproachOfSlice<V>(k, base, pass.contacts, pass.bodies, pass.substep);
        break;
    case Pass::warmStart:
        for (RigidBlock& k : pass.blocks)
            for (int base = 0; base < kBlockLanes; base += W)
                warmStartSlice<V>(k, base, pass.bodies, pass.h, pass.maxTurn);
        break;
    case Pass::solve: {
        const double invH = 1.0 / pass.h;
        for (RigidBlock& k : pass.blocks) {
            if (pass.everyRelaxOnly && !k.everyRelax) continue;
            for (int base = 0; base < kBlockLanes; base += W)
                solveSlice<V>(k, base, pass.bodies, *pass.softness, invH, pass.useBias);
        }
        break;
    }
    }
}

// Without AVX a block is run half at a time, two doubles a vector (SSE2 on x86-64): GCC splits a
// vector wider than the target's into scalars wherever it compares or selects, and the whole pyramid
// ran 1.6 x slower so.
void runPortable(const Pass& pass) { run<HalfLanes>(pass); }

#if defined(__x86_64__) && defined(__GNUC__)
// The same passes compiled for AVX, a whole block an instruction (no FMA, which AVX does not have).
__attribute__((target("avx"))) void runAvx(const Pass& pass) { run<Lanes>(pass); }
// And once more with AVX-512VL's encoding of the same four-lane instructions: 32 vector registers
// instead of 16, so a sweep keeps both bodies' velocities, the normal and the arms in registers
// instead of spilling some to the stack (the 820-box pyramid about 8 % faster on a Zen 4). Still no
// contraction into FMA (-ffp-contract=off), and the vectors stay four lanes wide: the same bits.
__attribute__((target("avx512f,avx512vl"))) void runAvx512(const Pass& pass) { run<Lanes>(pass); }
bool processorHasAvx() {
    static const bool avx = __builtin_cpu_supports("avx"); // a CPUID flag, read once: never a clock
    return avx;
}
bool processorHasAvx512() {
    static const bool avx512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
    return avx512;
}
#else
void runAvx(const Pass& pass) { run<HalfLanes>(pass); }
void runAvx512(const Pass& pass) { run<HalfLanes>(pass); }
bool processorHasAvx() { return false; }
bool processorHasAvx512() { return false; }
#endif

void dispatch(const Pass& pass, LaneCode code) {
    if (code == LaneCode::best && processorHasAvx512()) runAvx512(pass);
    else if (code != LaneCode::portable && processorHasAvx()) runAvx(pass);
    else runPortable(pass);
}

} // namespace

bool blocksRunAvx() { return processorHasAvx(); }
bool blocksRunAvx512() { return processorHasAvx512(); }

void refreshBlockArms(std::span<RigidBlock> blocks, std::span<RigidState> bodies, LaneCode code) {
    dispatch(Pass{Pass::arms, blocks, bodies}, code);
}

void measureBlockApproach(std::span<RigidBlock> blocks, std::span<RigidContact> contacts, std::span<RigidState> bodies,
                          int substep, LaneCode code) {
    dispatch(Pass{Pass::approach, blocks, bodies, contacts, substep}, code);
}

void warmStartBlocks(std::span<RigidBlock> blocks, std::span<RigidState> bodies, double h, double maxTurn,
                     LaneCode code) {
    dispatch(Pass{Pass::warmStart, blocks, bodies, {}, 0, nullptr, h, maxTurn}, code);
}

void solveBlocks(std::span<RigidBlock> blocks, std::span<RigidState> bodies, const RigidContactSoftness& softness,
                 double h, bool useBias, bool everyRelaxOnly, LaneCode code) {
    dispatch(Pass{Pass::solve, blocks, bodies, {}, 0, &softness, h, 0.0, useBias, everyRelaxOnly}, code);
}

} // namespace rube
