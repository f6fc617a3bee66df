#pragma once
// Internal: warm starting of rigid contacts from one step to the next. A contact point is known again
// by its body pair and the features that made it (the manifold point's id: reference face, incident
// edge and end), as Box2D matches manifold points; a point found again starts the step with the
// impulses it ended the last one with, so a stack carries its weight from the first substep instead
// of sinking while the impulses build up again. Not part of the public API.

#include "rigid_contacts.hpp"
#include "world_handles.hpp"
#include "worker_pool.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace rube {

/// The last step's impulses of every rigid contact point, by body pair and feature.
class RigidContactCache {
    struct Entry {
        std::uint64_t pair = 0;    ///< side A's index, side B's kind and index
        std::uint32_t feature = 0; ///< the manifold point's id
        double normalImpulse = 0.0;
        double tangentImpulse = 0.0;
    };

public:
    /// Gives each point found in the cache its impulses back and marks it carried (when it pushed).
    void apply(std::span<RigidContact> contacts, WorkerPool* pool = nullptr) const;
    /// Looks contacts up one after the other: each search gallops on from where the last one ended
    /// (doubling steps, then a binary search within the last step), so contacts that come in key
    /// order, as the list does (rigid_pairs.cpp), are found in a few steps each. One that comes
    /// before the last is still found, by a search from the table's beginning.
    class Lookup {
    public:
        explicit Lookup(const RigidContactCache& cache) : entries_(cache.entries_) {}
        /// Gives each point of `c` found in the cache its impulses back and marks it carried (when it pushed).
        void apply(RigidContact& c);

    private:
        std::span<const Entry> entries_;
        std::size_t from_ = 0;
    };
    /// Remembers every point's impulses at the end of the step's substeps (before restitution).
    /// `listOrder`, when given, is where each contact of the list (in key order) now stands in
    /// `contacts`: visited so, the entries need no sorting, and the workers of `pool` share the visit.
    void store(std::span<const RigidContact> contacts, std::span<const int> listOrder = {}, WorkerPool* pool = nullptr);
    /// Moves the stored points to their bodies' new slots, dropping those of bodies that left.
    void remap(const SlotRemap& remap);

private:
    /// The entries gathered in list order; false if they do not come out in key order.
    bool storeInListOrder(std::span<const RigidContact> contacts, std::span<const int> listOrder, WorkerPool* pool);
    /// Calls take(entry) for each point of `c` that pushed (the points the table remembers), in order.
    template <class Take>
    static void forEachEntry(const RigidContact& c, Take take);
    /// The table's order: by pair, then feature.
    static bool keyLess(const Entry& a, const Entry& b) {
        return a.pair != b.pair ? a.pair < b.pair : a.feature < b.feature;
    }
    std::vector<Entry> entries_; ///< sorted by (pair, feature)
    std::vector<std::size_t> chunkEntries_;    ///< store: entries in each chunk of the list
    std::vector<std::uint8_t> chunkAscending_; ///< store: whether each chunk's entries ascend
};

} // namespace rube
