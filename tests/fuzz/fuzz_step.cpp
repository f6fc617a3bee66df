// libFuzzer target: a step of a random scene. The bytes choose a method (all five) and up to eight
// balls (position, radius, mass, velocity up to 200 m/s, bounciness, friction, spin), up to three
// segments inside a closed box, up to three rigid bodies (blocks; turning boxes, capsules and pivots
// under solver and auto), ropes, water, a fan, a magnet, a thruster and a kinematic circle; the world then steps 60
// times, a circle or segment removed and a rigid body disabled at step 20 (enabled again at 40) when the bytes say so.
// It must never produce a NaN or an infinity, and never do more work in a step than the event cap allows.
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

constexpr rube::Method kMethods[] = {rube::Method::discrete, rube::Method::turnBased, rube::Method::exact,
                                     rube::Method::solver, rube::Method::automatic};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rube;
    Bytes bytes(data, size);
    WorldDef def;
    def.method = kMethods[bytes.byte() % 5];
    def.gravity = {bytes.in(-20.0, 20.0), bytes.in(-20.0, 20.0)};
    def.maxEventsPerStep = 256;
    def.bounds = {{-10.0, -10.0}, {10.0, 10.0}};
    World world(def);
    const Vec2 corners[] = {{-5, -5}, {5, -5}, {5, 5}, {-5, 5}};
    for (int i = 0; i < 4; ++i)
        world.addSegment(
            {corners[i], corners[(i + 1) % 4], bytes.in(0.0, 0.2), {bytes.in(0.0, 1.0), bytes.in(0.0, 1.0)}, -1});
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
    // Rigid bodies (turning ones and pivots only where the method models them), ropes, water, fields
    // and a kinematic circle (issue 27).
    const bool turning = movesTurningBodies(def.method);
    const int bodies = bytes.byte() % 4;
    for (int i = 0; i < bodies && !bytes.empty(); ++i) {
        RigidBodyDef body;
        body.shape = turning && bytes.byte() % 2 ? BodyShape::capsule : BodyShape::box;
        body.fixedRotation = body.shape == BodyShape::box && (!turning || bytes.byte() % 2);
        body.position = {bytes.in(-4.0, 4.0), bytes.in(-4.0, 4.0)};
        body.halfExtents = {bytes.in(0.02, 0.8), bytes.in(0.02, 0.5)};
        body.mass = bytes.in(1e-3, 1e3);
        body.angle = body.fixedRotation ? 0.0 : bytes.in(-3.2, 3.2);
        body.velocity = {bytes.in(-50.0, 50.0), bytes.in(-50.0, 50.0)};
        body.angularVelocity = body.fixedRotation ? 0.0 : bytes.in(-50.0, 50.0);
        body.material = {bytes.in(0.0, 1.0), bytes.in(0.0, 1.0)};
        const BodyId index = world.addBody(body);
        if (turning && bytes.byte() % 3 == 0)
            world.addPivot(
                {index, {bytes.in(-0.5, 0.5), 0.0}, body.position + Vec2{bytes.in(-0.5, 0.5), bytes.in(-0.5, 0.5)}});
    }
    const int circles = static_cast<int>(world.circles().size());
    for (int i = 0, ropes = bytes.byte() % 3; i < ropes && circles > 0; ++i) {
        RopeDef rope;
        rope.circle = world.circleId(bytes.byte() % circles);
        rope.anchor = {bytes.in(-4.5, 4.5), bytes.in(-4.5, 4.5)};
        rope.length = bytes.in(0.1, 5.0);
        world.addRope(rope);
    }
    const std::uint8_t fields = bytes.byte();
    if (fields & 1)
        world.fields().waters.push_back(
            {{-5.0, -5.0}, {5.0, bytes.in(-5.0, 5.0)}, bytes.in(1.0, 5000.0), bytes.in(0.0, 5000.0)});
    if (fields & 2)
        world.fields().winds.push_back({{bytes.in(-5.0, 5.0), -5.0},
                                        {0.0, 1.0},
                                        10.0,
                                        bytes.in(0.5, 5.0),
                                        bytes.in(0.0, 50.0),
                                        bytes.in(0.0, 50.0),
                                        true});
    if (fields & 4)
        world.fields().magnets.push_back(
            {{bytes.in(-4.0, 4.0), bytes.in(-4.0, 4.0)}, bytes.in(0.0, 500.0), 0.1, 1e9, true});
    if ((fields & 8) && circles > 0)
        world.fields().thrusters.push_back(
            {world.circleId(bytes.byte() % circles), {bytes.in(-500.0, 500.0), bytes.in(-500.0, 500.0)}, 0.0, 0.5});
    if (fields & 16) {
        KinematicPath path;
        path.loop = true;
        path.keys = {{0.0, {}, 0.0}, {bytes.in(0.1, 1.0), {bytes.in(-2.0, 2.0), bytes.in(-2.0, 2.0)}, 0.0}};
        CircleDef mover;
        mover.position = {bytes.in(-3.0, 3.0), bytes.in(-3.0, 3.0)};
        mover.radius = bytes.in(0.05, 0.5);
        mover.motion = Motion::kinematic;
        mover.path = world.addPath(std::move(path));
        world.addCircle(mover);
    }
    // Edits between steps: remove a circle (and its ropes), a segment; disable a rigid body, enable it again.
    const std::uint8_t edits = bytes.byte(), which = bytes.byte();
    BodyId disabled;
    for (int step = 0; step < 60; ++step) {
        if (step == 20) {
            if ((edits & 1) && !world.circles().empty())
                world.remove(world.circleId(which % static_cast<int>(world.circles().size())));
            if ((edits & 2) && !world.segments().empty())
                world.remove(world.segmentId(which % static_cast<int>(world.segments().size())));
            if ((edits & 4) && !world.bodies().empty()) {
                disabled = world.bodyId(which % static_cast<int>(world.bodies().size()));
                world.setEnabled(disabled, false);
            }
        }
        if (step == 40 && !disabled.isNull()) world.setEnabled(disabled, true);
        world.step();
        if (world.stats().nonFinite) __builtin_trap();
        if (world.stats().maxEventsInStep > def.maxEventsPerStep) __builtin_trap();
    }
    return 0;
}
