#pragma once
/// Debug overlays: what the trails (the lecture's debug key D) and the impact markers remember
/// between frames, and how they are drawn over the scene.

#include "rube/physics/world.hpp"
#include "rube/render/draw_list.hpp"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <unordered_map>
#include <vector>

namespace rube::game {

/// The recent path of every dynamic circle: its position after each step, and its centre at
/// each impact within the step, so that a bounce between two steps shows as a corner and not
/// as a shortcut. Points older than the window or beyond `maxPoints` are dropped, so memory
/// stays bounded however long the run.
class Trails {
public:
    /// Tracks the circles of `world` that are dynamic now, starting from where they are, keeping
    /// `seconds` of simulated time and at most `maxPoints` points per circle.
    Trails(const World& world, double seconds, std::size_t maxPoints);
    /// Adds the impacts and the positions of the step just taken; call after each step.
    void record(const World& world);
    /// One polyline per tracked circle, fading from transparent (oldest) to `color` (now).
    void draw(render::DrawList& list, render::Color color, float widthPixels) const;
    /// The points kept for the i-th tracked circle (in circle order), oldest first.
    std::vector<render::Point> pointsOf(std::size_t i) const;

private:
    struct Sample {
        render::Point at;
        double time = 0.0;
    };
    void add(std::size_t body, Vec2 at, double time);

    double seconds_;
    std::size_t maxPoints_;
    std::vector<int> slotOfCircle_;              // circle index -> tracked slot, or -1
    std::vector<int> circleOfSlot_;              // tracked slot -> circle index
    std::vector<std::deque<Sample>> samples_;    // per tracked slot, oldest first
    mutable std::vector<render::Point> scratch_; // one body's points, for the draw list
};

/// Impacts of the last `linger` seconds of simulated time, so that a point of impact stays on
/// screen for several frames (and is not lost between frames with --every K > 1). Only the
/// newest impact of each pair of bodies is kept: a resting or sliding contact, which reports an
/// impact every step, shows one marker where the bodies touch now, not a smear along its path.
class RecentImpacts {
public:
    /// Keeps impacts for `lingerSeconds`, and at most `maxKept` of them (the newest).
    RecentImpacts(double lingerSeconds, std::size_t maxKept);
    /// Takes the impacts of the step just taken and forgets those too old; call after each step.
    void record(const World& world);
    /// Each impact as a ring at its point of impact and an arrow along its collision normal
    /// (towards the circle that was hit), fading out as it ages; sizes in pixels.
    void draw(render::DrawList& list, double now, float pixelsPerMetre, render::Color ringColor,
              render::Color arrowColor) const;
    /// Impacts that draw() would show now: the newest of each pair, not yet expired.
    std::size_t shown() const { return newest_.size(); }

private:
    struct Kept {
        std::uint64_t sequence = 0; // the order impacts were recorded in
        Impact impact;
    };
    double linger_;
    std::size_t maxKept_;
    std::uint64_t nextSequence_ = 0;
    std::deque<Kept> impacts_;                                // oldest first
    std::unordered_map<std::uint64_t, std::uint64_t> newest_; // pair of bodies -> its newest impact's sequence
};

} // namespace rube::game
