// Worker threads for the rigid solver (issue 26, WorldDef::workers): the same scene stepped with 1,
// 2, 3 and 4 workers ends in the same state bit for bit (stateHash), over scenes whose colours are
// large enough to be shared (a pyramid, a domino run, a bin of mixed bodies, chains on joints); a
// world with workers stops and joins its threads when destroyed mid-run; bad counts are refused.
#include "rube/physics/joint.hpp"
#include "rube/physics/world.hpp"
#include "scene_builders.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>

using namespace rube;
using rube::test::line;

namespace {

WorldDef solverDef(int workers) {
    WorldDef def;
    def.method = Method::solver;
    def.gravity = {0.0, -10.0};
    def.sleepSpeed = 0.0; // awake throughout: every step solves every contact
    def.workers = workers;
    return def;
}

RigidBodyDef box(Vec2 position, Vec2 halfExtents, double angle = 0.0) {
    RigidBodyDef d;
    d.position = position;
    d.halfExtents = halfExtents;
    d.angle = angle;
    d.material = {0.0, 0.6};
    return d;
}

void addFloor(World& world, double halfWidth) {
    SegmentDef floor = line({-halfWidth, 0.0}, {halfWidth, 0.0});
    floor.material = {0.0, 1.0};
    world.addSegment(floor);
}

void pyramid(World& world, int base) {
    addFloor(world, base + 10.0);
    for (int row = 0; row < base; ++row)
        for (int k = 0; k < base - row; ++k)
            world.addBody(box({(k - 0.5 * (base - row - 1)) * 1.0, 0.5 + row * 1.0}, {0.5, 0.5}));
}

/// Dominoes 0.1 x 1 m, 0.6 m apart, the first pushed over: the run falls for the whole test.
void dominoes(World& world, int count) {
    addFloor(world, 0.6 * count + 10.0);
    for (int k = 0; k < count; ++k) {
        RigidBodyDef d = box({0.6 * k, 0.5}, {0.05, 0.5});
        if (k == 0) d.angularVelocity = -3.0;
        world.addBody(d);
    }
}

/// Boxes, capsules and balls of several sizes dropped in rows into a bin, some spinning.
void mixedBin(World& world, int count) {
    const double half = 8.0;
    addFloor(world, half);
    world.addSegment(line({-half, 0.0}, {-half, 60.0}));
    world.addSegment(line({half, 0.0}, {half, 60.0}));
    for (int k = 0; k < count; ++k) {
        const int column = k % 20, row = k / 20;
        const Vec2 at{-7.2 + 0.76 * column + 0.05 * (row % 3), 0.6 + 0.8 * row};
        const double size = 0.18 + 0.03 * (k % 5);
        if (k % 3 == 2) {
            CircleDef c = rube::test::ball(at, {0.0, 0.0}, size);
            c.material = {0.2, 0.5};
            world.addCircle(c);
            continue;
        }
        RigidBodyDef d = box(at, {size, 0.7 * size}, 0.3 * (k % 7));
        if (k % 3 == 1) d.shape = BodyShape::capsule;
        d.angularVelocity = (k % 4) - 1.5;
        d.material = {0.3, 0.5};
        world.addBody(d);
    }
}

/// Chains of 12 boxes hinged to each other and the first to the world, swinging onto a pyramid.
void chainsOverPyramid(World& world) {
    pyramid(world, 24);
    for (int chain = 0; chain < 4; ++chain) {
        const Vec2 top{-9.0 + 6.0 * chain, 30.0};
        JointEnd previous{};
        Vec2 anchor = top;
        for (int link = 0; link < 12; ++link) {
            const Vec2 centre = top + Vec2{0.5 + 1.0 * link, 0.0};
            const JointEnd end{{}, world.addBody(box(centre, {0.5, 0.1}))};
            JointDef d;
            d.kind = JointKind::revolute;
            d.a = previous;
            d.b = end;
            d.localAnchorA = world.localPoint(previous, anchor);
            d.localAnchorB = world.localPoint(end, anchor);
            d.referenceAngle = world.angleOf(end) - world.angleOf(previous);
            world.addJoint(d);
            previous = end;
            anchor = centre + Vec2{0.5, 0.0};
        }
    }
}

std::uint64_t hashAfter(const std::function<void(World&)>& build, int workers, int steps) {
    World world(solverDef(workers));
    build(world);
    for (int s = 0; s < steps; ++s) world.step();
    REQUIRE(!world.stats().nonFinite);
    return stateHash(world);
}

/// The threads this process runs now (Linux: /proc/self/status), or -1 where that cannot be read.
int threadCount() {
    std::ifstream status("/proc/self/status");
    for (std::string key; status >> key;) {
        if (key == "Threads:") {
            int n = -1;
            status >> n;
            return n;
        }
        status.ignore(1 << 16, '\n');
    }
    return -1;
}

} // namespace

/// The hash after `steps` steps is the same for 2, 3 and 4 workers as for one.
void checkSameForAnyWorkers(const std::function<void(World&)>& build, int steps) {
    const std::uint64_t serial = hashAfter(build, 1, steps);
    for (int workers = 2; workers <= 4; ++workers) {
        INFO(workers << " workers");
        CHECK(hashAfter(build, workers, steps) == serial);
    }
}

TEST_CASE("rigid workers: a pyramid ends the same bit for bit with any number of workers", "[rigid][workers]") {
    checkSameForAnyWorkers([](World& w) { pyramid(w, 30); }, 40);
}

TEST_CASE("rigid workers: a domino run ends the same bit for bit with any number of workers", "[rigid][workers]") {
    checkSameForAnyWorkers([](World& w) { dominoes(w, 600); }, 90);
}

TEST_CASE("rigid workers: a bin of mixed bodies ends the same bit for bit with any number of workers",
          "[rigid][workers]") {
    checkSameForAnyWorkers([](World& w) { mixedBin(w, 500); }, 120);
}

TEST_CASE("rigid workers: chains on joints end the same bit for bit with any number of workers", "[rigid][workers]") {
    checkSameForAnyWorkers(chainsOverPyramid, 90);
}

TEST_CASE("rigid workers: the scenes move, so equal hashes compare real motion", "[rigid][workers]") {
    // A hash compared after nothing moved would prove nothing: each scene's state changes over the run.
    World dominoWorld(solverDef(2));
    dominoes(dominoWorld, 600);
    const std::uint64_t before = stateHash(dominoWorld);
    for (int s = 0; s < 90; ++s) dominoWorld.step();
    CHECK(stateHash(dominoWorld) != before);
    const BodyId sixth = dominoWorld.bodyId(5);
    CHECK(std::abs(dominoWorld.body(sixth).angle) > 0.1); // the sixth domino has been knocked over
}

TEST_CASE("rigid workers: a world destroyed or moved mid-run joins its threads", "[rigid][workers]") {
    const int before = threadCount();
    {
        World world(solverDef(4));
        pyramid(world, 20);
        for (int s = 0; s < 5; ++s) world.step();
        if (before > 0) CHECK(threadCount() == before + 3);
        World moved(std::move(world)); // the threads go with it, and keep working
        for (int s = 0; s < 5; ++s) moved.step();
        if (before > 0) CHECK(threadCount() == before + 3);
    }
    if (before > 0) CHECK(threadCount() == before);
    {
        World one(solverDef(1)); // one worker starts no thread
        if (before > 0) CHECK(threadCount() == before);
    }
}

TEST_CASE("rigid workers: counts outside 1 to 64 are refused", "[rigid][workers]") {
    for (const int workers : {0, -1, kMaxWorkers + 1, 1000}) {
        INFO(workers);
        CHECK_THROWS_AS(World(solverDef(workers)), std::invalid_argument);
    }
    CHECK_NOTHROW(World(solverDef(kMaxWorkers)));
}
