// How stiff each rigid contact and pivot is: the stacking contacts (between shapes no pivot or joint
// holds) and the others, a ball's and a mechanism's (engine/physics/ARCHITECTURE.md, "Stacks and
// mechanisms").
#include "rigid_stage.hpp"

#include <algorithm>

namespace rube {

namespace {

/// Stiffness of rigid contacts between two movable bodies (and twice that against infinite mass),
/// at most this fraction of the substep rate, heavily damped: the circle contacts' tuning.
constexpr double kContactHertz = 60.0;
/// Stiffness of the stacking contacts (RigidContact::stacking: between shapes no pivot or joint
/// holds), likewise capped. A box resting under load L overlaps by L / (m omega^2) (makeSoftness'
/// spring), so a pyramid sinks by the sum of its rows' loads over omega^2. At 70 Hz, relaxed once
/// (method_solver.cpp, kRigidContactRelaxPasses), Box2D's 100-row pyramid sinks 0.14 m and no box
/// moves more than 0.20 m; at 60 Hz a box then moved 0.25 m. The other contacts keep 60 Hz: a
/// ball's and a mechanism's, stiffer, changed how seesaws, buckets, paddles and counterweights throw
/// and catch (three levels' wrong attempts reached the goal at 65 and 70 Hz, and at 90 the
/// chain-door's solution of the time, since rebuilt, no longer did).
constexpr double kStackContactHertz = 70.0;
constexpr double kMaxHertzPerSubstepRate = 0.25;
constexpr double kStaticHertzScale = 2.0;
constexpr double kContactDampingRatio = 10.0;
/// Pivots: stiffer than contacts and less damped, as Box2D v3's joints (twice the contact hertz).
constexpr double kPivotHertz = 120.0;
constexpr double kPivotDampingRatio = 2.0;

} // namespace

void RigidStage::chooseSoftnesses(double h) {
    // A contact's spring at `wanted` hertz (capped by the substep rate), and twice as stiff against infinite mass.
    const auto springs = [h](double wanted, Softness& movable, Softness& fixed) {
        const double hertz = std::min(wanted, kMaxHertzPerSubstepRate / h);
        movable = makeSoftness(hertz, kContactDampingRatio, h);
        fixed = makeSoftness(kStaticHertzScale * hertz, kContactDampingRatio, h);
    };
    springs(kContactHertz, contactSoftness_.movable, contactSoftness_.fixed);
    springs(kStackContactHertz, contactSoftness_.stackMovable, contactSoftness_.stackFixed);
    pivotSoftness_ = makeSoftness(std::min(kPivotHertz, 2.0 * kMaxHertzPerSubstepRate / h), kPivotDampingRatio, h);
}

bool RigidStage::stacking(const RigidContact& c) const {
    const auto shape = [&](BodySide side, int body) {
        const bool circle = !side.rigid && side.index < circleCount_;
        return !circle && held_[static_cast<std::size_t>(body)] == 0;
    };
    return shape(c.a, c.bodyA) && shape(c.b, c.bodyB);
}

void RigidStage::markHeld(const StepContext& ctx) {
    held_.assign(states_.size(), 0);
    const auto rigid = [&](int body) {
        if (body >= 0) held_[static_cast<std::size_t>(body)] = 1;
    };
    const auto circle = [&](int c) {
        // A jointed circle no rigid contact touches has no solver body here, and needs none.
        if (c >= 0 && otherSlot_[static_cast<std::size_t>(c)] >= 0)
            held_[static_cast<std::size_t>(otherSlot_[static_cast<std::size_t>(c)])] = 1;
    };
    for (const Pivot& p : ctx.pivots) rigid(p.body);
    for (const Joint& j : ctx.joints) {
        rigid(j.bodyA);
        rigid(j.bodyB);
        circle(j.circleA);
        circle(j.circleB);
    }
}

} // namespace rube
