#pragma once
// Internal: the rigid contacts grouped into colours, so that no two contacts of a colour share a
// movable body (Box2D v3's graph colouring). A sweep still visits every contact once, colour after
// colour, but consecutive contacts of a colour do not wait on each other's velocities, so the
// processor overlaps them (and a worker could take a colour's share). Not part of the public API.

#include "rigid_contacts.hpp"

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

/// solveRigidContacts over `contacts` in colour order (as `colours` built them), two contacts of a
/// colour at a time in the lanes of LanePair (rigid_contact_lanes.hpp); the overflow one by one. The
/// same bits as solveRigidContacts over the same list, with SSE2 or without.
void solveColouredContacts(std::span<RigidContact> contacts, const RigidColours& colours, std::span<RigidState> bodies,
                           const RigidContactSoftness& softness, double h, bool useBias);

} // namespace rube
