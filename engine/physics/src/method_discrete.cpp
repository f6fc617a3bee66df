// The discrete method (lecture 5's first method, lecture 3's fixed time step): move every body over
// the whole step, then push overlaps apart and reflect. Cheap, and honest about where it fails: a
// ball tunnels through a line when speed x dt > 2 (r + segment radius), and stacks sink.
#include "block_pairs.hpp"
#include "resolve.hpp"
#include "step_method.hpp"

#include <algorithm>
#include <vector>

namespace rube {
namespace {

class DiscreteMethod final : public StepMethod {
public:
    void step(StepContext& ctx, double dt) override {
        // Where each centre starts: it decides which side of a line a circle is pushed back to.
        startCentres_.resize(ctx.circles.size());
        for (std::size_t i = 0; i < ctx.circles.size(); ++i) startCentres_[i] = ctx.circles[i].position;

        // Semi-implicit Euler (lecture 3): velocity first, then position with the new velocity.
        for (Circle& c : ctx.circles) {
            if (c.motion == Motion::dynamic) c.velocity += ctx.def.gravity * dt;
            if (c.motion != Motion::fixed) c.position += c.velocity * dt;
        }
        for (Segment& s : ctx.segments) {
            if (s.motion() != Motion::kinematic) continue;
            s.a += s.velocity * dt;
            s.b += s.velocity * dt;
        }
        // "Try to correct overlapping positions, resolve collisions" (lecture 3), all at the end of the step.
        int events = separateOverlaps(ctx, startCentres_, dt, ctx.time + dt, true);
        if (!ctx.bodies.empty()) events += stepBlocks(ctx, dt);
        ctx.stats.maxEventsInStep = std::max(ctx.stats.maxEventsInStep, events);
    }

private:
    // Lecture 3's blocks the same way: semi-implicit Euler, then pushed out on the side they started.
    int stepBlocks(StepContext& ctx, double dt) {
        blockStarts_.resize(ctx.bodies.size());
        for (std::size_t i = 0; i < ctx.bodies.size(); ++i) {
            RigidBody& b = ctx.bodies[i];
            blockStarts_[i] = b.position;
            if (!isBlock(b)) continue;
            if (b.motion == Motion::dynamic) b.velocity += ctx.def.gravity * dt;
            if (b.motion != Motion::fixed) b.position += b.velocity * dt;
        }
        return separateBlockOverlaps(ctx, blockStarts_, dt, ctx.time + dt);
    }

    std::vector<Vec2> startCentres_; ///< reused every step: no allocation once grown
    std::vector<Vec2> blockStarts_;
};

} // namespace

std::unique_ptr<StepMethod> makeDiscreteMethod() { return std::make_unique<DiscreteMethod>(); }

} // namespace rube
