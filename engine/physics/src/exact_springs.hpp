#pragma once
// Internal to the exact method (method_exact.cpp) and auto (auto_islands.cpp): a circle held by a
// spring to a fixed point moves on the spring's closed form between impacts, so the exact method
// carries it as exactly as it carries a parabola. Not part of the public API.
//
// With the spring force f = -k (|d| - L0) n - c (n . v) n (joint_spring.cpp), d = p - anchor,
// n = d / |d|, and gravity g, the motion is linear, hence closed form, in two cases only:
//   - L0 = 0 and c = 0: f = -k d, the 2-D isotropic oscillator, whatever the motion;
//   - the body on the spring's line, moving along it, with gravity along it (or none): 1-D,
//     m s'' = -k (s - L0) - c s' + m g.n, as long as s = d.n keeps its sign (or L0 = 0).
// Both are  y'' + 2 zeta omega y' + omega^2 y = 0  for y = p - x_eq, with omega^2 = k / m,
// zeta = c / (2 sqrt(k m)) and x_eq = anchor + L0 n + g / omega^2, per component. Anything else
// (rest length with a perpendicular offset, radial damping off the line, one-sided springs, two
// bodies, an anchor off the centre, a box) is not linear and has no closed form: `exactSpringRefusal`
// names why, the exact method refuses it and auto gives its island to the solver.

#include "step_method.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rube {

/// Thrown by the exact method when a spring it was given has no closed form, or an impact within
/// the step put its circle where it has none (off the spring's line). The world's bodies are as
/// they were when the method began; auto takes it as a failed exact trial.
class SpringNotExact : public std::logic_error {
public:
    SpringNotExact(const std::string& what, int circle = -1) : std::logic_error(what), circle(circle) {}
    int circle; ///< the circle (the step context's slot) knocked off its closed form, or -1
};

/// The damped oscillator y'' + 2 zeta omega y' + omega^2 y = 0 about x_eq, per component.
struct SpringPath {
    Vec2 equilibrium;   ///< x_eq = anchor + L0 n + g / omega^2, m
    double omega = 0.0; ///< sqrt(k / m), rad/s
    double zeta = 0.0;  ///< c / (2 sqrt(k m))
};

/// Position and velocity after t from (position, velocity) on the path: under-damped
///   y = e^(-zeta omega t) (y0 cos(wd t) + (u0 + zeta omega y0) sin(wd t) / wd),  wd = omega sqrt(1 - zeta^2),
/// critically damped y = e^(-omega t) (y0 + (u0 + omega y0) t), over-damped with cosh and sinh of
/// s t, s = omega sqrt(zeta^2 - 1); the velocities are their derivatives.
void springMove(const SpringPath& path, Vec2& position, Vec2& velocity, double t);

/// A bound on the speed over all later times: the oscillator's energy |v|^2 / 2 + omega^2 |y|^2 / 2
/// never grows (damping only takes), so |v| <= sqrt(|v0|^2 + omega^2 |y0|^2).
double springSpeedBound(const SpringPath& path, Vec2 position, Vec2 velocity);

/// Why joint `j` has no closed form under the exact method as the bodies stand now, or empty when
/// it has one. `withBlocks`: the world has rigid bodies (exact's block searches assume parabolas).
std::string exactSpringRefusal(const Joint& j, std::span<const Circle> circles, Vec2 gravity, bool withBlocks);

/// The slot of the circle a spring to the world holds (-1 when neither end is a circle).
int springCircle(const Joint& j);
/// The closed form's x_eq, omega and zeta for spring `j` holding circle `c` (one without a refusal).
SpringPath springPathOf(const Joint& j, const Circle& c, Vec2 gravity);

/// The spring-held circles of one exact step.
class ExactSprings {
public:
    /// Reads the step's joints; throws SpringNotExact naming the first without a closed form.
    void build(const StepContext& ctx);
    bool empty() const { return held_.empty(); }
    /// The path of circle `i`, or nullptr when no spring holds it.
    const SpringPath* pathOf(int i) const {
        const int k = i < static_cast<int>(index_.size()) ? index_[static_cast<std::size_t>(i)] : -1;
        return k < 0 ? nullptr : &held_[static_cast<std::size_t>(k)].path;
    }
    /// After an impact changed circle `i`'s velocity: why its spring has no closed form any more
    /// (knocked off the spring's line, or through the anchor), else empty. The path itself (x_eq,
    /// omega, zeta) does not depend on the velocity.
    std::string recheck(const StepContext& ctx, int i) const;

private:
    struct Held {
        int joint = -1;
        int circle = -1;
        SpringPath path;
    };
    std::vector<Held> held_;
    std::vector<int> index_; ///< per circle: its entry in held_, or -1
};

} // namespace rube
