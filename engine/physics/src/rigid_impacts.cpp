// The rigid contacts' impacts: what the game's targets, switches and the trace hear of a box or a
// domino striking something, reported as the circle contacts report theirs (recordContactImpacts).
#include "rigid_stage.hpp"

namespace rube {

namespace {

/// The point of the contact that approached fastest among those that pushed, or -1 when none did.
int fastestPoint(const RigidContact& c) {
    int best = -1;
    for (int k = 0; k < c.count; ++k) {
        const RigidContactPoint& p = c.points[k];
        if (p.maxNormalImpulse <= 0.0) continue;
        if (best < 0 || p.approachSpeed > c.points[best].approachSpeed) best = k;
    }
    return best;
}

} // namespace

int RigidStage::recordImpacts(StepContext& ctx) const {
    int impacts = 0;
    for (const RigidContact& c : contacts_) {
        const int k = fastestPoint(c);
        if (k < 0) continue; // never touched: a speculative contact only
        const RigidContactPoint& p = c.points[k];
        // Pushing since the last step (warm started), or touching slower than gravity adds in a step
        // or two: resting contact, as the circle solver counts it.
        if (p.carried || p.approachSpeed <= ctx.restingSpeed) {
            ++ctx.stats.restingContacts;
            continue;
        }
        // Side A is always a rigid body; its anchor has moved and turned with it over the step.
        const auto a = static_cast<std::size_t>(c.a.index);
        const RigidState& s = states_[a];
        Impact impact;
        impact.time = ctx.time + p.touchSubstep * substepTime_;
        impact.pointOfImpact = startPosition_[a] + s.displacement + rotate(s.turnRotation, p.anchorA);
        impact.approachSpeed = p.approachSpeed;
        const bool ballHitsBody = !c.b.rigid && c.b.index < circleCount_ &&
                                  ctx.circles[static_cast<std::size_t>(c.b.index)].motion == Motion::dynamic;
        if (ballHitsBody) {
            // A ball's impact on a body: the ball is the circle, the normal points from the body to it.
            impact.circle = c.b.index;
            impact.otherKind = Other::body;
            impact.other = c.a.index;
            impact.normal = c.normal;
        } else {
            // The body's impact (lecture 3's blocks report theirs so): circle -1, the normal towards the body.
            impact.body = c.a.index;
            impact.otherKind = c.b.rigid ? Other::body : c.b.index < circleCount_ ? Other::circle : Other::segment;
            impact.other = c.b.rigid || c.b.index < circleCount_ ? c.b.index : c.b.index - circleCount_;
            impact.normal = -c.normal;
        }
        ctx.impacts.push_back(impact);
        ++impacts;
    }
    ctx.stats.impacts += impacts;
    return impacts;
}

} // namespace rube
