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
    const auto less = [](const Entry& a, const Entry& b) {
        return std::make_tuple(a.pair, a.feature) < std::make_tuple(b.pair, b.feature);
    };
    // Every pushing point's entry, the contacts visited in the order `at` gives.
    const auto gather = [&](auto at) {
        entries_.clear();
        for (std::size_t visit = 0; visit < contacts.size(); ++visit) {
            const RigidContact& c = contacts[at(visit)];
            const std::uint64_t pair = pairKey(c);
            for (int k = 0; k < c.count; ++k) {
                const RigidContactPoint& p = c.points[k];
                if (p.normalImpulse > 0.0) entries_.push_back({pair, p.feature, p.normalImpulse, p.tangentImpulse});
            }
        }
    };
    // Visited in list order (contacts[listOrder[k]]), which is key order (RigidStage::findContacts:
    // body by body, the others by index), the entries come sorted but for a contact's two points,
    // which one swap puts right. Anything else (no list order, or two entries sharing a key) is sorted
    // from the contacts' own order, as always, so warm starting never depends on the shortcut.
    if (!listOrder.empty() && listOrder.size() == contacts.size()) {
        gather([&](std::size_t visit) { return static_cast<std::size_t>(listOrder[visit]); });
        for (std::size_t k = 1; k < entries_.size(); ++k)
            if (entries_[k - 1].pair == entries_[k].pair && less(entries_[k], entries_[k - 1]))
                std::swap(entries_[k - 1], entries_[k]);
        bool ascending = true;
        for (std::size_t k = 1; k < entries_.size() && ascending; ++k) ascending = less(entries_[k - 1], entries_[k]);
        if (ascending) return;
    }
    gather([](std::size_t visit) { return visit; });
    std::sort(entries_.begin(), entries_.end(), less);
}

} // namespace rube
