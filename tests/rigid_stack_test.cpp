// A stack of rigid boxes under the solver, warm started from step to step (rigid_warm_start): five
// 0.4 m boxes stacked on the floor sink 1.8 mm at the top with the stacking contacts' 70 Hz (2.8 mm
// when this test was written) and stay upright over 10 s; rebuilding every impulse from zero each
// step, they sank 6.0 mm, drifted 9 mm and tilted 5 mrad.
#include "rube/physics/world.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace rube;

TEST_CASE("a stack of five boxes rests: the top sinks less than 3.5 mm and drifts less than 3 mm over 10 s",
          "[rigid][stack]") {
    WorldDef def;
    def.method = Method::solver;
    World world(def);
    SegmentDef floor;
    floor.a = {-20.0, 0.0};
    floor.b = {20.0, 0.0};
    floor.material = {0.0, 0.6};
    world.addSegment(floor);
    constexpr int kBoxes = 5;
    const double height = 0.4;
    for (int i = 0; i < kBoxes; ++i) {
        RigidBodyDef d;
        d.position = {0.0, 0.5 * height + height * i}; // exactly touching
        d.halfExtents = {0.4, 0.5 * height};
        d.mass = 1.0;
        d.material = {0.0, 0.6};
        world.addBody(d);
    }
    const double topHeight = 0.5 * height + height * (kBoxes - 1);
    double deepest = 0.0, drift = 0.0, tilt = 0.0, lateSinking = 0.0;
    for (int step = 0; step < 600; ++step) {
        world.step();
        const RigidBody& top = world.bodies()[kBoxes - 1];
        deepest = std::max(deepest, topHeight - top.position.y);
        if (step >= 540) lateSinking = std::max(lateSinking, topHeight - top.position.y); // the last second
        for (const RigidBody& b : world.bodies()) {
            drift = std::max(drift, std::abs(b.position.x));
            tilt = std::max(tilt, std::abs(b.angle));
        }
    }
    const double finalSinking = topHeight - world.bodies()[kBoxes - 1].position.y;
    std::printf("5-box stack over 10 s: top sinks at most %.4g mm (%.4g mm in the last second, %.4g mm at the end); "
                "drift %.3g mm, tilt %.3g rad; %lld impacts\n",
                1e3 * deepest, 1e3 * lateSinking, 1e3 * finalSinking, 1e3 * drift, tilt,
                static_cast<long long>(world.stats().impacts));
    CHECK(deepest < 3.5e-3);
    CHECK(drift < 3e-3);
    CHECK(tilt < 1e-3);
    CHECK(world.stats().impacts == 0); // stacked touching: resting contact from the first step
}
