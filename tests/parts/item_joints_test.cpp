// Items with rigid bodies and joints (ItemBodies::rigidBodies, ::joints): the framework the
// catalogue's mechanisms stand on (issue 22). Two test kinds: a wheel on an axle to the world
// (a motor when its speed is set), and a belt that names two wheels by their items' names.
#include "level_run.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace rube;
using namespace rube::game;

namespace {

struct WheelParams {
    double radius = 0.5;
    double motorSpeed = 0.0; // rad/s; 0: no motor
    bool box = false;        // a square plate instead of a disc
};

constexpr PartKey kWheelKeys[] = {kKindKey, kNameKey, kPositionKey};

// A disc (or square plate) on an axle fixed in the world at its centre.
class TestWheel final : public PartKind {
public:
    std::string_view name() const override { return "test-wheel"; }
    int order() const override { return 1000; }
    std::string_view summary() const override { return "a test wheel"; }
    std::span<const PartKey> keys() const override { return kWheelKeys; }
    ItemDesc make(Vec2 position) const override { return made(position, WheelParams{}); }
    void read(TableReader&, ItemDesc&, SceneReading&) const override {}
    ItemBodies bodies(const ItemDesc& item) const override {
        const auto& p = item.params.as<WheelParams>();
        ItemBodies bodies;
        ItemJoint axle;
        axle.def.kind = JointKind::revolute;
        axle.def.localAnchorA = item.position; // the world's frame
        if (p.motorSpeed != 0.0) axle.def.motor = {p.motorSpeed, 1e3};
        axle.b.index = 0;
        if (p.box) {
            RigidBodyDef plate;
            plate.position = item.position;
            plate.halfExtents = {p.radius, p.radius};
            plate.angle = item.angle;
            plate.mass = 2.0;
            bodies.rigidBodies.push_back(plate);
            axle.b.to = ItemJointEnd::To::body;
        } else {
            CircleDef disc;
            disc.position = item.position;
            disc.radius = p.radius;
            disc.mass = 1.0;
            bodies.circles.push_back(disc);
            axle.b.to = ItemJointEnd::To::circle;
        }
        bodies.joints.push_back(axle);
        return bodies;
    }
    void draw(const PartDrawing&) const override {}
};

struct BeltParams {
    std::string from, to;
    double ratio = -1.0;
};

// A belt: a gear between the axles of two wheels, named.
class TestBelt final : public PartKind {
public:
    std::string_view name() const override { return "test-belt"; }
    int order() const override { return 1001; }
    std::string_view summary() const override { return "a test belt"; }
    std::span<const PartKey> keys() const override { return kWheelKeys; }
    ItemDesc make(Vec2 position) const override { return made(position, BeltParams{}); }
    void read(TableReader&, ItemDesc&, SceneReading&) const override {}
    ItemBodies bodies(const ItemDesc& item) const override {
        const auto& p = item.params.as<BeltParams>();
        ItemBodies bodies;
        ItemJoint belt;
        belt.def.kind = JointKind::gear;
        belt.def.ratio = p.ratio;
        belt.gearItemA = p.from;
        belt.gearItemB = p.to;
        bodies.joints.push_back(belt);
        return bodies;
    }
    void draw(const PartDrawing&) const override {}
};

const TestWheel kWheel;
const TestBelt kBelt;

ItemDesc wheel(const std::string& name, Vec2 at, WheelParams params) {
    ItemDesc item = kWheel.make(at);
    item.name = name;
    item.params = PartParams(params);
    return item;
}

SceneDesc machine(double r1, double r2, double speed, bool plate) {
    SceneDesc scene;
    scene.world.timeStep = 1.0 / 60;
    scene.world.method = Method::solver;
    scene.world.gravity = {0.0, 0.0};
    scene.level.items.push_back(wheel("driver", {-2.0, 1.0}, {r1, speed, false}));
    // The belt is listed between its wheels: it names one listed after it.
    ItemDesc belt = kBelt.make({0.0, 1.0});
    belt.params = PartParams(BeltParams{"driver", "driven", -r2 / r1});
    scene.level.items.push_back(belt);
    scene.level.items.push_back(wheel("driven", {2.0, 1.0}, {r2, 0.0, plate}));
    return scene;
}

} // namespace

TEST_CASE("an item's rigid bodies and joints join the World, and a belt named by items turns its wheel",
          "[parts][joints]") {
    for (const bool plate : {false, true}) {
        for (const auto& [r1, r2] : {std::pair{0.5, 0.25}, std::pair{0.4, 0.4}, std::pair{0.3, 0.75}}) {
            INFO("r1 " << r1 << " r2 " << r2 << (plate ? " (a plate)" : " (a disc)"));
            LevelRun run(machine(r1, r2, 3.0, plate), {});
            REQUIRE(run.world().joints().size() == 3); // two axles and the belt
            REQUIRE(run.states()[2].body.isNull() == !plate);
            REQUIRE(run.states()[0].joints.size() == 1);
            REQUIRE(run.states()[1].joints.size() == 1);
            for (int i = 0; i < 120; ++i) run.step();
            const double driver = run.world().circle(run.states()[0].circle).angularVelocity;
            const double driven = plate ? run.world().body(run.states()[2].body).angularVelocity
                                        : run.world().circle(run.states()[2].circle).angularVelocity;
            CHECK(driver == Approx(3.0).epsilon(0.01));
            // A belt turns both wheels the same way, at r1 / r2 of the driver (within 0.5 %).
            CHECK(driven == Approx(driver * r1 / r2).epsilon(0.005));
            // The axles hold: each wheel's centre stays where it was placed.
            CHECK(run.itemPosition(2).x == Approx(2.0).margin(1e-6));
            CHECK(run.itemPosition(0).y == Approx(1.0).margin(1e-6));
        }
    }
}

TEST_CASE("a rigid item's extent is its body's bounds, turned", "[parts][joints]") {
    for (const double degrees : {0.0, 30.0, 45.0, 90.0}) {
        INFO(degrees << " degrees");
        ItemDesc plate = wheel("plate", {2.0, 1.0}, {0.5, 0.0, true});
        plate.angle = degrees * std::numbers::pi / 180.0;
        // A square of half side h turned by a has half bounds h (|cos a| + |sin a|).
        const double half = 0.5 * (std::abs(std::cos(plate.angle)) + std::abs(std::sin(plate.angle)));
        const Aabb box = kWheel.extent(plate);
        CHECK(box.min.x == Approx(2.0 - half));
        CHECK(box.max.y == Approx(1.0 + half));
    }
}
