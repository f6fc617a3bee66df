// Debug overlays: bounded histories, drawn as plain shapes (the renderer knows nothing of bodies
// or impacts).
#include "debug_overlays.hpp"

#include <algorithm>
#include <cmath>

namespace rube::game {

namespace {

render::Point toPoint(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

// Sizes of an impact marker, in pixels: big enough to see on a 640x360 frame, small enough not
// to hide a pool ball (about 12 px across in a 1280x720 frame) it sits on.
constexpr float kRingRadius = 5.0f;
constexpr float kRingWidth = 2.0f;
constexpr float kArrowLength = 26.0f;
constexpr float kArrowWidth = 2.0f;

// One key per pair of bodies: the circle, and what it hit.
std::uint64_t pairKey(const Impact& impact) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(impact.circle)) << 32) ^
           (static_cast<std::uint64_t>(impact.otherKind) << 30) ^ static_cast<std::uint32_t>(impact.other);
}

} // namespace

Trails::Trails(const World& world, double seconds, std::size_t maxPoints)
    : seconds_(std::max(seconds, 0.0)), maxPoints_(std::max<std::size_t>(maxPoints, 2)) {
    const auto circles = world.circles();
    slotOfCircle_.assign(circles.size(), -1);
    for (std::size_t i = 0; i < circles.size(); ++i) {
        if (circles[i].motion != Motion::dynamic) continue;
        slotOfCircle_[i] = static_cast<int>(circleOfSlot_.size());
        circleOfSlot_.push_back(static_cast<int>(i));
    }
    samples_.resize(circleOfSlot_.size());
    for (std::size_t slot = 0; slot < circleOfSlot_.size(); ++slot) {
        add(slot, circles[static_cast<std::size_t>(circleOfSlot_[slot])].position, world.time());
    }
}

void Trails::add(std::size_t slot, Vec2 at, double time) {
    std::deque<Sample>& trail = samples_[slot];
    trail.push_back({toPoint(at), time});
    while (trail.size() > maxPoints_ || (trail.size() > 2 && time - trail.front().time > seconds_)) trail.pop_front();
}

void Trails::record(const World& world) {
    const auto circles = world.circles();
    // Where the circle was when it hit: the point of impact moved back along the normal by the
    // radius. The exact methods resolve impacts in time order, so corners come in order.
    for (const Impact& impact : world.lastImpacts()) {
        if (impact.circle < 0 || static_cast<std::size_t>(impact.circle) >= slotOfCircle_.size()) continue;
        const int slot = slotOfCircle_[static_cast<std::size_t>(impact.circle)];
        if (slot < 0) continue;
        const double radius = circles[static_cast<std::size_t>(impact.circle)].radius;
        const Vec2 centre{impact.pointOfImpact.x + impact.normal.x * radius,
                          impact.pointOfImpact.y + impact.normal.y * radius};
        const std::deque<Sample>& trail = samples_[static_cast<std::size_t>(slot)];
        if (!trail.empty() && impact.time < trail.back().time) continue; // a solver contact reported out of order
        add(static_cast<std::size_t>(slot), centre, impact.time);
    }
    for (std::size_t slot = 0; slot < circleOfSlot_.size(); ++slot) {
        add(slot, circles[static_cast<std::size_t>(circleOfSlot_[slot])].position, world.time());
    }
}

std::vector<render::Point> Trails::pointsOf(std::size_t i) const {
    std::vector<render::Point> points;
    for (const Sample& s : samples_.at(i)) points.push_back(s.at);
    return points;
}

void Trails::draw(render::DrawList& list, render::Color color, float widthPixels) const {
    for (const std::deque<Sample>& trail : samples_) {
        if (trail.size() < 2) continue;
        scratch_.clear();
        for (const Sample& s : trail) scratch_.push_back(s.at);
        list.polyline(scratch_, widthPixels, color.withAlpha(0), color);
    }
}

RecentImpacts::RecentImpacts(double lingerSeconds, std::size_t maxKept)
    : linger_(std::max(lingerSeconds, 0.0)), maxKept_(std::max<std::size_t>(maxKept, 1)) {}

void RecentImpacts::record(const World& world) {
    for (const Impact& impact : world.lastImpacts()) {
        newest_[pairKey(impact)] = nextSequence_;
        impacts_.push_back({nextSequence_++, impact});
    }
    // Impacts arrive in time order, so the old ones are all at the front.
    while (!impacts_.empty() && (impacts_.size() > maxKept_ || world.time() - impacts_.front().impact.time > linger_)) {
        const auto it = newest_.find(pairKey(impacts_.front().impact));
        if (it != newest_.end() && it->second == impacts_.front().sequence) newest_.erase(it);
        impacts_.pop_front();
    }
}

void RecentImpacts::draw(render::DrawList& list, double now, float pixelsPerMetre, render::Color ringColor,
                         render::Color arrowColor) const {
    const float metresPerPixel = pixelsPerMetre > 0.0f ? 1.0f / pixelsPerMetre : 0.0f;
    for (const auto& [sequence, impact] : impacts_) {
        const auto newest = newest_.find(pairKey(impact));
        if (newest == newest_.end() || newest->second != sequence) continue; // an older impact of a pair
        const double age = now - impact.time;
        if (age < 0.0 || age > linger_) continue;
        // Full strength on the frame of the impact, fading linearly to nothing after `linger`.
        const double strength = linger_ > 0.0 ? 1.0 - age / linger_ : 1.0;
        const auto fade = [&](render::Color c) {
            return c.withAlpha(static_cast<std::uint8_t>(std::lround(c.a * strength)));
        };
        const render::Point at = toPoint(impact.pointOfImpact);
        const render::Point tip{at.x + static_cast<float>(impact.normal.x) * kArrowLength * metresPerPixel,
                                at.y + static_cast<float>(impact.normal.y) * kArrowLength * metresPerPixel};
        list.ring(at, kRingRadius * metresPerPixel, kRingWidth, fade(ringColor));
        list.arrow(at, tip, kArrowWidth, fade(arrowColor));
    }
}

} // namespace rube::game
