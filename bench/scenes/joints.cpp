// joints-gear, joints-pulley, joints-spring (issue 21): a machine's joints against their formulas,
// run by every engine that has the joint (rube's solver and auto; Box2D 2.4.1's gear, pulley and
// distance-joint spring; Chipmunk 7's gear and damped spring, no pulley). rube's discrete,
// turn-based and exact methods refuse joints and are not run.
//  - gear: a motor turns wheel 1 at 3 rad/s; a gear of ratio 2.5 couples wheel 2:
//    error = the largest |angle2 + angle1 / 2.5| over 10 s (rad), error2 = |omega1 - 3| / 3 at the end.
//  - pulley: an Atwood machine of 1 kg and 3 kg for 2 s: error = |a - g (m2 - m1) / (m1 + m2)| / a from
//    the light ball's speed at the end, error2 = the largest |length - L| (m).
//  - spring: a 1 kg ball on a spring of k = 100 N/m to a fixed point, hanging under gravity and
//    set going 0.5 m below its rest, 20 s (32 periods): error = the largest relative energy error,
//    error2 = the period's relative error (up-crossings of the equilibrium).

#include "scene.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace bench {
namespace {

constexpr Vec2 kGravity{0.0, -9.81};
constexpr double kGearRatio = 2.5, kMotorSpeed = 3.0;

class GearProbe final : public Probe {
public:
    void observe(const Sim& sim, int, double) override {
        worst_ = std::max(worst_, std::abs(sim.ball(1).angle + sim.ball(0).angle / kGearRatio));
    }
    Metrics finish(const Sim& sim) override {
        Metrics m;
        m.error = worst_;
        m.error2 = std::abs(sim.ball(0).angularVelocity - kMotorSpeed) / kMotorSpeed;
        return m;
    }

private:
    double worst_ = 0.0;
};

constexpr double kLight = 1.0, kHeavy = 3.0, kRope = 60.0;
constexpr Vec2 kGroundA{-1.0, 30.0}, kGroundB{1.0, 30.0};

class PulleyProbe final : public Probe {
public:
    void observe(const Sim& sim, int, double t) override {
        const double length = sim.ball(0).position.distance(kGroundA) + sim.ball(1).position.distance(kGroundB);
        worst_ = std::max(worst_, std::abs(length - kRope));
        time_ = t;
    }
    Metrics finish(const Sim& sim) override {
        const double expected = 9.81 * (kHeavy - kLight) / (kLight + kHeavy);
        Metrics m;
        m.error = std::abs(sim.ball(0).velocity.y / time_ - expected) / expected;
        m.error2 = worst_;
        return m;
    }

private:
    double worst_ = 0.0, time_ = 1.0;
};

constexpr double kStiffness = 100.0, kRest = 1.0, kMass = 1.0;
constexpr Vec2 kAnchor{0.0, 5.0};
// The equilibrium hangs m g / k below the rest length; the ball starts 0.5 m below that.
constexpr double kSag = kMass * 9.81 / kStiffness;

class SpringProbe final : public Probe {
public:
    explicit SpringProbe(double dt) : dt_(dt) {}
    void observe(const Sim& sim, int step, double) override {
        const BallState b = sim.ball(0);
        const double stretch = b.position.distance(kAnchor) - kRest;
        // Spring, kinetic and gravity's energy, gravity's measured from the start.
        const double e = 0.5 * kStiffness * stretch * stretch + 0.5 * kMass * b.velocity.lengthSquared() +
                         kMass * 9.81 * (b.position.y - start_.y);
        worst_ = std::max(worst_, std::abs(e - e0_) / e0_);
        const double x = stretch - kSag;
        if (previous_ < 0.0 && x >= 0.0) ups_.push_back((step - 1 + (-previous_) / (x - previous_)) * dt_);
        previous_ = x;
    }
    Metrics finish(const Sim&) override {
        Metrics m;
        m.error = worst_;
        const double period = 2.0 * std::numbers::pi * std::sqrt(kMass / kStiffness);
        if (ups_.size() >= 2)
            m.error2 = std::abs((ups_.back() - ups_.front()) / static_cast<double>(ups_.size() - 1) - period) / period;
        return m;
    }

private:
    double dt_;
    Vec2 start_{kAnchor.x, kAnchor.y - kRest - kSag - 0.5};
    // The energy at the start: at rest, stretched by the sag and 0.5 m more.
    double e0_ = 0.5 * kStiffness * (kSag + 0.5) * (kSag + 0.5);
    double worst_ = 0.0, previous_ = 1.0;
    std::vector<double> ups_;
};

[[maybe_unused]] const bool gear = registerScene({
    .name = "joints-gear",
    .errorName = "gear_angle_error_rad",
    .error2Name = "motor_speed_error_rel",
    .logError = true,
    .gravity = kGravity,
    .duration = [](const SceneSize& s) { return s.quick ? 1.0 : 10.0; },
    .boundsMin = {-10, -10},
    .boundsMax = {10, 10},
    .build =
        [](Sim& sim, const SceneSize&) {
            sim.addBall({.position = {0, 0}, .radius = 0.5, .mass = 1.0});
            sim.addBall({.position = {3, 0}, .radius = 1.25, .mass = 2.0});
            sim.addJoint({.kind = JointSpec::Kind::pin, .a = 0, .motorSpeed = kMotorSpeed, .maxTorque = 50.0});
            sim.addJoint({.kind = JointSpec::Kind::pin, .a = 1});
            sim.addJoint({.kind = JointSpec::Kind::gear, .a = 0, .b = 1, .ratio = kGearRatio});
        },
    .probe = [](const SceneSize&, double) { return std::make_unique<GearProbe>(); },
});

[[maybe_unused]] const bool pulley = registerScene({
    .name = "joints-pulley",
    .errorName = "atwood_acceleration_error_rel",
    .error2Name = "rope_length_error_m",
    .logError = true,
    .gravity = kGravity,
    .duration = [](const SceneSize& s) { return s.quick ? 0.5 : 2.0; },
    .boundsMin = {-50, -50},
    .boundsMax = {50, 50},
    .build =
        [](Sim& sim, const SceneSize&) {
            sim.addBall({.position = {-1, 0}, .radius = 0.2, .mass = kLight});
            sim.addBall({.position = {1, 0}, .radius = 0.2, .mass = kHeavy});
            sim.addJoint({.kind = JointSpec::Kind::pulley,
                          .a = 0,
                          .b = 1,
                          .ratio = 1.0,
                          .groundA = kGroundA,
                          .groundB = kGroundB,
                          .length = kRope});
        },
    .probe = [](const SceneSize&, double) { return std::make_unique<PulleyProbe>(); },
});

[[maybe_unused]] const bool spring = registerScene({
    .name = "joints-spring",
    .errorName = "spring_energy_error_rel",
    .error2Name = "spring_period_error_rel",
    .logError = true,
    .gravity = kGravity,
    .duration = [](const SceneSize& s) { return s.quick ? 2.0 : 20.0; },
    .boundsMin = {-10, -10},
    .boundsMax = {10, 10},
    .build =
        [](Sim& sim, const SceneSize&) {
            sim.addBall({.position = {kAnchor.x, kAnchor.y - kRest - kSag - 0.5}, .radius = 0.1, .mass = kMass});
            sim.addJoint({.kind = JointSpec::Kind::spring,
                          .a = 0,
                          .anchor = kAnchor,
                          .stiffness = kStiffness,
                          .damping = 0.0,
                          .restLength = kRest});
        },
    .probe = [](const SceneSize&, double dt) { return std::make_unique<SpringProbe>(dt); },
});

} // namespace
} // namespace bench
