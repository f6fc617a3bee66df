#pragma once
// Internal: a StepContext over some of the world's bodies, so `auto` can run exact on some islands
// and the solver on the others. The chosen dynamic circles and rigid bodies are copied out with
// every non-dynamic circle (infinite masses every island shares), the method runs on the copies,
// and the results are written back. Segments, impacts and counters are the world's own; impacts
// are given back the world's indices, and asleep circles keep naming their island by a world index.

#include "step_method.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace rube {

/// Some of a step's bodies, copied out to be stepped by one method.
class StepSubset {
public:
    /// Copies out dynamic circle i when chosen[i], rigid body b when chosen[circles + b], every
    /// non-dynamic circle, and the pivots and joints of the chosen bodies (a joint's ends share an island).
    void gather(const StepContext& world, std::span<const std::uint8_t> chosen);
    /// A context over the copies; segments, impacts and counters are the world's, the def is `def`.
    StepContext context(const StepContext& world, const WorldDef& def);
    /// Writes the chosen bodies back, and the non-dynamic circles too when `shared` (one method's
    /// motion of them is kept); gives the impacts from `firstImpact` on the world's indices.
    void scatter(StepContext& world, bool shared, std::size_t firstImpact);
    /// Gives the impacts from `firstImpact` on the world's indices (scatter does it too).
    void remapImpacts(StepContext& world, std::size_t firstImpact) const;
    /// Turns the written-back circles on at their constant spin (for a method that does not turn
    /// them, in a step where the world leaves the turning to the solver).
    void carryAngles(StepContext& world, bool shared, double dt) const;
    /// The world index of each copied circle, in order.
    std::span<const int> circleIndices() const { return circleMap_; }
    /// The world index of each copied rigid body, in order.
    std::span<const int> bodyIndices() const { return bodyMap_; }

private:
    std::vector<Circle> circles_;
    std::vector<RigidBody> bodies_;
    std::vector<Pivot> pivots_;
    std::vector<Joint> joints_;
    std::vector<int> circleMap_;     // copy -> world
    std::vector<int> bodyMap_;       // copy -> world
    std::vector<int> circleInverse_; // world -> copy, -1 when not copied
    std::vector<int> bodyInverse_;   // world -> copy, -1 when not copied
};

} // namespace rube
