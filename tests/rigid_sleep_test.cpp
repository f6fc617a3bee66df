// Sleeping for rigid bodies (issue 26), under the solver and under auto (whose solver islands sleep
// the same way): a settled stack of boxes sleeps; a box its contacts cannot
// hold (a slope steeper than its friction angle), or an island a running motor drives, never does; a
// ball, a setter or a motor wakes exactly the island it reaches; and sleeping moves nothing a
// settled scene shows.
#include "rube/physics/world.hpp"
#include "scene_builders.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

using namespace rube;
using rube::test::ball;
using rube::test::line;

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

/// The solver, or auto, which gives the solver every island with a turning body, pivot or joint
/// (method_auto.cpp) and lets it sleep there: every test runs under both.
WorldDef sleepDef(Method method, double sleepSpeed = WorldDef{}.sleepSpeed) {
    WorldDef def;
    def.method = method;
    def.gravity = {0.0, -10.0};
    def.sleepSpeed = sleepSpeed;
    return def;
}

RigidBodyDef box(Vec2 position, Vec2 halfExtents, double angle = 0.0, double friction = 0.6) {
    RigidBodyDef d;
    d.position = position;
    d.halfExtents = halfExtents;
    d.angle = angle;
    d.material = {0.0, friction};
    return d;
}

void addFloor(World& world, double halfWidth = 40.0) {
    SegmentDef floor = line({-halfWidth, 0.0}, {halfWidth, 0.0});
    floor.material = {0.0, 1.0};
    world.addSegment(floor);
}

/// A pyramid of unit boxes (half size 0.5 m) with `base` boxes in its lowest row, centred on x.
std::vector<BodyId> addPyramid(World& world, int base, double x) {
    std::vector<BodyId> ids;
    for (int row = 0; row < base; ++row)
        for (int k = 0; k < base - row; ++k)
            ids.push_back(world.addBody(box({x + (k - 0.5 * (base - row - 1)) * 1.0, 0.5 + row * 1.0}, {0.5, 0.5})));
    return ids;
}

bool allAsleep(const World& world, const std::vector<BodyId>& ids) {
    for (const BodyId id : ids)
        if (!world.body(id).sleep.asleep) return false;
    return true;
}

bool noneAsleep(const World& world, const std::vector<BodyId>& ids) {
    for (const BodyId id : ids)
        if (world.body(id).sleep.asleep) return false;
    return true;
}

/// Steps until every body of `ids` is asleep; the step count, or -1 after `most` steps.
int stepsToSleep(World& world, const std::vector<BodyId>& ids, int most) {
    for (int s = 1; s <= most; ++s) {
        world.step();
        if (allAsleep(world, ids)) return s;
    }
    return -1;
}

} // namespace

TEST_CASE("rigid sleep: a settled pyramid falls asleep within a bound, and then costs no contacts", "[sleep][rigid]") {
    const Method method = GENERATE(Method::solver, Method::automatic);
    INFO("method " << methodName(method));
    // Stacked exactly, the boxes start at rest and settle by millimetres: each must stay under
    // sleepSpeed for timeToSleep, so the whole island sleeps after timeToSleep plus the settling,
    // which the bound allows a second for (Box2D's pyramids sleep after about as long).
    const int base = GENERATE(1, 3, 6, 10);
    World world(sleepDef(method));
    addFloor(world);
    const std::vector<BodyId> ids = addPyramid(world, base, 0.0);
    const double dt = world.def().timeStep;
    const int bound = static_cast<int>(std::ceil((world.def().timeToSleep + 1.0) / dt));
    const int steps = stepsToSleep(world, ids, bound);
    INFO("base " << base << ": asleep after " << steps << " steps (bound " << bound << ")");
    REQUIRE(steps > 0);
    // Never before timeToSleep: every body must have been slow that long.
    CHECK(steps >= static_cast<int>(std::floor(world.def().timeToSleep / dt)));
    // Asleep, nothing is solved: no resting contact is counted and nothing moves.
    const std::int64_t resting = world.stats().restingContacts;
    std::vector<Vec2> before;
    for (const BodyId id : ids) before.push_back(world.body(id).position);
    for (int s = 0; s < 60; ++s) world.step();
    CHECK(world.stats().restingContacts == resting);
    for (std::size_t k = 0; k < ids.size(); ++k) CHECK(world.body(ids[k]).position == before[k]);
}

TEST_CASE("rigid sleep: a box on a slope steeper than its friction angle never sleeps, on a shallower one it does",
          "[sleep][rigid]") {
    const Method method = GENERATE(Method::solver, Method::automatic);
    INFO("method " << methodName(method));
    // On a slope of angle theta a box slides with a = g (sin theta - mu cos theta) once theta exceeds
    // atan(mu). Just past it, a is tiny: at 0.05 degree over, a = g (cos t + mu sin t) 0.05 degree,
    // about 0.01 m/s^2, so it stays under sleepSpeed (0.01 m/s) for the whole of timeToSleep (0.5 s):
    // only the hold rule (gravity outside the contacts' friction cones) keeps it awake.
    const double mu = GENERATE(0.3, 0.6);
    const double over = GENERATE(0.05, 0.2, 3.0); // degrees past the friction angle
    const double sign = GENERATE(1.0, -1.0);      // steeper, or shallower by as much
    const double theta = std::atan(mu) + sign * over * kDegree;
    World world(sleepDef(method));
    // A long slope through the origin, falling to the left; the floor's friction is 1, the box's mu.
    const Vec2 along{std::cos(theta), std::sin(theta)};
    SegmentDef slope = line(along * -60.0, along * 20.0);
    slope.material = {0.0, 1.0};
    world.addSegment(slope);
    const Vec2 normal{-along.y, along.x};
    const Vec2 start = normal * 0.25;
    const BodyId b = world.addBody(box(start, {0.5, 0.25}, theta, mu));
    const double seconds = 4.0;
    bool everAsleep = false;
    for (int s = 0; s < static_cast<int>(seconds / world.def().timeStep); ++s) {
        world.step();
        everAsleep = everAsleep || world.body(b).sleep.asleep;
    }
    const double slid = -(world.body(b).position - start).dot(along);
    const double a = 10.0 * (std::sin(theta) - mu * std::cos(theta));
    INFO("mu " << mu << ", theta " << theta / kDegree << " deg: a " << a << " m/s^2, slid " << slid << " m (a t^2/2 "
               << 0.5 * a * seconds * seconds << ")");
    if (sign > 0.0) {
        CHECK_FALSE(everAsleep);
        // It slides as Coulomb's law says (the soft contact settles in first: a tenth lost at most).
        CHECK(slid > 0.9 * 0.5 * a * seconds * seconds);
    } else {
        CHECK(world.body(b).sleep.asleep);
        CHECK(std::abs(slid) < 0.01); // held where it landed
    }
}

TEST_CASE("rigid sleep: a ball dropped on a sleeping pyramid wakes its island and no other", "[sleep][rigid]") {
    const Method method = GENERATE(Method::solver, Method::automatic);
    INFO("method " << methodName(method));
    const double gap = GENERATE(3.0, 8.0); // between the two pyramids' bases
    const int base = 4;
    World world(sleepDef(method));
    addFloor(world);
    const std::vector<BodyId> left = addPyramid(world, base, 0.0);
    const std::vector<BodyId> right = addPyramid(world, base, base + gap);
    std::vector<BodyId> all = left;
    all.insert(all.end(), right.begin(), right.end());
    REQUIRE(stepsToSleep(world, all, 240) > 0);
    // A ball above the left pyramid's top: it falls base + 1.5 m, and reaches the top within 1 s.
    CircleDef drop = ball({0.0, base + 1.5}, {0.0, 0.0}, 0.2);
    drop.material = {0.0, 0.5};
    world.addCircle(drop);
    int wokeAt = -1;
    for (int s = 1; s <= 90 && wokeAt < 0; ++s) {
        world.step();
        if (!allAsleep(world, left)) wokeAt = s;
    }
    INFO("the left pyramid woke at step " << wokeAt);
    REQUIRE(wokeAt > 0);
    CHECK(noneAsleep(world, left)); // the whole island, at once
    CHECK(allAsleep(world, right)); // the other one sleeps on
    // A setter wakes the right one's island too.
    world.setVelocity(right.front(), {0.0, 0.1});
    CHECK(noneAsleep(world, right));
}

TEST_CASE("rigid sleep: a sleeping seesaw wakes and tips when a ball lands on one end", "[sleep][rigid][joints]") {
    const Method method = GENERATE(Method::solver, Method::automatic);
    INFO("method " << methodName(method));
    const bool pivot = GENERATE(false, true); // a pivot, or a revolute joint to the world
    World world(sleepDef(method));
    addFloor(world);
    const double halfLength = 2.0;
    const BodyId plank = world.addBody(box({0.0, 1.0}, {halfLength, 0.1}));
    if (pivot) {
        world.addPivot(PivotDef{plank, {0.0, 0.0}, {0.0, 1.0}});
    } else {
        JointDef hinge;
        hinge.a = JointEnd{};
        hinge.b = JointEnd{{}, plank};
        hinge.localAnchorA = {0.0, 1.0};
        world.addJoint(hinge);
    }
    // Balanced on its hinge it is held there: it sleeps.
    REQUIRE(stepsToSleep(world, {plank}, 120) > 0);
    const double angle = world.body(plank).angle;
    world.addCircle(ball({halfLength - 0.3, 2.5}, {}, 0.2));
    bool woke = false;
    for (int s = 0; s < 60; ++s) {
        world.step();
        woke = woke || !world.body(plank).sleep.asleep;
    }
    CHECK(woke);
    // The ball's weight on the right end turns it clockwise.
    CHECK(world.body(plank).angle < angle - 0.05);
}

TEST_CASE("rigid sleep: a running motor keeps its island awake, switched off it sleeps, on again it wakes",
          "[sleep][rigid][joints]") {
    const Method method = GENERATE(Method::solver, Method::automatic);
    INFO("method " << methodName(method));
    // A motor speed whose rim speed, omega times the bounding radius, is under sleepSpeed: slow
    // enough to sleep by speed alone, so only the motor rule keeps it awake.
    const double speed = GENERATE(0.002, -0.005); // rad/s
    World world(sleepDef(method));
    const BodyId wheel = world.addBody(box({0.0, 2.0}, {0.5, 0.5}));
    REQUIRE(std::abs(speed) * boundingRadius(world.body(wheel)) < world.def().sleepSpeed);
    JointDef hinge;
    hinge.b = JointEnd{{}, wheel};
    hinge.localAnchorA = {0.0, 2.0};
    hinge.motor = {speed, 100.0};
    const JointId j = world.addJoint(hinge);
    const double seconds = 3.0;
    bool everAsleep = false;
    for (int s = 0; s < static_cast<int>(seconds / world.def().timeStep); ++s) {
        world.step();
        everAsleep = everAsleep || world.body(wheel).sleep.asleep;
    }
    CHECK_FALSE(everAsleep);
    CHECK(world.body(wheel).angle == Approx(speed * seconds).epsilon(0.05)); // driven all along
    world.setJointMotor(j, {0.0, 0.0});
    REQUIRE(stepsToSleep(world, {wheel}, 120) > 0);
    world.setJointMotor(j, {speed, 100.0});
    CHECK_FALSE(world.body(wheel).sleep.asleep);
}

// A boxing glove's piston (a prismatic joint with a motor and limits) punched out to the end of its
// stroke keeps driving into the limit, which pushes back: it moves nothing, so its island may sleep as
// a braked one does. Over slide directions (level, slanting, straight up against gravity), strokes
// and speeds: the glove comes to rest at the stroke's end and falls asleep there; a new speed wakes
// it, it slides back to the other limit and sleeps again.
TEST_CASE("rigid sleep: a motor stalled at its limit lets its island sleep, a new speed wakes it",
          "[sleep][rigid][joints]") {
    const Method method = GENERATE(Method::solver, Method::automatic);
    const double degrees = GENERATE(0.0, 30.0, 90.0);
    const double stroke = GENERATE(0.3, 0.8);
    const double speed = GENERATE(1.0, 4.0);
    INFO("method " << methodName(method) << ", axis at " << degrees << " degrees, stroke " << stroke << " m, speed "
                   << speed << " m/s");
    World world(sleepDef(method));
    const Vec2 axis{std::cos(degrees * kDegree), std::sin(degrees * kDegree)};
    const Vec2 home{0.0, 2.0};
    const BodyId glove = world.addBody(box(home, {0.15, 0.15}));
    JointDef piston;
    piston.kind = JointKind::prismatic;
    piston.b = JointEnd{{}, glove};
    piston.localAnchorA = home;
    piston.localAxisA = axis;
    piston.limits = {true, 0.0, stroke};
    piston.motor = {speed, 400.0};
    const JointId j = world.addJoint(piston);
    // Out to the stroke's end in stroke / speed, then asleep within the time to sleep and a second.
    const int most = static_cast<int>((stroke / speed + world.def().timeToSleep + 1.0) / world.def().timeStep);
    REQUIRE(stepsToSleep(world, {glove}, most) > 0);
    CHECK((world.body(glove).position - home).dot(axis) == Approx(stroke).margin(0.01));
    CHECK(world.body(glove).velocity.length() < world.def().sleepSpeed);
    // Pulled back: awake at once, home again, and asleep there too.
    world.setJointMotor(j, {-speed, 400.0});
    CHECK_FALSE(world.body(glove).sleep.asleep);
    REQUIRE(stepsToSleep(world, {glove}, most) > 0);
    CHECK((world.body(glove).position - home).dot(axis) == Approx(0.0).margin(0.01));
    // Without limits the same motor drives on and never sleeps (the rule above, for a slide).
    JointDef free = piston;
    free.limits = {};
    World open(sleepDef(method));
    const BodyId runner = open.addBody(box(home, {0.15, 0.15}));
    free.b = JointEnd{{}, runner};
    open.addJoint(free);
    CHECK(stepsToSleep(open, {runner}, most) < 0);
}

TEST_CASE("rigid sleep: sleeping on or off, a settled scene rests in the same place", "[sleep][rigid]") {
    const Method method = GENERATE(Method::solver, Method::automatic);
    INFO("method " << methodName(method));
    // Sleeping stops a body only after it has stayed under sleepSpeed for timeToSleep; the awake
    // run's bodies are at rest by then too, so the two agree to within what a body creeps in
    // timeToSleep at sleepSpeed (5 mm), the bound checked.
    const int base = GENERATE(3, 5);
    const auto run = [&](double sleepSpeed) {
        World world(sleepDef(method, sleepSpeed));
        addFloor(world);
        addPyramid(world, base, 0.0);
        // A few dominoes and a ball on the floor beside it.
        for (int k = 0; k < 3; ++k) world.addBody(box({5.0 + 0.6 * k, 0.5}, {0.1, 0.5}, 0.0));
        world.addCircle(ball({-5.0, 2.0}, {}, 0.3));
        for (int s = 0; s < 240; ++s) world.step();
        return world;
    };
    const World asleep = run(WorldDef{}.sleepSpeed), awake = run(0.0);
    const double bound = asleep.def().sleepSpeed * asleep.def().timeToSleep;
    double worst = 0.0;
    for (std::size_t k = 0; k < asleep.bodies().size(); ++k) {
        CHECK(asleep.bodies()[k].sleep.asleep);
        worst = std::max(worst, asleep.bodies()[k].position.distance(awake.bodies()[k].position));
    }
    INFO("base " << base << ": largest difference " << worst << " m (bound " << bound << " m)");
    CHECK(worst <= bound);
}

TEST_CASE("rigid sleep: deterministic, the same state hash run twice", "[sleep][rigid][determinism]") {
    const Method method = GENERATE(Method::solver, Method::automatic);
    INFO("method " << methodName(method));
    const auto run = [method] {
        World world(sleepDef(method));
        addFloor(world);
        addPyramid(world, 5, 0.0);
        addPyramid(world, 3, 7.0);
        const BodyId plank = world.addBody(box({-6.0, 1.0}, {1.5, 0.1}));
        world.addPivot(PivotDef{plank, {0.0, 0.0}, {-6.0, 1.0}});
        std::vector<std::uint64_t> hashes;
        for (int s = 0; s < 300; ++s) {
            if (s == 120) world.addCircle(ball({0.0, 7.0}, {}, 0.2));
            if (s == 150) world.addCircle(ball({-5.0, 3.0}, {}, 0.2));
            world.step();
            hashes.push_back(stateHash(world));
        }
        return hashes;
    };
    CHECK(run() == run());
}

TEST_CASE("rigid sleep: removing what a sleeping stack rests on wakes it, and it falls", "[sleep][rigid]") {
    const Method method = GENERATE(Method::solver, Method::automatic);
    INFO("method " << methodName(method));
    const int height = GENERATE(2, 4);
    World world(sleepDef(method));
    addFloor(world);
    std::vector<BodyId> stack;
    for (int k = 0; k < height; ++k) stack.push_back(world.addBody(box({0.0, 0.5 + k}, {0.5, 0.5})));
    REQUIRE(stepsToSleep(world, stack, 120) > 0);
    world.remove(stack.front());
    stack.erase(stack.begin());
    CHECK(noneAsleep(world, stack));
    // Free fall of 1 m takes sqrt(2 h / g) = 0.45 s: a second later the stack stands on the floor.
    for (int s = 0; s < 60; ++s) world.step();
    for (std::size_t k = 0; k < stack.size(); ++k)
        CHECK(world.body(stack[k]).position.y == Approx(0.5 + static_cast<double>(k)).margin(0.02));
}
