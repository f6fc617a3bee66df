// Warm starting of rigid contacts between steps: a sorted table of the last step's impulses.
#include "rigid_warm_start.hpp"

#include <algorithm>
#include <tuple>

namespace rube {

namespace {

/// Contacts in a worker's share of the look-ups (one costs a few tens of nanoseconds).
constexpr std::size_t kApplyChunk = 256;

/// One number per body pair: side A (always a rigid body), whether B is rigid, and B's index.
std::uint64_t pairKey(const RigidContact& c) {
    return static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.a.index)) << 32 |
           static_cast<std::uint64_t>(c.b.rigid ? 0u : 1u) << 31 | static_cast<std::uint32_t>(c.b.index);
}

} // namespace

void RigidContactCache::apply(std::span<RigidContact> contacts, WorkerPool* pool) const {
    if (entries_.empty()) return;
    // Each contact looks itself up and writes only itself: any split among the workers, the same impulses.
    forShares(pool, contacts.size(), kApplyChunk,
              [&](std::size_t first, std::size_t last) { applyTo(contacts.subspan(first, last - first)); });
}

void RigidContactCache::applyTo(std::span<RigidContact> contacts) const {
    const auto before = [](const Entry& e, const std::tuple<std::uint64_t, std::uint32_t>& key) {
        return std::make_tuple(e.pair, e.feature) < key;
    };
    // Contacts come mostly in key order (body by body), so each search gallops on from where the last
    // one ended (doubling steps, then a binary search within the last step): the same first entry not
    // before the key as a search over the whole table, found in a few steps.
    std::size_t from = 0;
    for (RigidContact& c : contacts) {
        const std::uint64_t pair = pairKey(c);
        for (int k = 0; k < c.count; ++k) {
            RigidContactPoint& p = c.points[k];
            const auto key = std::make_tuple(pair, p.feature);
            if (from > 0 && !before(entries_[from - 1], key)) from = 0; // behind the last one: search all
            std::size_t step = 1, lo = from;
            while (lo + step <= entries_.size() && before(entries_[lo + step - 1], key)) {
                lo += step;
                step *= 2;
            }
            const auto first = entries_.begin() + static_cast<std::ptrdiff_t>(lo);
            const auto last = entries_.begin() + static_cast<std::ptrdiff_t>(std::min(lo + step, entries_.size()));
            const auto it = std::lower_bound(first, last, key, before);
            from = static_cast<std::size_t>(it - entries_.begin());
            if (it == entries_.end() || it->pair != pair || it->feature != p.feature) continue;
            p.normalImpulse = it->normalImpulse;
            p.tangentImpulse = it->tangentImpulse;
            p.carried = it->normalImpulse > 0.0;
        }
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
    std::sort(entries_.begin(), entries_.end(), [](const Entry& x, const Entry& y) {
        return std::make_tuple(x.pair, x.feature) < std::make_tuple(y.pair, y.feature);
    });
}

void RigidContactCache::store(std::span<const RigidContact> contacts, std::span<const int> listOrder) {
    // Visited in list order (contacts[listOrder[k]]), which is key order (RigidStage::findContacts:
    // body by body, the others by index), the entries are one ascending run; visited colour by colour,
    // each colour in list order, a few. Merged, the runs are what a sort gives, at a fraction of its
    // cost. A contact's points are put in feature order first. Should two entries share a key, a sort
    // of the entries in the contacts' own order decides as it always did, so warm starting never
    // depends on the merge.
    const auto less = [](const Entry& a, const Entry& b) {
        return std::make_tuple(a.pair, a.feature) < std::make_tuple(b.pair, b.feature);
    };
    entries_.clear();
    runs_.clear();
    const bool listed = !listOrder.empty() && listOrder.size() == contacts.size();
    for (std::size_t visit = 0; visit < contacts.size(); ++visit) {
        const RigidContact& c = contacts[listed ? static_cast<std::size_t>(listOrder[visit]) : visit];
        const std::uint64_t pair = pairKey(c);
        const std::size_t first = entries_.size();
        for (int k = 0; k < c.count; ++k) {
            const RigidContactPoint& p = c.points[k];
            if (p.normalImpulse > 0.0) entries_.push_back({pair, p.feature, p.normalImpulse, p.tangentImpulse});
        }
        if (entries_.size() == first) continue;
        if (entries_.size() - first == 2 && less(entries_[first + 1], entries_[first]))
            std::swap(entries_[first], entries_[first + 1]);
        if (first == 0 || less(entries_[first - 1], entries_[first])) continue;
        runs_.push_back(first); // a run starts here
    }
    // The runs' bounds [0, r1, ..., n), adjacent runs merged pairwise, round after round: log2(runs)
    // passes over the entries.
    runs_.insert(runs_.begin(), 0);
    runs_.push_back(entries_.size());
    const auto at = [&](std::size_t k) { return entries_.begin() + static_cast<std::ptrdiff_t>(k); };
    while (runs_.size() > 2) {
        std::size_t kept = 1;
        for (std::size_t r = 0; r + 1 < runs_.size(); r += 2) {
            const std::size_t end = r + 2 < runs_.size() ? runs_[r + 2] : runs_[r + 1];
            if (r + 2 < runs_.size()) std::inplace_merge(at(runs_[r]), at(runs_[r + 1]), at(end), less);
            runs_[kept++] = end;
        }
        runs_.resize(kept);
    }
    for (std::size_t k = 1; k < entries_.size(); ++k)
        if (!less(entries_[k - 1], entries_[k])) {
            // Two entries share a key: the sort of the entries as listed, as before the runs were merged.
            entries_.clear();
            for (const RigidContact& c : contacts) {
                const std::uint64_t pair = pairKey(c);
                for (int j = 0; j < c.count; ++j) {
                    const RigidContactPoint& p = c.points[j];
                    if (p.normalImpulse > 0.0)
                        entries_.push_back({pair, p.feature, p.normalImpulse, p.tangentImpulse});
                }
            }
            std::sort(entries_.begin(), entries_.end(), less);
            return;
        }
}

} // namespace rube
