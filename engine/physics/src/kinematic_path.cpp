// Scripted paths for kinematic bodies: piecewise-linear offsets over time.
#include "rube/physics/body.hpp"

#include <cmath>

namespace rube {

Vec2 KinematicPath::offsetAt(double t) const {
    if (keys.empty()) return {};
    if (keys.size() == 1) return keys.front().offset;
    const double start = keys.front().time;
    const double end = keys.back().time;
    if (loop && end > start) t = start + std::fmod(t - start, end - start);
    if (t <= start) return keys.front().offset;
    if (t >= end) return keys.back().offset;
    for (std::size_t i = 1; i < keys.size(); ++i) {
        if (t > keys[i].time) continue;
        const PathKey& k0 = keys[i - 1];
        const PathKey& k1 = keys[i];
        const double span = k1.time - k0.time;
        return span > 0.0 ? lerp(k0.offset, k1.offset, (t - k0.time) / span) : k1.offset;
    }
    return keys.back().offset;
}

} // namespace rube
