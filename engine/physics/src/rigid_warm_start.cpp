// Warm starting of rigid contacts between steps: a sorted table of the last step's impulses.
#include "rigid_warm_start.hpp"

#include <algorithm>
#include <tuple>

namespace rube {

namespace {

/// Contacts in a worker's share of the look-ups (one costs a few tens of nanoseconds).
constexpr std::size_t kApplyChunk = 256;
/// Contacts in a worker's share of the store (one costs a few nanoseconds).
constexpr std::size_t kStoreChunk = 512;

/// One number per body pair: side A (always a rigid body), whether B is rigid, and B's index.
std::uint64_t pairKey(const RigidContact& c) {
    return static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.a.index)) << 32 |
           static_cast<std::uint64_t>(c.b.rigid ? 0u : 1u) << 31 | static_cast<std::uint32_t>(c.b.index);
}

} // namespace

template <class Take>
void RigidContactCache::forEachEntry(const RigidContact& c, Take take) {
    const std::uint64_t pair = pairKey(c);
    for (int k = 0; k < c.count; ++k) {
        const RigidContactPoint& p = c.points[k];
        if (p.normalImpulse > 0.0) take(Entry{pair, p.feature, p.normalImpulse, p.tangentImpulse});
    }
}

void RigidContactCache::apply(std::span<RigidContact> contacts, WorkerPool* pool) const {
    if (entries_.empty()) return;
    // Each contact looks itself up and writes only itself: any split among the workers, the same impulses.
    forShares(pool, contacts.size(), kApplyChunk, [&](std::size_t first, std::size_t last) {
        Lookup lookup(*this);
        for (std::size_t k = first; k < last; ++k) lookup.apply(contacts[k]);
    });
}

void RigidContactCache::Lookup::apply(RigidContact& c) {
    if (entries_.empty()) return;
    const auto before = [](const Entry& e, const std::tuple<std::uint64_t, std::uint32_t>& key) {
        return std::make_tuple(e.pair, e.feature) < key;
    };
    const std::uint64_t pair = pairKey(c);
    for (int k = 0; k < c.count; ++k) {
        RigidContactPoint& p = c.points[k];
        const auto key = std::make_tuple(pair, p.feature);
        if (from_ > 0 && !before(entries_[from_ - 1], key)) from_ = 0; // behind the last one: search all
        std::size_t step = 1, lo = from_;
        while (lo + step <= entries_.size() && before(entries_[lo + step - 1], key)) {
            lo += step;
            step *= 2;
        }
        const auto first = entries_.begin() + static_cast<std::ptrdiff_t>(lo);
        const auto last = entries_.begin() + static_cast<std::ptrdiff_t>(std::min(lo + step, entries_.size()));
        const auto it = std::lower_bound(first, last, key, before);
        from_ = static_cast<std::size_t>(it - entries_.begin());
        if (it == entries_.end() || it->pair != pair || it->feature != p.feature) continue;
        p.normalImpulse = it->normalImpulse;
        p.tangentImpulse = it->tangentImpulse;
        p.carried = it->normalImpulse > 0.0;
    }
}

void RigidContactCache::remap(const SlotRemap& remap) {
    const int oldCircles = static_cast<int>(remap.circles.to.size());
    std::size_t kept = 0;
    for (const Entry& e : entries_) {
        // Side A is a rigid body; side B a rigid body, or a solver body (circles, then segments).
        const int a = remap.bodies(static_cast<int>(e.pair >> 32));
        const bool rigid = (e.pair >> 31 & 1u) == 0;
        const int oldB = static_cast<int>(e.pair & 0x7fffffffu);
        const int b = rigid               ? remap.bodies(oldB)
                      : oldB < oldCircles ? remap.circles(oldB)
                                          : (remap.segments(oldB - oldCircles) < 0
                                                 ? -1
                                                 : remap.circles.size + remap.segments(oldB - oldCircles));
        if (a < 0 || b < 0) continue;
        Entry moved = e;
        moved.pair = static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32 |
                     static_cast<std::uint64_t>(rigid ? 0u : 1u) << 31 | static_cast<std::uint32_t>(b);
        entries_[kept++] = moved;
    }
    entries_.resize(kept);
    std::sort(entries_.begin(), entries_.end(), keyLess);
}

void RigidContactCache::store(std::span<const RigidContact> contacts, std::span<const int> listOrder,
                              WorkerPool* pool) {
    // Visited in list order (contacts[listOrder[k]]), which is key order (RigidStage::findContacts:
    // body by body, the others by index), the entries come sorted but for a contact's two points,
    // which one swap puts right. Anything else (no list order, or two entries sharing a key) is sorted
    // from the contacts' own order, as always, so warm starting never depends on the shortcut.
    if (!listOrder.empty() && listOrder.size() == contacts.size() && storeInListOrder(contacts, listOrder, pool))
        return;
    entries_.clear();
    for (const RigidContact& c : contacts) forEachEntry(c, [&](const Entry& e) { entries_.push_back(e); });
    std::sort(entries_.begin(), entries_.end(), keyLess);
}

bool RigidContactCache::storeInListOrder(std::span<const RigidContact> contacts, std::span<const int> listOrder,
                                         WorkerPool* pool) {
    const auto at = [&](std::size_t visit) -> const RigidContact& {
        return contacts[static_cast<std::size_t>(listOrder[visit])];
    };
    // Two phases over chunks of the list: each chunk counts its pushing points, then writes their
    // entries at the sum of the counts before it, puts each contact's two in key order and checks
    // that its entries ascend. The entries land where one gather in list order puts them, for any split.
    const std::size_t n = listOrder.size();
    const std::size_t chunkCount = (n + kStoreChunk - 1) / kStoreChunk;
    chunkEntries_.assign(chunkCount, 0);
    chunkAscending_.assign(chunkCount, 1);
    const auto count = [&](std::size_t first, std::size_t last) {
        std::size_t entries = 0;
        for (std::size_t visit = first; visit < last; ++visit)
            forEachEntry(at(visit), [&](const Entry&) { ++entries; });
        chunkEntries_[first / kStoreChunk] = entries;
    };
    const auto fill = [&](std::size_t first, std::size_t last) {
        const std::size_t chunk = first / kStoreChunk;
        std::size_t out = 0;
        for (std::size_t j = 0; j < chunk; ++j) out += chunkEntries_[j];
        const std::size_t begin = out;
        for (std::size_t visit = first; visit < last; ++visit)
            forEachEntry(at(visit), [&](const Entry& e) { entries_[out++] = e; });
        for (std::size_t k = begin + 1; k < out; ++k)
            if (entries_[k - 1].pair == entries_[k].pair && keyLess(entries_[k], entries_[k - 1]))
                std::swap(entries_[k - 1], entries_[k]);
        bool ascending = true;
        for (std::size_t k = begin + 1; k < out && ascending; ++k) ascending = keyLess(entries_[k - 1], entries_[k]);
        chunkAscending_[chunk] = ascending ? 1 : 0;
    };
    entries_.resize(2 * n); // room for every point (two a contact) before the counts are summed
    if (worthSharing(pool, n, kStoreChunk)) {
        const std::size_t sizes[2] = {n, n}, chunks[2] = {kStoreChunk, kStoreChunk};
        auto work = [&](int phase, std::size_t first, std::size_t last) {
            if (phase == 0) count(first, last);
            else fill(first, last); // the counting phase is done: every count is in
        };
        pool->run(2, sizes, chunks, work);
    } else {
        for (std::size_t first = 0; first < n; first += kStoreChunk) count(first, std::min(n, first + kStoreChunk));
        for (std::size_t first = 0; first < n; first += kStoreChunk) fill(first, std::min(n, first + kStoreChunk));
    }
    std::size_t total = 0;
    for (const std::size_t e : chunkEntries_) total += e;
    entries_.resize(total);
    // In key order only if every chunk ascends and so does each seam between two chunks. (Where one
    // gather would have swapped across a seam, the keys ascend after the swap, all distinct: the sort
    // that follows a refusal here gives that same order.)
    if (std::find(chunkAscending_.begin(), chunkAscending_.end(), 0) != chunkAscending_.end()) return false;
    std::size_t seam = 0;
    for (std::size_t j = 0; j + 1 < chunkCount; ++j) {
        seam += chunkEntries_[j];
        if (seam > 0 && seam < total && !keyLess(entries_[seam - 1], entries_[seam])) return false;
    }
    return true;
}

} // namespace rube
