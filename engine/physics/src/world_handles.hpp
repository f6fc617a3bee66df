#pragma once
// Internal: the World's handle tables. The world's arrays stay packed in insertion order (every
// method iterates them as before); a handle names an entry of a table, and the entry names the
// thing's slot in its array. Removing or disabling a thing erases its slot stably (the others keep
// their order, so a world evolves as if the thing had never been there) and the slots after it move
// down by one; enabling it again puts it back where its insertion order says. Not part of the public API.

#include "rube/physics/handles.hpp"
#include "rube/physics/world.hpp"

#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

namespace rube {

/// Where every slot of one array went in a change: old slot -> new slot, -1 when it left the array.
/// `size` is the array's new size; new slots no old one maps to are things that just (re)entered.
struct SlotMap {
    std::vector<int> to;
    int size = 0;
    /// The new slot of `old`, or -1 (also for -1).
    int operator()(int old) const {
        return old < 0 || old >= static_cast<int>(to.size()) ? -1 : to[static_cast<std::size_t>(old)];
    }
    /// True when slot numbers changed.
    bool empty() const { return to.empty() && size == 0; }
};

/// A change of the world's arrays as the step methods see them: per kind, empty when it did not change.
struct SlotRemap {
    SlotMap circles, segments, bodies;
};

/// Applies `map` to an array parallel to the remapped one: kept entries move to their new slots,
/// new slots get `fill`.
template <class T>
void remapParallel(std::vector<T>& items, const SlotMap& map, const T& fill) {
    if (map.empty()) return;
    std::vector<T> out(static_cast<std::size_t>(map.size), fill);
    for (std::size_t old = 0; old < items.size() && old < map.to.size(); ++old)
        if (map.to[old] >= 0) out[static_cast<std::size_t>(map.to[old])] = items[old];
    items.swap(out);
}

/// One kind's table of handles: a generation and a slot per entry, and each slot's entry.
class HandleTable {
public:
    struct Entry {
        std::uint32_t generation = 1;
        bool live = false;          ///< made and not removed
        bool enabled = true;        ///< in the array (a disabled thing waits outside it)
        int slot = -1;              ///< its slot in the array while enabled, else -1
        std::uint64_t sequence = 0; ///< insertion order: where it goes back when enabled again
        std::uint64_t userValue = 0;
        double gravityScale = 1.0; ///< kept while disabled (circles and rigid bodies)
    };

    /// A new entry whose thing is appended to the array (slot = the array's size before).
    int create(int slot);
    /// The entry of `index`/`generation`, or null when no live entry has them.
    Entry* find(std::int32_t index, std::uint32_t generation);
    const Entry* find(std::int32_t index, std::uint32_t generation) const;
    /// As find, but throws std::invalid_argument naming `what` for a stale or null handle.
    Entry& at(std::int32_t index, std::uint32_t generation, const char* what);
    const Entry& at(std::int32_t index, std::uint32_t generation, const char* what) const;
    Entry& entry(int index) { return entries_[static_cast<std::size_t>(index)]; }
    /// The entry in `slot`.
    int entryOfSlot(int slot) const { return slotEntries_[static_cast<std::size_t>(slot)]; }
    int slotCount() const { return static_cast<int>(slotEntries_.size()); }
    /// How many entries there are, live or retired.
    int entryCount() const { return static_cast<int>(entries_.size()); }
    /// Takes entry `index`'s thing out of the array (stable): returns where the slots went.
    SlotMap leave(int index);
    /// Puts entry `index`'s thing back into the array in insertion order: returns where the slots
    /// went (its own new slot is entry(index).slot).
    SlotMap enter(int index);
    /// Ends entry `index` (after `leave`): its generation moves on and the entry may be reused.
    void retire(int index);

private:
    std::vector<Entry> entries_;
    std::vector<int> slotEntries_; ///< per slot, its entry
    std::vector<int> free_;        ///< retired entries, reused last-in first-out
    std::uint64_t nextSequence_ = 0;
};

/// The handle of table entry `index`.
template <class Id>
Id handleOf(HandleTable& table, int index) {
    return Id{index, table.entry(index).generation};
}

/// The handle of the thing in `slot` of `table`'s array; throws std::out_of_range past the end.
template <class Id>
Id idOfSlot(const HandleTable& table, int slot) {
    if (slot < 0 || slot >= table.slotCount()) throw std::out_of_range("no such slot");
    const int entry = table.entryOfSlot(slot);
    return Id{entry, const_cast<HandleTable&>(table).entry(entry).generation};
}

/// The world's tables, and the state of what waits outside the arrays (by table entry).
struct WorldTables {
    HandleTable circles, segments, bodies, ropes, pivots, joints;
    std::vector<Circle> parkedCircles;                    ///< per circle entry: its state while disabled
    std::vector<Segment> parkedSegments;                  ///< per segment entry, likewise
    std::vector<RigidBody> parkedBodies;                  ///< per body entry, likewise
    std::vector<Rope> parkedRopes;                        ///< per rope entry: the rope while it does not act
    std::vector<Pivot> parkedPivots;                      ///< per pivot entry, likewise
    std::vector<Joint> parkedJoints;                      ///< per joint entry, likewise
    std::vector<std::uint8_t> ropeOn, pivotOn, jointOn;   ///< per entry: its own switch (setEnabled)
    std::vector<std::uint8_t> circleEscaped, bodyEscaped; ///< per entry: escaped before it was disabled (counted once)
    std::vector<int> thrusterSlots;                       ///< per thruster: its circle's slot this step, -1 none
};

/// Grows a per-entry vector to hold `index`.
template <class T>
T& perEntry(std::vector<T>& items, int index) {
    if (static_cast<std::size_t>(index) >= items.size()) items.resize(static_cast<std::size_t>(index) + 1);
    return items[static_cast<std::size_t>(index)];
}

} // namespace rube
