// The rigid contacts' greedy colouring (see rigid_colours.hpp).
#include "rigid_colours.hpp"

#include "rigid_contact_lanes.hpp"

#include <bit>

namespace rube {

void RigidColours::build(std::vector<RigidContact>& contacts, std::span<const RigidState> bodies) {
    used_.assign(bodies.size(), 0u);
    colour_.resize(contacts.size());
    int count[kRigidColours + 1] = {};
    constexpr std::uint32_t kAll = (1u << kRigidColours) - 1u;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const auto a = static_cast<std::size_t>(contacts[k].bodyA), b = static_cast<std::size_t>(contacts[k].bodyB);
        const bool movesA = bodies[a].inverseMass > 0.0, movesB = bodies[b].inverseMass > 0.0;
        const std::uint32_t taken = (movesA ? used_[a] : 0u) | (movesB ? used_[b] : 0u);
        const std::uint32_t free = ~taken & kAll;
        const int colour = free == 0u ? kRigidColours : std::countr_zero(free);
        if (colour < kRigidColours) {
            if (movesA) used_[a] |= 1u << colour;
            if (movesB) used_[b] |= 1u << colour;
        }
        colour_[k] = static_cast<std::uint8_t>(colour);
        ++count[colour];
    }
    starts_[0] = 0;
    for (int c = 0; c <= kRigidColours; ++c) starts_[c + 1] = starts_[c] + count[c];
    int next[kRigidColours + 1];
    for (int c = 0; c <= kRigidColours; ++c) next[c] = starts_[c];
    sorted_.resize(contacts.size());
    for (std::size_t k = 0; k < contacts.size(); ++k)
        sorted_[static_cast<std::size_t>(next[colour_[k]]++)] = contacts[k];
    contacts.swap(sorted_);
}

void solveColouredContacts(std::span<RigidContact> contacts, const RigidColours& colours, std::span<RigidState> bodies,
                           const RigidContactSoftness& softness, double h, bool useBias) {
#ifdef RUBE_RIGID_LANES_SSE2
    const double invH = 1.0 / h;
    RigidContact standIn; // the odd contact out's partner: no points, no friction, writes nothing
    standIn.bodyA = contacts.empty() ? 0 : contacts[0].bodyA;
    standIn.bodyB = standIn.bodyA;
    for (int colour = 0; colour < kRigidColours; ++colour) {
        const int end = colours.start(colour + 1);
        int k = colours.start(colour);
        for (; k + 1 < end; k += 2)
            solveContactPair<LanePair>(contacts[static_cast<std::size_t>(k)], contacts[static_cast<std::size_t>(k + 1)],
                                       bodies, softness, invH, useBias, true);
        if (k < end)
            solveContactPair<LanePair>(contacts[static_cast<std::size_t>(k)], standIn, bodies, softness, invH, useBias,
                                       false);
    }
    const auto first = static_cast<std::size_t>(colours.start(kRigidColours));
    solveRigidContacts(contacts.subspan(first), bodies, softness, h, useBias);
#else
    (void)colours;
    solveRigidContacts(contacts, bodies, softness, h, useBias);
#endif
}

} // namespace rube
