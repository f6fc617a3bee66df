// The joints' part of the solver's step (joint_stage.hpp).
#include "joint_stage.hpp"

#include <algorithm>

namespace rube {

namespace {

/// Sweeps over the joints in each of the solver's passes. Gauss-Seidel carries a load along a chain
/// one link a sweep: with one, a 10 kg weight on 20 links of 1 kg stretched the chain by 1.36 %
/// (boxes; 0.65 % capsules), with four by 0.27 % (0.32 %). Forces (springs) act once a pass.
constexpr int kJointPasses = 4;

JointSide sideOf(int circle, int body) {
    if (body >= 0) return {body, true};
    if (circle >= 0) return {circle, false};
    return {};
}

bool sameJoint(const Joint& x, const Joint& y) {
    return x.def.kind == y.def.kind && x.circleA == y.circleA && x.bodyA == y.bodyA && x.circleB == y.circleB &&
           x.bodyB == y.bodyB && x.jointA == y.jointA && x.jointB == y.jointB;
}

} // namespace

namespace {
constexpr std::int64_t kCirclePairBase = std::int64_t{1} << 32;
std::int64_t circlePairKey(int a, int b) {
    return static_cast<std::int64_t>(std::min(a, b)) * kCirclePairBase + std::max(a, b);
}
} // namespace

void connectedCirclePairs(std::span<const Joint> joints, std::vector<std::int64_t>& pairs) {
    pairs.clear();
    for (const Joint& j : joints)
        if (!j.def.collideConnected && j.circleA >= 0 && j.circleB >= 0)
            pairs.push_back(circlePairKey(j.circleA, j.circleB));
    std::sort(pairs.begin(), pairs.end());
}

bool connectedCircles(std::span<const std::int64_t> pairs, int a, int b) {
    return !pairs.empty() && std::binary_search(pairs.begin(), pairs.end(), circlePairKey(a, b));
}

bool jointsTurnCircles(std::span<const Joint> joints) {
    return std::any_of(joints.begin(), joints.end(), [](const Joint& j) { return j.circleA >= 0 || j.circleB >= 0; });
}

void JointStage::prepare(const StepContext& ctx, double h, const Softness& softness) {
    const std::size_t n = ctx.joints.size();
    const bool same = last_.size() == n && std::equal(last_.begin(), last_.end(), ctx.joints.begin(), sameJoint);
    constraints_.resize(n);
    circleTurn_.assign(ctx.circles.size(), 0.0);
    circles_.clear();
    const auto place = [&](int circle, int body, Vec2& centre, double& angle) {
        if (body >= 0) {
            centre = ctx.bodies[static_cast<std::size_t>(body)].position;
            angle = ctx.bodies[static_cast<std::size_t>(body)].angle;
        } else if (circle >= 0) {
            centre = ctx.circles[static_cast<std::size_t>(circle)].position;
            angle = ctx.circles[static_cast<std::size_t>(circle)].angle;
            circles_.push_back(circle);
        } else {
            centre = {};
            angle = 0.0;
        }
    };
    for (std::size_t k = 0; k < n; ++k) {
        const Joint& j = ctx.joints[k];
        JointConstraint& c = constraints_[k];
        if (!same) c = JointConstraint{};
        c.joint = &j;
        c.a = sideOf(j.circleA, j.bodyA);
        c.b = sideOf(j.circleB, j.bodyB);
        place(j.circleA, j.bodyA, c.centreA, c.angleA);
        place(j.circleB, j.bodyB, c.centreB, c.angleB);
        c.gearA = j.jointA;
        c.gearB = j.jointB;
        c.kickDue = false;
        if (!j.def.motor.on()) c.motorImpulse = 0.0; // a motor switched off (World::setJointMotor) pushes no more
    }
    std::sort(circles_.begin(), circles_.end());
    circles_.erase(std::unique(circles_.begin(), circles_.end()), circles_.end());
    last_.assign(ctx.joints.begin(), ctx.joints.end());
    step_ = JointStep{h, softness, Softness{softness.biasRate, 1.0, 0.0}, constraints_};
    for (JointConstraint& c : constraints_) behaviourOf(c.joint->def.kind).prepare(c, view_, step_);
}

void JointStage::bind(const RigidSolverView& view) { view_ = JointView{view, circleTurn_}; }

void JointStage::motorsStalled(std::vector<std::uint8_t>& out) const {
    out.resize(constraints_.size());
    for (std::size_t k = 0; k < constraints_.size(); ++k) {
        const JointConstraint& c = constraints_[k];
        const JointDef& d = c.joint->def;
        // The limit rows push against the coordinate's motion past them: the upper one back against a
        // motor turning it up (speed > 0), the lower one against a motor turning it down.
        out[k] = d.motor.on() && d.limits.on &&
                 ((d.motor.speed > 0.0 && c.upperImpulse > 0.0) || (d.motor.speed < 0.0 && c.lowerImpulse > 0.0));
    }
}

void JointStage::warmStart() {
    for (JointConstraint& c : constraints_) behaviourOf(c.joint->def.kind).warmStart(c, view_, step_);
}

void JointStage::solve(bool useBias) {
    for (int pass = 0; pass < kJointPasses; ++pass)
        for (JointConstraint& c : constraints_) {
            const JointBehaviour& b = behaviourOf(c.joint->def.kind);
            if (pass > 0 && b.isForce) continue;
            (useBias ? b.solvePosition : b.solveVelocity)(c, view_, step_);
        }
}

void JointStage::integrateCircleTurns(double h) {
    if (view_.bodies.omega.empty()) return;
    for (const int i : circles_)
        circleTurn_[static_cast<std::size_t>(i)] += view_.bodies.omega[static_cast<std::size_t>(i)] * h;
}

bool JointStage::holdsBody(int index) const {
    return std::any_of(constraints_.begin(), constraints_.end(), [&](const JointConstraint& c) {
        return (c.a.rigid && c.a.index == index) || (c.b.rigid && c.b.index == index);
    });
}

} // namespace rube
