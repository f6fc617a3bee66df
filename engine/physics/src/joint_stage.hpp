#pragma once
// Internal: the joints' part of the solver's step. RigidStage calls it at its own points of the
// substep loop (prepare, bind, warm start, solve, relax, positions), so joints, pivots and contacts
// form one Gauss-Seidel system over the same velocities. Each joint goes through its kind's
// JointBehaviour (joint_solver.hpp). Not part of the public API.

#include "joint_solver.hpp"
#include "step_method.hpp"

#include <cstdint>
#include <vector>

namespace rube {

class JointStage {
public:
    /// Sets up the step's joints as their ends stand at its start; impulses carried over when the
    /// joints are the ones of the last step.
    void prepare(const StepContext& ctx, double h, const Softness& softness);
    /// Binds the solver's bodies for the substeps.
    void bind(const RigidSolverView& view);
    bool empty() const { return constraints_.empty(); }
    void warmStart();
    /// solvePosition of every joint when `useBias`, else solveVelocity.
    void solve(bool useBias);
    /// After the substep's positions moved: the jointed circles' turns.
    void integrateCircleTurns(double h);
    /// True when a joint holds rigid body `index` (it is not free between its contacts).
    bool holdsBody(int index) const;
    /// After the step, per joint (ctx.joints order): 1 where its motor is stalled at a limit, driving
    /// into it while the limit pushed back this step: it moves nothing, only presses, as a brake holds.
    void motorsStalled(std::vector<std::uint8_t>& out) const;

private:
    std::vector<JointConstraint> constraints_;
    std::vector<Joint> last_; // the joints of the last step, to match the warm starts
    std::vector<double> circleTurn_;
    std::vector<int> circles_; // jointed circles
    JointStep step_;
    JointView view_;
};

/// True when some joint ends on a circle: the solver must turn circles this step.
bool jointsTurnCircles(std::span<const Joint> joints);

/// The pairs of circles a joint joins without collideConnected, as a * 2^32 + b with a < b,
/// sorted: the circle solver's contacts and sweeps leave them out (rigid_find_contacts.cpp does the same
/// for pairs with a rigid body).
void connectedCirclePairs(std::span<const Joint> joints, std::vector<std::int64_t>& pairs);

/// Whether circles a and b are among `pairs` (connectedCirclePairs).
bool connectedCircles(std::span<const std::int64_t> pairs, int a, int b);

/// Calls list(i) for each circle a joint ends on.
template <class List>
void listJointedCircles(std::span<const Joint> joints, List list) {
    for (const Joint& j : joints) {
        if (j.circleA >= 0) list(j.circleA);
        if (j.circleB >= 0) list(j.circleB);
    }
}

} // namespace rube
