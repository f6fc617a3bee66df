// The exact method's resting pairs: short lists per circle (a circle rests on a handful of others at
// most, so a scan beats hashing).
#include "exact_resting_pairs.hpp"

#include <algorithm>

namespace rube {

void RestingPairs::reset(int circles) {
    circleCount_ = circles;
    of_.resize(static_cast<std::size_t>(circles));
    for (std::vector<Entry>& list : of_) list.clear();
}

std::uint8_t RestingPairs::state(int circle, Other kind, int other) const {
    const int column = columnOf(kind, other);
    for (const Entry& entry : of_[static_cast<std::size_t>(circle)])
        if (entry.column == column) return entry.state;
    return kSearched;
}

void RestingPairs::set(int circle, Other kind, int other, std::uint8_t state) {
    const auto mark = [&](int owner, int column) {
        std::vector<Entry>& list = of_[static_cast<std::size_t>(owner)];
        for (Entry& entry : list)
            if (entry.column == column) return void(entry.state = state);
        list.push_back(Entry{column, state});
    };
    mark(circle, columnOf(kind, other));
    if (kind == Other::circle) mark(other, circle);
}

void RestingPairs::forgetCircle(int circle) {
    std::vector<Entry>& list = of_[static_cast<std::size_t>(circle)];
    for (const Entry& entry : list)
        if (entry.column < circleCount_)
            std::erase_if(of_[static_cast<std::size_t>(entry.column)],
                          [&](const Entry& back) { return back.column == circle; });
    list.clear();
}

void RestingPairs::forgetSegment(int circle, int segment) {
    const int column = columnOf(Other::segment, segment);
    std::erase_if(of_[static_cast<std::size_t>(circle)], [&](const Entry& entry) { return entry.column == column; });
}

} // namespace rube
