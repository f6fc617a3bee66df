#pragma once
// Internal: the rigid contacts grouped into colours, so that no two contacts of a colour share a
// movable body (Box2D v3's graph colouring). A sweep still visits every contact once, colour after
// colour, but consecutive contacts of a colour do not wait on each other's velocities, so the
// processor overlaps them, and the world's workers share a colour's contacts (sweepColours). Not part
// of the public API.

#include "rigid_contacts.hpp"
#include "worker_pool.hpp"

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

namespace rube {

/// A contact's two solver bodies: all the colouring reads of it.
struct RigidContactEnds {
    int bodyA = 0, bodyB = 0;
};

/// Colours a contact may take before it goes to the overflow, which is solved last in list order.
constexpr int kRigidColours = 12;

/// The contacts' colours as ranges of the reordered contact list.
class RigidColours {
public:
    /// Reorders `contacts` into colours: each contact, in list order, takes the first colour in
    /// which neither of its movable bodies (inverse mass > 0 in `bodies`) has a contact yet;
    /// fixed, static and asleep bodies do not count. One that fits none of kRigidColours goes to
    /// the overflow colour. Within a colour the contacts keep their list order, so the result
    /// depends on nothing but the list.
    void build(std::vector<RigidContact>& contacts, std::span<const RigidState> bodies);
    /// The same colours for contacts known by their solver bodies alone (ends[k] of the k-th in list
    /// order), without moving anything: the k-th goes to placeOfListed()[k].
    void assign(std::span<const RigidContactEnds> ends, std::span<const RigidState> bodies);
    /// Contacts [start(c), start(c + 1)) have colour c; colour kRigidColours is the overflow.
    int start(int colour) const { return starts_[static_cast<std::size_t>(colour)]; }

    /// Per contact of the list as given to build(): its place in colour order.
    std::span<const int> placeOfListed() const { return to_; }

    /// Contacts in the overflow colour, solved one by one after the others.
    int overflow() const { return starts_[kRigidColours + 1] - starts_[kRigidColours]; }

private:
    std::vector<std::uint32_t> used_; // per body: the colours that hold a contact of it
    std::vector<std::uint8_t> colour_;
    std::vector<int> to_; // per contact in list order: its place in colour order
    std::vector<RigidContact> sorted_;
    std::vector<RigidContactEnds> ends_;
    int starts_[kRigidColours + 2] = {};
};

/// Contacts in one worker's chunk of a colour (a whole number of blocks of four, sweepBlocks); a colour
/// of fewer than two chunks is not worth a hand-over (a contact costs about 40 ns, a hand-over about 1 us).
constexpr std::size_t kContactChunk = 32;

/// Calls sweep(first, last) over the contacts [first, last) colour after colour, the overflow last
/// and whole. With `pool`, the colours are cut into chunks the workers share, and no worker starts
/// a colour before the last one is done. A sweep that writes only its contacts and their movable
/// bodies gives the same bits for any split, since no two contacts of a colour share a movable
/// body; the serial order is the colours' order.
template <class Sweep>
void sweepColours(WorkerPool* pool, const RigidColours& colours, Sweep sweep) {
    const auto at = [&](int colour) { return static_cast<std::size_t>(colours.start(colour)); };
    std::size_t sizes[kRigidColours + 1], chunks[kRigidColours + 1];
    bool shared = false;
    for (int colour = 0; colour <= kRigidColours; ++colour) {
        sizes[colour] = at(colour + 1) - at(colour);
        chunks[colour] = colour < kRigidColours ? kContactChunk : std::max<std::size_t>(1, sizes[colour]);
        shared = shared || (colour < kRigidColours && worthSharing(pool, sizes[colour], kContactChunk));
    }
    if (!shared) {
        for (int colour = 0; colour <= kRigidColours; ++colour)
            if (sizes[colour] > 0) sweep(at(colour), at(colour + 1));
        return;
    }
    auto work = [&](int colour, std::size_t first, std::size_t last) { sweep(at(colour) + first, at(colour) + last); };
    pool->run(kRigidColours + 1, sizes, chunks, work);
}

} // namespace rube
