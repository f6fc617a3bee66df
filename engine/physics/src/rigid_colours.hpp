#pragma once
// Internal: the rigid contacts grouped into colours, so that no two contacts of a colour share a
// movable body (Box2D v3's graph colouring). A sweep still visits every contact once, colour after
// colour, but consecutive contacts of a colour do not wait on each other's velocities, so the
// processor overlaps them (and a worker could take a colour's share). Not part of the public API.

#include "rigid_contacts.hpp"
#include "worker_pool.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace rube {

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
    /// Contacts [start(c), start(c + 1)) have colour c; colour kRigidColours is the overflow.
    int start(int colour) const { return starts_[static_cast<std::size_t>(colour)]; }

    /// Contacts in the overflow colour, solved one by one after the others.
    int overflow() const { return starts_[kRigidColours + 1] - starts_[kRigidColours]; }

private:
    std::vector<std::uint32_t> used_; // per body: the colours that hold a contact of it
    std::vector<std::uint8_t> colour_;
    std::vector<RigidContact> sorted_;
    int starts_[kRigidColours + 2] = {};
};

/// Contacts of a colour each worker needs before a colour is shared (below it one worker sweeps all).
constexpr std::size_t kLeastContactsEach = 64;

/// Calls sweep(first, last) over the contacts [first, last) colour after colour, the overflow last
/// and whole. With `pool`, each large colour is split among the workers (in runs of an even length,
/// so the lanes keep their pairs) and all meet at a barrier before the next colour. A sweep that
/// writes only its contacts and their movable bodies gives the same bits for any split, since no two
/// contacts of a colour share a movable body; the serial order is the colours' order.
template <class Sweep>
void sweepColours(WorkerPool* pool, const RigidColours& colours, Sweep sweep) {
    const auto at = [&](int colour) { return static_cast<std::size_t>(colours.start(colour)); };
    const int workers = pool == nullptr ? 1 : pool->workers();
    const std::size_t least = kLeastContactsEach * static_cast<std::size_t>(workers);
    bool shared = false;
    for (int colour = 0; colour < kRigidColours && workers > 1; ++colour)
        shared = shared || at(colour + 1) - at(colour) >= least;
    if (!shared) {
        for (int colour = 0; colour <= kRigidColours; ++colour)
            if (at(colour) < at(colour + 1)) sweep(at(colour), at(colour + 1));
        return;
    }
    auto task = [&](int w) {
        for (int colour = 0; colour < kRigidColours; ++colour) {
            const std::size_t first = at(colour), n = at(colour + 1) - first;
            if (n == 0) continue;
            if (n < least) { // too few to share: one worker, the others go on to the barrier
                if (w == 0) sweep(first, first + n);
            } else {
                const WorkerPool::Range r = pool->share(n, w, 2);
                if (r.begin < r.end) sweep(first + r.begin, first + r.end);
            }
            pool->barrier();
        }
        if (w == 0 && at(kRigidColours) < at(kRigidColours + 1)) sweep(at(kRigidColours), at(kRigidColours + 1));
    };
    pool->run(task);
}

/// solveRigidContacts over the contacts of one colour (or of the overflow), two at a time in the
/// lanes of LanePair (rigid_contact_lanes.hpp). The same bits as solveRigidContacts over the same
/// contacts, with SSE2 or without.
void solveContactLanes(std::span<RigidContact> contacts, std::span<RigidState> bodies,
                       const RigidContactSoftness& softness, double h, bool useBias);

/// solveRigidContacts over `contacts` in colour order (as `colours` built them), sharing each colour
/// among `pool`'s workers (sweepColours); the overflow one by one. The same bits as
/// solveRigidContacts over the same list, with SSE2 or without, for any number of workers.
void solveColouredContacts(std::span<RigidContact> contacts, const RigidColours& colours, std::span<RigidState> bodies,
                           const RigidContactSoftness& softness, double h, bool useBias, WorkerPool* pool = nullptr);

} // namespace rube
