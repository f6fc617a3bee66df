// Ropes in the solver's sleeping islands (solver_sleep.hpp). The world enforces ropes after the
// method (rope_constraint.cpp), so the sleep pass, which runs inside the solver's step, sees a roped
// circle before its rope has acted: a weight hanging still has just been given g dt downwards and
// moved g dt^2 past the rope's length. The pass therefore judges a circle's speed as the rope will
// leave it, and lets a taut rope hold its circle as a frictionless contact would, along the rope.
#include "solver_sleep.hpp"

namespace rube {

namespace {

/// A rope counts as taut for sleeping when its ends are at least this share of its length less than
/// L apart. The rope pass leaves them L apart to rounding; the solver's step may then have moved them
/// either way by |v| dt + g dt^2.
constexpr double kTautShare = 1e-6;
/// Passes over the ropes after the first when a rope joins two circles, as rope_constraint.cpp makes.
constexpr int kChainPasses = 8;

double inverseMassOf(const Circle& c) { return c.motion == Motion::dynamic ? c.inverseMass : 0.0; }

bool acts(const Rope& rope, std::size_t circleCount) {
    return !rope.cut && rope.circle >= 0 && static_cast<std::size_t>(rope.circle) < circleCount &&
           (rope.other < 0 || static_cast<std::size_t>(rope.other) < circleCount);
}

/// The unit vector from the rope's far end to its circle when the rope is taut, else zero.
Vec2 tautDirection(std::span<const Circle> circles, const Rope& rope) {
    const Vec2 far = rope.other >= 0 ? circles[static_cast<std::size_t>(rope.other)].position : rope.anchor;
    const Vec2 d = circles[static_cast<std::size_t>(rope.circle)].position - far;
    const double distance = d.length();
    if (!(distance > 0.0) || distance < rope.length * (1.0 - kTautShare)) return {};
    return d / distance;
}

/// Neither end can move this step (asleep, or not dynamic): the rope changes no velocity.
bool asleepOrFixed(std::span<const Circle> circles, const Rope& rope) {
    const auto still = [](const Circle& c) { return c.sleep.asleep || c.motion != Motion::dynamic; };
    return still(circles[static_cast<std::size_t>(rope.circle)]) &&
           (rope.other < 0 || still(circles[static_cast<std::size_t>(rope.other)]));
}

bool awakeOrMoving(const Circle& c) {
    return c.motion == Motion::dynamic ? !c.sleep.asleep && c.inverseMass > 0.0
                                       : c.motion == Motion::kinematic && c.velocity != Vec2{};
}

} // namespace

std::span<const Vec2> SleepIslands::ropeVelocities(std::span<const Circle> circles, std::span<const Rope> ropes) {
    ropeVelocity_.resize(circles.size());
    for (std::size_t i = 0; i < circles.size(); ++i) ropeVelocity_[i] = circles[i].velocity;
    // What pullTaut (rope_constraint.cpp) will take out: the relative velocity that stretches a taut
    // rope, shared by inverse mass (the turn a free swing's velocity gets keeps its length); with a
    // rope between two circles, over as many passes as the rope pass makes (a chain's ropes share
    // their stretch out one after another).
    bool chained = false;
    for (const Rope& rope : ropes) chained = chained || (acts(rope, circles.size()) && rope.other >= 0);
    for (int pass = 0; pass <= (chained ? kChainPasses : 0); ++pass)
        for (const Rope& rope : ropes) {
            if (!acts(rope, circles.size()) || asleepOrFixed(circles, rope)) continue;
            const Vec2 n = tautDirection(circles, rope);
            if (n == Vec2{}) continue;
            const auto a = static_cast<std::size_t>(rope.circle);
            const double wa = inverseMassOf(circles[a]);
            const double wb = rope.other >= 0 ? inverseMassOf(circles[static_cast<std::size_t>(rope.other)]) : 0.0;
            if (!(wa + wb > 0.0)) continue;
            const Vec2 vb = rope.other >= 0 ? ropeVelocity_[static_cast<std::size_t>(rope.other)] : Vec2{};
            const double stretching = (ropeVelocity_[a] - vb).dot(n);
            if (!(stretching > 0.0)) continue;
            ropeVelocity_[a] -= n * (stretching * wa / (wa + wb));
            if (rope.other >= 0)
                ropeVelocity_[static_cast<std::size_t>(rope.other)] += n * (stretching * wb / (wa + wb));
        }
    return ropeVelocity_;
}

void SleepIslands::offerRopeRays(std::span<const Circle> circles, std::span<const Rope> ropes, Vec2 up) {
    // A taut rope pulls its circle towards the far end and the far circle towards it: one ray each,
    // no cone (a rope has no friction), counted as a holding contact.
    const auto offer = [&](int i, Vec2 ray) {
        const auto n = static_cast<std::size_t>(i);
        if (state_[n] != ready) return;
        ++holding_[n];
        normalRays_[n].offer(up, ray);
        coneRays_[n].offer(up, ray);
    };
    for (const Rope& rope : ropes) {
        if (!acts(rope, circles.size())) continue;
        const Vec2 n = tautDirection(circles, rope);
        if (n == Vec2{}) continue;
        offer(rope.circle, -n);
        if (rope.other >= 0) offer(rope.other, n);
    }
}

void SleepIslands::joinRopes(std::span<const Circle> circles, std::span<const Rope> ropes) {
    // A rope's circles share an island, slack or taut (the rope may pull at any step); a ready end
    // roped to an awake circle, or to a moving kinematic one, keeps its island awake.
    const auto block = [&](int i) { blocked_[static_cast<std::size_t>(i)] = 1; };
    for (const Rope& rope : ropes) {
        if (!acts(rope, circles.size()) || rope.other < 0) continue;
        const int a = rope.circle, b = rope.other;
        const std::uint8_t sa = state_[static_cast<std::size_t>(a)], sb = state_[static_cast<std::size_t>(b)];
        const bool aCarries = sa == other && awakeOrMoving(circles[static_cast<std::size_t>(a)]);
        const bool bCarries = sb == other && awakeOrMoving(circles[static_cast<std::size_t>(b)]);
        if (sa == ready && sb == ready) join(a, b);
        else if (sa == ready && (sb == awake || bCarries)) block(a);
        else if (sb == ready && (sa == awake || aCarries)) block(b);
    }
}

void SleepIslands::ropeReached(std::span<const Circle> circles, std::span<const Rope> ropes,
                               std::vector<int>& reached) {
    reached.clear();
    for (const Rope& rope : ropes) {
        if (!acts(rope, circles.size()) || rope.other < 0) continue;
        const Circle& a = circles[static_cast<std::size_t>(rope.circle)];
        const Circle& b = circles[static_cast<std::size_t>(rope.other)];
        if (a.sleep.asleep && awakeOrMoving(b)) reached.push_back(rope.circle);
        if (b.sleep.asleep && awakeOrMoving(a)) reached.push_back(rope.other);
    }
}

} // namespace rube
