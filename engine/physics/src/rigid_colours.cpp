// The rigid contacts' greedy colouring (see rigid_colours.hpp).
#include "rigid_colours.hpp"

#include <bit>

namespace rube {

void RigidColours::build(std::vector<RigidContact>& contacts, std::span<const RigidState> bodies) {
    ends_.resize(contacts.size());
    for (std::size_t k = 0; k < contacts.size(); ++k) ends_[k] = {contacts[k].bodyA, contacts[k].bodyB};
    assign(ends_, bodies);
    sorted_.resize(contacts.size());
    for (std::size_t k = 0; k < contacts.size(); ++k) sorted_[static_cast<std::size_t>(to_[k])] = contacts[k];
    contacts.swap(sorted_);
}

void RigidColours::assign(std::span<const RigidContactEnds> ends, std::span<const RigidState> bodies) {
    used_.assign(bodies.size(), 0u);
    colour_.resize(ends.size());
    int count[kRigidColours + 1] = {};
    constexpr std::uint32_t kAll = (1u << kRigidColours) - 1u;
    for (std::size_t k = 0; k < ends.size(); ++k) {
        const auto a = static_cast<std::size_t>(ends[k].bodyA), b = static_cast<std::size_t>(ends[k].bodyB);
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
    to_.resize(ends.size());
    for (std::size_t k = 0; k < ends.size(); ++k) to_[k] = next[colour_[k]]++;
}

} // namespace rube
