// The World's handle tables: entries, generations, and stable slot changes (see world_handles.hpp).
#include "world_handles.hpp"

#include <algorithm>
#include <string>

namespace rube {

int HandleTable::create(int slot) {
    int index;
    if (!free_.empty()) {
        index = free_.back();
        free_.pop_back();
    } else {
        index = static_cast<int>(entries_.size());
        entries_.emplace_back();
    }
    Entry& e = entries_[static_cast<std::size_t>(index)];
    const std::uint32_t generation = e.generation;
    e = Entry{};
    e.generation = generation;
    e.live = true;
    e.slot = slot;
    e.sequence = nextSequence_++;
    slotEntries_.push_back(index);
    return index;
}

HandleTable::Entry* HandleTable::find(std::int32_t index, std::uint32_t generation) {
    if (index < 0 || static_cast<std::size_t>(index) >= entries_.size()) return nullptr;
    Entry& e = entries_[static_cast<std::size_t>(index)];
    return e.live && e.generation == generation ? &e : nullptr;
}

const HandleTable::Entry* HandleTable::find(std::int32_t index, std::uint32_t generation) const {
    return const_cast<HandleTable*>(this)->find(index, generation);
}

HandleTable::Entry& HandleTable::at(std::int32_t index, std::uint32_t generation, const char* what) {
    Entry* e = find(index, generation);
    if (!e) throw std::invalid_argument(std::string("no such ") + what + " (a null handle, or one that was removed)");
    return *e;
}

const HandleTable::Entry& HandleTable::at(std::int32_t index, std::uint32_t generation, const char* what) const {
    return const_cast<HandleTable*>(this)->at(index, generation, what);
}

SlotMap HandleTable::leave(int index) {
    Entry& e = entries_[static_cast<std::size_t>(index)];
    SlotMap map;
    const int count = slotCount();
    map.to.resize(static_cast<std::size_t>(count));
    for (int s = 0; s < count; ++s) map.to[static_cast<std::size_t>(s)] = s < e.slot ? s : s == e.slot ? -1 : s - 1;
    map.size = count - 1;
    slotEntries_.erase(slotEntries_.begin() + e.slot);
    for (int s = e.slot; s < map.size; ++s)
        entries_[static_cast<std::size_t>(slotEntries_[static_cast<std::size_t>(s)])].slot = s;
    e.slot = -1;
    e.enabled = false;
    return map;
}

SlotMap HandleTable::enter(int index) {
    Entry& e = entries_[static_cast<std::size_t>(index)];
    // The slots hold their things in insertion order: it goes before the first one inserted after it.
    const auto at = std::find_if(slotEntries_.begin(), slotEntries_.end(), [&](int other) {
        return entries_[static_cast<std::size_t>(other)].sequence > e.sequence;
    });
    const int slot = static_cast<int>(at - slotEntries_.begin());
    SlotMap map;
    const int count = slotCount();
    map.to.resize(static_cast<std::size_t>(count));
    for (int s = 0; s < count; ++s) map.to[static_cast<std::size_t>(s)] = s < slot ? s : s + 1;
    map.size = count + 1;
    slotEntries_.insert(at, index);
    for (int s = slot; s < map.size; ++s)
        entries_[static_cast<std::size_t>(slotEntries_[static_cast<std::size_t>(s)])].slot = s;
    e.enabled = true;
    return map;
}

void HandleTable::retire(int index) {
    Entry& e = entries_[static_cast<std::size_t>(index)];
    e.live = false;
    ++e.generation;
    free_.push_back(index);
}

} // namespace rube
