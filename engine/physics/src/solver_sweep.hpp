#pragma once
// Internal: the solver's continuous pass against tunnelling. Not part of the public API.
//
// Speculative contacts catch what comes within a circle's margin at the start of the step; a circle
// that moved further than that margin (a bullet: 5000 m/s is 83 m per step) may have passed through
// something the contacts never saw. Its straight motion over the step is swept against every shape,
// in the shape's own frame (relative motion, so moving bodies are handled too), and the earliest
// time of impact clamps it there, as Box2D's continuous pass does.

#include "broadphase_grid.hpp"
#include "solver_narrowphase.hpp"
#include "step_method.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace rube {

/// Earliest t in [0, 1] at which q0 + t d comes within `reach` of point c from outside, or -1
/// (|q0 + t d - c| = reach, the smaller root of the quadratic; lecture 5, circle-circle TOI).
double sweepPointCircle(Vec2 q0, Vec2 d, Vec2 c, double reach);

/// Earliest t in [0, 1] at which q0 + t d comes within `reach` of segment ab from outside, or -1:
/// the earliest entry into either face of the capsule's slab or either line cap.
double sweepPointCapsule(Vec2 q0, Vec2 d, Vec2 a, Vec2 b, double reach);

/// What the continuous pass reads besides the world: the step's start positions, margins and grid.
struct SweepInput {
    std::span<const Vec2> start;             ///< circle positions at the start of the step
    std::span<const double> margins;         ///< per circle: how far its contacts looked ahead
    std::span<const int> bullets;            ///< circles too fast to be filed along their path in the grid
    std::span<const std::uint8_t> isBullet;  ///< per circle
    std::span<const std::uint8_t> isDynamic; ///< per circle
    const ContactCache& contacts;            ///< this step's contacts: pairs the solver already kept apart
    std::span<const std::uint8_t>
        inFlight;            ///< per circle: no contact pushed it this step, so gravity alone bent its path
    int maxCellsPerAxis = 8; ///< a longer path than this looks at every shape instead
    std::span<const std::int64_t> connected = {}; ///< circle pairs a joint keeps from colliding (joint_stage.hpp)
};

/// The continuous pass, with candidate buffers kept between steps.
class ContinuousSweep {
public:
    /// For every dynamic circle that moved further than its margin this step (ctx.circles at the end of
    /// the step; segments still at their start, moving with their velocity), finds the earliest time of
    /// impact against any circle or segment, moves the circle there (carried along by the body it hit),
    /// resolves the bounce (v' = u - C (v - u), lecture 3) and records it. Returns the impacts recorded.
    int run(const SweepInput& in, BroadphaseGrid& grid, StepContext& ctx, double dt);

private:
    /// The earliest time of impact found: t in [0, 1] of the step, against a solver body index.
    struct Hit {
        double t = 2.0;
        int other = -1;
    };
    /// The earliest shape circle i's straight motion over the step enters (other = -1 for none).
    Hit earliestHit(int i, const SweepInput& in, BroadphaseGrid& grid, const StepContext& ctx, double dt);
    /// Moves circle i to its time of impact, bounces it and records the impact; true when recorded.
    bool resolve(int i, const Hit& hit, const SweepInput& in, StepContext& ctx, double dt);

    std::vector<int> circles_; // candidates from the grid
    std::vector<int> segments_;
};

} // namespace rube
