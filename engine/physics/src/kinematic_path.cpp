// Scripted paths for kinematic bodies: piecewise-linear offsets (and turns) over time.
#include "kinematic_pose.hpp"

#include <cmath>

namespace rube {

namespace {

/// The value of `of(key)` at time t along the path's keys: straight lines in between, held before
/// the first and after the last key, or with `loop` starting again from the first.
template <class Value, class Of>
Value interpolate(const KinematicPath& path, double t, Of of) {
    const std::vector<PathKey>& keys = path.keys;
    if (keys.empty()) return Value{};
    if (keys.size() == 1) return of(keys.front());
    const double start = keys.front().time;
    const double end = keys.back().time;
    if (path.loop && end > start) t = start + std::fmod(t - start, end - start);
    if (t <= start) return of(keys.front());
    if (t >= end) return of(keys.back());
    for (std::size_t i = 1; i < keys.size(); ++i) {
        if (t > keys[i].time) continue;
        const PathKey& k0 = keys[i - 1];
        const PathKey& k1 = keys[i];
        const double span = k1.time - k0.time;
        return span > 0.0 ? of(k0) + (of(k1) - of(k0)) * ((t - k0.time) / span) : of(k1);
    }
    return of(keys.back());
}

} // namespace

Vec2 KinematicPath::offsetAt(double t) const {
    return interpolate<Vec2>(*this, t, [](const PathKey& k) { return k.offset; });
}

double KinematicPath::angleAt(double t) const {
    return interpolate<double>(*this, t, [](const PathKey& k) { return k.angle; });
}

bool KinematicPath::turns() const {
    for (const PathKey& k : keys)
        if (k.angle != 0.0) return true;
    return false;
}

void placeTurningSegment(Segment& s, const KinematicPath& path, double t) {
    // The pivot rides on the path's offset; both ends turn about it by the path's angle.
    const Vec2 pivot = lerp(s.originA, s.originB, s.pivotAlong);
    const Vec2 moved = pivot + path.offsetAt(t);
    const double angle = path.angleAt(t);
    s.a = moved + (s.originA - pivot).rotated(angle);
    s.b = moved + (s.originB - pivot).rotated(angle);
}

void placeTurningSegments(std::span<Segment> segments, std::span<const KinematicPath> paths, double t) {
    for (Segment& s : segments)
        if (s.path >= 0 && paths[static_cast<std::size_t>(s.path)].turns())
            placeTurningSegment(s, paths[static_cast<std::size_t>(s.path)], t);
}

} // namespace rube
