#pragma once
// Internal to the exact method (method_exact.cpp): circles held on static line faces for the rest of
// a step. A resting contact on a face holds the ball on it: it slides along the face under the part of
// gravity (and of a magnet's pull) the face does not cancel, so its next impact (the other side of a V) is found
// exactly, and a ball held by two faces that are not parallel stands still. Not part of the public API.

#include "step_method.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace rube {

/// A circle held on a static line's face for the rest of the step.
struct HeldFace {
    int circle = -1;
    int segment = -1;
    Vec2 normal; ///< of the face, towards the circle
};

/// The faces holding circles in one exact step, and the acceleration each circle is left with.
class HeldFaces {
public:
    /// Starts a step: no face holds anything, every circle falls with `gravity`.
    void reset(std::size_t circleCount, Vec2 gravity);
    /// Circle `circle` falls with `free` instead when no face holds it (gravity and a magnet's pull).
    void setFreeAcceleration(int circle, Vec2 free);
    bool empty() const { return faces_.empty(); }
    int size() const { return static_cast<int>(faces_.size()); }
    /// Its free acceleration, or what the faces holding circle `circle` leave of it.
    Vec2 acceleration(int circle) const { return accelerations_[static_cast<std::size_t>(circle)]; }
    /// A resting contact of `circle` on `segment`'s face (normal towards the circle): held there when the
    /// line is fixed and its free acceleration presses the circle on it; wedged (velocity zero) against a face it holds
    /// at an angle.
    void hold(StepContext& ctx, int circle, int segment, Vec2 normal);
    /// The earliest time within the horizon at which face `f`'s circle passes an end of the face.
    std::optional<double> leavesFace(const StepContext& ctx, int f, double horizon) const;
    /// Face `f` ends: its circle falls freely unless another face holds it. Returns the face released.
    HeldFace release(int f);
    /// A real impact: the circle is no longer held by any face.
    void letGo(int circle);

private:
    Vec2 heldAcceleration(int circle) const;

    std::vector<HeldFace> faces_;
    std::vector<Vec2> accelerations_; ///< per circle
    std::vector<Vec2> free_;          ///< per circle, with no face holding it
};

} // namespace rube
