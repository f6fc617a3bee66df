// The rigid contacts' impacts: what the game's targets, switches and the trace hear of a box or a
// domino striking something, reported as the circle contacts report theirs (recordContactImpacts).
#include "rigid_stage.hpp"

namespace rube {

namespace {

/// Contacts in a worker's share of the check (a contact costs a few nanoseconds).
constexpr std::size_t kImpactChunk = 512;

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

int RigidStage::recordImpacts(StepContext& ctx) {
    // Which point of each contact struck (or kResting, kUntouched): each contact's own slot, shared
    // among the workers; the impacts are then made in the contacts' order from the few that struck.
    constexpr std::int8_t kUntouched = -1, kResting = -2;
    struckPoint_.resize(contacts_.size());
    const double restingSpeed = ctx.restingSpeed;
    forShares(pool_, contacts_.size(), kImpactChunk, [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) {
            const RigidContact& c = contacts_[i];
            const int k = fastestPoint(c);
            // Never touched: a speculative contact only. Pushing since the last step (warm started),
            // or touching slower than gravity adds in a step or two: resting contact, as the circle
            // solver counts it.
            const RigidContactPoint* p = k < 0 ? nullptr : &c.points[k];
            struckPoint_[i] = p == nullptr                                     ? kUntouched
                              : p->carried || p->approachSpeed <= restingSpeed ? kResting
                                                                               : static_cast<std::int8_t>(k);
        }
    });
    int impacts = 0;
    for (std::size_t i = 0; i < contacts_.size(); ++i) {
        if (struckPoint_[i] == kUntouched) continue;
        if (struckPoint_[i] == kResting) {
            ++ctx.stats.restingContacts;
            continue;
        }
        const RigidContact& c = contacts_[i];
        const RigidContactPoint& p = c.points[struckPoint_[i]];
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
