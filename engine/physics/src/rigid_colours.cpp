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

void solveContactLanes(std::span<RigidContact> contacts, std::span<RigidState> bodies,
                       const RigidContactSoftness& softness, double h, bool useBias) {
#ifdef RUBE_RIGID_LANES_SSE2
    if (contacts.empty()) return;
    const double invH = 1.0 / h;
    RigidContact standIn; // the odd contact out's partner: no points, no friction, writes nothing
    standIn.bodyA = contacts[0].bodyA;
    standIn.bodyB = standIn.bodyA;
    std::size_t k = 0;
    for (; k + 1 < contacts.size(); k += 2)
        solveContactPair<LanePair>(contacts[k], contacts[k + 1], bodies, softness, invH, useBias, true);
    if (k < contacts.size()) solveContactPair<LanePair>(contacts[k], standIn, bodies, softness, invH, useBias, false);
#else
    solveRigidContacts(contacts, bodies, softness, h, useBias);
#endif
}

void solveColouredContacts(std::span<RigidContact> contacts, const RigidColours& colours, std::span<RigidState> bodies,
                           const RigidContactSoftness& softness, double h, bool useBias, WorkerPool* pool) {
    const auto overflow = static_cast<std::size_t>(colours.start(kRigidColours));
    sweepColours(pool, colours, [&](std::size_t first, std::size_t last) {
        const std::span<RigidContact> run = contacts.subspan(first, last - first);
        // The overflow's contacts may share bodies: one after the other.
        if (first >= overflow) solveRigidContacts(run, bodies, softness, h, useBias);
        else solveContactLanes(run, bodies, softness, h, useBias);
    });
}

} // namespace rube
