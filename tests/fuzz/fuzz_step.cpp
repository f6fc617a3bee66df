// libFuzzer target: a step of a random scene. The bytes choose a method and up to eight balls
// (position, radius, mass, velocity up to 200 m/s, bounciness, friction, spin) and up to three
// segments inside a closed box; the world then steps 60 times. It must never produce a NaN or an
// infinity, and never do more work in a step than the event cap allows.
#include "rube/physics/world.hpp"

#include <cstddef>
#include <cstdint>

namespace {

class Bytes {
public:
    Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
    /// A byte mapped onto [lo, hi].
    double in(double lo, double hi) { return lo + (hi - lo) * byte() / 255.0; }
    bool empty() const { return pos_ >= size_; }

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t pos_ = 0;
};

constexpr rube::Method kMethods[] = {rube::Method::discrete, rube::Method::turnBased, rube::Method::exact, rube::Method::solver, rube::Method::automatic};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rube;
    Bytes bytes(data, size);
    WorldDef def;
    def.method = kMethods[bytes.byte() % 4];
    def.gravity = {bytes.in(-20.0, 20.0), bytes.in(-20.0, 20.0)};
    def.maxEventsPerStep = 256;
    def.bounds = {{-10.0, -10.0}, {10.0, 10.0}};
    World world(def);
    const Vec2 corners[] = {{-5, -5}, {5, -5}, {5, 5}, {-5, 5}};
    for (int i = 0; i < 4; ++i) world.addSegment({corners[i], corners[(i + 1) % 4], bytes.in(0.0, 0.2), {bytes.in(0.0, 1.0), bytes.in(0.0, 1.0)}, -1});
    const int segments = bytes.byte() % 4;
    for (int i = 0; i < segments; ++i) {
        const Vec2 a{bytes.in(-4.5, 4.5), bytes.in(-4.5, 4.5)};
        Vec2 b{bytes.in(-4.5, 4.5), bytes.in(-4.5, 4.5)};
        if (a == b) b.x += 0.5;
        world.addSegment({a, b, bytes.in(0.0, 0.3), {bytes.in(0.0, 1.0), bytes.in(0.0, 1.0)}, -1});
    }
    const int balls = 1 + bytes.byte() % 8;
    for (int i = 0; i < balls && !bytes.empty(); ++i) {
        CircleDef ball;
        ball.position = {bytes.in(-4.5, 4.5), bytes.in(-4.5, 4.5)};
        ball.radius = bytes.in(0.02, 1.0);
        ball.mass = bytes.in(0.01, 100.0);
        ball.velocity = {bytes.in(-200.0, 200.0), bytes.in(-200.0, 200.0)};
        ball.angularVelocity = bytes.in(-50.0, 50.0);
        ball.material = {bytes.in(0.0, 1.0), bytes.in(0.0, 1.0)};
        world.addCircle(ball);
    }
    for (int step = 0; step < 60; ++step) {
        world.step();
        if (world.stats().nonFinite) __builtin_trap();
        if (world.stats().maxEventsInStep > def.maxEventsPerStep) __builtin_trap();
    }
    return 0;
}
