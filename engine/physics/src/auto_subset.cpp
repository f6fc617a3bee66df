// auto's subsets of a step's bodies (see auto_subset.hpp).
#include "auto_subset.hpp"

namespace rube {

void StepSubset::gather(const StepContext& world, std::span<const std::uint8_t> chosen) {
    const std::size_t circleCount = world.circles.size();
    circles_.clear();
    bodies_.clear();
    pivots_.clear();
    circleMap_.clear();
    bodyMap_.clear();
    circleInverse_.assign(circleCount, -1);
    bodyInverse_.assign(world.bodies.size(), -1);
    // In world order, so a method that breaks ties by index breaks them as it would on the world.
    for (std::size_t i = 0; i < circleCount; ++i) {
        if (world.circles[i].motion == Motion::dynamic && !chosen[i]) continue;
        circleInverse_[i] = static_cast<int>(circles_.size());
        circleMap_.push_back(static_cast<int>(i));
        circles_.push_back(world.circles[i]);
    }
    for (std::size_t b = 0; b < world.bodies.size(); ++b) {
        if (!chosen[circleCount + b]) continue;
        bodyInverse_[b] = static_cast<int>(bodies_.size());
        bodyMap_.push_back(static_cast<int>(b));
        bodies_.push_back(world.bodies[b]);
    }
    for (const Pivot& p : world.pivots) {
        if (p.body < 0 || static_cast<std::size_t>(p.body) >= bodyInverse_.size() ||
            bodyInverse_[static_cast<std::size_t>(p.body)] < 0)
            continue;
        Pivot copy = p;
        copy.body = bodyInverse_[static_cast<std::size_t>(p.body)];
        pivots_.push_back(copy);
    }
    // A joint whose bodies are all copied, its ends given the copies' slots (a gear's coupled joints
    // are not followed: gears are the solver's).
    joints_.clear();
    const auto copied = [](const std::vector<int>& inverse, int slot) {
        return slot < 0 ||
               (static_cast<std::size_t>(slot) < inverse.size() && inverse[static_cast<std::size_t>(slot)] >= 0);
    };
    for (const Joint& j : world.joints) {
        if (j.def.kind == JointKind::gear) continue;
        if (!copied(circleInverse_, j.circleA) || !copied(circleInverse_, j.circleB) ||
            !copied(bodyInverse_, j.bodyA) || !copied(bodyInverse_, j.bodyB))
            continue;
        Joint copy = j;
        const auto to = [](const std::vector<int>& inverse, int slot) {
            return slot < 0 ? -1 : inverse[static_cast<std::size_t>(slot)];
        };
        copy.circleA = to(circleInverse_, j.circleA);
        copy.circleB = to(circleInverse_, j.circleB);
        copy.bodyA = to(bodyInverse_, j.bodyA);
        copy.bodyB = to(bodyInverse_, j.bodyB);
        joints_.push_back(copy);
    }
    // An asleep circle names its island by one member's index: the copy's index of that member
    // (islands keep a sleeping island whole, so the member is copied too).
    for (std::size_t k = 0; k < circles_.size(); ++k) {
        SleepState& sleep = circles_[k].sleep;
        if (!sleep.asleep) continue;
        const bool known = sleep.island >= 0 && static_cast<std::size_t>(sleep.island) < circleCount &&
                           circleInverse_[static_cast<std::size_t>(sleep.island)] >= 0;
        sleep.island = known ? circleInverse_[static_cast<std::size_t>(sleep.island)] : static_cast<int>(k);
    }
}

StepContext StepSubset::context(const StepContext& world, const WorldDef& def) {
    StepContext sub{def,           circles_,    world.segments, bodies_,    world.time, world.restingSpeed,
                    world.impacts, world.stats, pivots_,        world.ropes};
    sub.sleep = world.sleep;
    sub.workers = world.workers;
    sub.joints = joints_;
    sub.magnets = world.magnets;
    return sub;
}

void StepSubset::scatter(StepContext& world, bool shared, std::size_t firstImpact) {
    for (std::size_t k = 0; k < circles_.size(); ++k) {
        Circle& c = circles_[k];
        if (c.sleep.asleep && c.sleep.island >= 0)
            c.sleep.island = circleMap_[static_cast<std::size_t>(c.sleep.island)];
        if (c.motion == Motion::dynamic || shared) world.circles[static_cast<std::size_t>(circleMap_[k])] = c;
    }
    for (std::size_t k = 0; k < bodies_.size(); ++k) world.bodies[static_cast<std::size_t>(bodyMap_[k])] = bodies_[k];
    remapImpacts(world, firstImpact);
}

void StepSubset::remapImpacts(StepContext& world, std::size_t firstImpact) const {
    for (std::size_t n = firstImpact; n < world.impacts.size(); ++n) {
        Impact& impact = world.impacts[n];
        if (impact.circle >= 0) impact.circle = circleMap_[static_cast<std::size_t>(impact.circle)];
        if (impact.body >= 0) impact.body = bodyMap_[static_cast<std::size_t>(impact.body)];
        if (impact.other < 0) continue;
        if (impact.otherKind == Other::circle) impact.other = circleMap_[static_cast<std::size_t>(impact.other)];
        else if (impact.otherKind == Other::body) impact.other = bodyMap_[static_cast<std::size_t>(impact.other)];
    }
}

void StepSubset::carryAngles(StepContext& world, bool shared, double dt) const {
    for (std::size_t k = 0; k < circles_.size(); ++k) {
        Circle& c = world.circles[static_cast<std::size_t>(circleMap_[k])];
        if (c.motion != Motion::dynamic && !shared) continue;
        if (c.angularVelocity != 0.0) c.angle += c.angularVelocity * dt;
    }
}

} // namespace rube
