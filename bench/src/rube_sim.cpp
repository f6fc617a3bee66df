// The rube adapter: one registered engine per time-step method, all through the public World API.

#include "sim.hpp"

#include "rube/physics/world.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace bench {
namespace {

class RubeSim final : public Sim {
public:
    RubeSim(const WorldSpec& spec, rube::Method method) : world_(makeDef(spec, method)) {}

    int addBall(const BallSpec& s) override {
        rube::CircleDef def;
        def.position = s.position;
        def.velocity = s.velocity;
        def.radius = s.radius;
        def.mass = s.mass;
        def.material = {s.bounciness, s.friction};
        return world_.slot(world_.addCircle(def));
    }

    void addLine(const LineSpec& s) override {
        rube::SegmentDef def;
        def.a = s.a;
        def.b = s.b;
        def.radius = s.radius;
        def.material = {s.bounciness, s.friction};
        if (s.velocity.x != 0.0 || s.velocity.y != 0.0) {
            // Constant velocity as a two-key path: far enough in time that no bench run reaches its end.
            constexpr double kPathSeconds = 1e4;
            def.path = world_.addPath({{{0.0, {}}, {kPathSeconds, s.velocity * kPathSeconds}}, false});
        }
        world_.addSegment(def);
    }

    int addBox(const BoxSpec& s) override {
        rube::RigidBodyDef def;
        def.shape = rube::BodyShape::box;
        def.position = s.position;
        def.angle = s.angle;
        def.halfExtents = s.halfExtents;
        def.mass = s.density * 4.0 * s.halfExtents.x * s.halfExtents.y;
        def.material = {s.bounciness, s.friction};
        def.motion = s.fixed ? rube::Motion::fixed : rube::Motion::dynamic;
        boxes_.push_back(world_.addBody(def));
        return static_cast<int>(boxes_.size()) - 1;
    }

    void step() override { world_.step(); }
    int ballCount() const override { return static_cast<int>(world_.circles().size()); }
    BallState ball(int i) const override {
        const auto& c = world_.circles()[static_cast<std::size_t>(i)];
        return {c.position, c.velocity, c.angularVelocity, c.angle};
    }
    int boxCount() const override { return static_cast<int>(boxes_.size()); }
    BoxState box(int i) const override {
        const rube::RigidBody& b = world_.body(boxes_[static_cast<std::size_t>(i)]);
        return {b.position, b.angle, b.velocity, b.angularVelocity};
    }
    std::int64_t capsHit() const override { return world_.stats().capsHit; }

    bool addJoint(const JointSpec& s) override {
        // Only the solver carries joints (auto gives their world to it); the other methods refuse them.
        if (!rube::movesTurningBodies(world_.def().method)) {
            lacksJoint_ = true;
            return false;
        }
        const auto ballEnd = [&](int i) { return rube::JointEnd{world_.circleId(i), {}}; };
        rube::JointDef d;
        switch (s.kind) {
        case JointSpec::Kind::pin:
            d.kind = rube::JointKind::revolute;
            d.b = ballEnd(s.a);
            d.localAnchorA = world_.circles()[static_cast<std::size_t>(s.a)].position;
            d.motor = {s.motorSpeed, s.maxTorque};
            pins_.resize(std::max(pins_.size(), static_cast<std::size_t>(s.a) + 1));
            pins_[static_cast<std::size_t>(s.a)] = world_.addJoint(d);
            return true;
        case JointSpec::Kind::gear:
            d.kind = rube::JointKind::gear;
            d.jointA = pins_.at(static_cast<std::size_t>(s.a));
            d.jointB = pins_.at(static_cast<std::size_t>(s.b));
            d.ratio = s.ratio;
            break;
        case JointSpec::Kind::pulley:
            d.kind = rube::JointKind::pulley;
            d.a = ballEnd(s.a);
            d.b = ballEnd(s.b);
            d.groundA = s.groundA;
            d.groundB = s.groundB;
            d.ratio = s.ratio;
            d.length = s.length;
            break;
        case JointSpec::Kind::spring:
            d.kind = rube::JointKind::spring;
            d.localAnchorA = s.anchor;
            d.b = ballEnd(s.a);
            d.stiffness = s.stiffness;
            d.damping = s.damping;
            d.restLength = s.restLength;
            break;
        }
        world_.addJoint(d);
        return true;
    }

private:
    static rube::WorldDef makeDef(const WorldSpec& spec, rube::Method method) {
        rube::WorldDef def; // defaults for the rest (substeps 8, event cap 4096): as a level gets them
        def.gravity = spec.gravity;
        def.timeStep = spec.timeStep;
        def.method = method;
        if (!spec.rubeSleep) def.sleepSpeed = 0.0;
        def.workers = spec.rubeWorkers;
        return def;
    }

    rube::World world_;
    std::vector<rube::JointId> pins_; // per ball: its pin, for the gears
    std::vector<rube::BodyId> boxes_;
};

// Boxes that turn are moved by the solver alone (and by auto, which hands them to it).
Engine rubeEngine(rube::Method method, int order) {
    return {"rube-" + std::string(rube::methodName(method)), EngineKind::rubeMethod, order,
            [method](const WorldSpec& spec) { return std::make_unique<RubeSim>(spec, method); },
            method == rube::Method::solver || method == rube::Method::automatic};
}

[[maybe_unused]] const bool registered = registerEngine(rubeEngine(rube::Method::discrete, 0)) &&
                                         registerEngine(rubeEngine(rube::Method::turnBased, 1)) &&
                                         registerEngine(rubeEngine(rube::Method::exact, 2)) &&
                                         registerEngine(rubeEngine(rube::Method::solver, 3)) &&
                                         registerEngine(rubeEngine(rube::Method::automatic, 4));

} // namespace
} // namespace bench
