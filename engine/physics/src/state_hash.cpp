// The determinism hash: FNV-1a over the exact bits of every body's state.
#include "rube/physics/world.hpp"

#include <bit>
#include <cstdint>

namespace rube {

namespace {

constexpr std::uint64_t kFnvOffset = 14695981039346656037ull;
constexpr std::uint64_t kFnvPrime = 1099511628211ull;

void mix(std::uint64_t& h, double value) {
    // +0.0 and -0.0 hash differently on purpose: bit-identical means bit-identical.
    std::uint64_t bits = std::bit_cast<std::uint64_t>(value);
    for (int i = 0; i < 8; ++i) {
        h ^= bits & 0xffu;
        h *= kFnvPrime;
        bits >>= 8;
    }
}

// A moving body's state in a fixed order: position, velocity, angle, angular velocity.
void mixMotion(std::uint64_t& h, Vec2 position, Vec2 velocity, double angle, double angularVelocity) {
    mix(h, position.x);
    mix(h, position.y);
    mix(h, velocity.x);
    mix(h, velocity.y);
    mix(h, angle);
    mix(h, angularVelocity);
}

} // namespace

std::uint64_t stateHash(const World& world) {
    std::uint64_t h = kFnvOffset;
    for (const Circle& c : world.circles()) {
        mixMotion(h, c.position, c.velocity, c.angle, c.angularVelocity);
        // Sleep decides how the circle moves next: two worlds alike but for it would part ways.
        mix(h, c.sleep.asleep ? 1.0 : 0.0);
        mix(h, c.sleep.slowFor);
    }
    for (const Segment& s : world.segments()) {
        mix(h, s.a.x);
        mix(h, s.a.y);
        mix(h, s.b.x);
        mix(h, s.b.y);
    }
    for (const RigidBody& b : world.bodies()) {
        mixMotion(h, b.position, b.velocity, b.angle, b.angularVelocity);
        // As the circles' sleep; a body never counted slow (every world before rigid bodies could
        // sleep, and every method but the solver) hashes as it did then.
        if (b.sleep.asleep || b.sleep.slowFor != 0.0) {
            mix(h, b.sleep.asleep ? 1.0 : 0.0);
            mix(h, b.sleep.slowFor);
        }
    }
    return h;
}

} // namespace rube
