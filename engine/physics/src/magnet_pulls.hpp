#pragma once
// Internal: the magnets' kicks a method takes back for one step (exact and the solver). A magnet's
// pull, kicked in whole at the step's start (field_pass.cpp), brought a ball it holds on the magnet
// back at the kick's speed every step, a touch fast enough to bounce: a ball hanging still reported
// 0.23 m/s away from the magnet every step. Taken back, the pull moves the ball as gravity does, a
// constant acceleration a0 = F(x0) / m over the step (exact on its parabola, the solver a share each
// substep), a touch no faster than that acceleration gives rests, and after the step the velocity
// gets (a1 - a0) dt / 2 with a1 the pull where the ball ended: velocity Verlet, x1 = x0 + v0 dt +
// a0 dt^2 / 2 and v1 = v0 + (a0 + a1) dt / 2, second order where the kick is first. Not part of
// the public API.

#include "field_pass.hpp"

#include <cstddef>
#include <span>
#include <vector>

namespace rube {

/// Per circle, the magnets' kick a0 dt one step took back (zero for the circles it did not).
class MagnetPulls {
public:
    /// Starts a step: the kick magnetKick gives each circle `skip(i)` does not pass over; none (empty)
    /// when there is no magnet. The caller takes each kick() out of the velocity it steps.
    template <class Skip>
    void takeBack(std::span<const Circle> circles, std::span<const Magnet> magnets, double dt, Skip skip) {
        kicks_.clear();
        if (magnets.empty()) return;
        kicks_.assign(circles.size(), Vec2{});
        for (std::size_t i = 0; i < circles.size(); ++i)
            if (!skip(i)) kicks_[i] = magnetKick(magnets, circles[i], dt);
    }
    /// None taken back this step.
    void clear() { kicks_.clear(); }
    bool empty() const { return kicks_.empty(); }
    std::size_t size() const { return kicks_.size(); }
    /// Circle i's kick taken back, zero when none (or when there was no magnet).
    Vec2 kick(std::size_t i) const { return i < kicks_.size() ? kicks_[i] : Vec2{}; }
    /// The resting threshold a pulled circle needs, as the world's is for gravity alone (2 |g| dt +
    /// 1e-3, World::stepContext): 2 |g dt + a0 dt| + 1e-3, what the pull and gravity give it in a
    /// step; 0 for a circle no magnet pulled.
    double restingSpeed(std::size_t i, Vec2 gravity, double dt) const;
    /// After the step: half the change of pull, (a1 - a0) dt / 2, to every pulled circle.
    void finish(std::span<Circle> circles, std::span<const Magnet> magnets, double dt) const;

private:
    std::vector<Vec2> kicks_;
};

} // namespace rube
