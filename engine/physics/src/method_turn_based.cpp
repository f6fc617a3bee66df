// The turn-based method (lecture 3): velocities take gravity first, then each dynamic body in index
// order moves over the step or until its first impact against the others where they are now, and
// that impact is resolved at once. Efficient and overlap-free, but positions are slightly off: order matters.
// Resting contact on something that holds still (an approach below restingSpeed, C = 0) does not end
// the turn: the body slides on along the surface for the rest of it, as on an incline it must.
#include "block_pairs.hpp"
#include "kinematic_pose.hpp"
#include "resolve.hpp"
#include "step_method.hpp"

#include "rube/physics/time_of_impact.hpp"

#include <algorithm>
#include <cmath>

namespace rube {
namespace {

// Pieces one turn may take (each ends at an impact on a still surface) before it ends where it is.
constexpr int kPiecesPerTurn = 8;
// Two surfaces wedge a circle when their normals are not parallel (|n1 x n2| above round-off).
constexpr double kParallelSine = 1e-9;

// The earliest impact of one body's turn, and what it hit.
struct TurnImpact {
    Collision collision;
    Other kind = Other::circle;
    int other = -1;
    Vec2 otherVelocity; ///< the other's velocity (zero for a body standing still in this turn)
    double otherInverseMass = 0.0;
    double bounciness = 1.0;
    bool scripted = false; ///< the other is kinematic: it keeps moving during the turn
};

class TurnBasedMethod final : public StepMethod {
public:
    void step(StepContext& ctx, double dt) override {
        // "Update velocities using gravity and other forces" (lecture 3).
        for (Circle& c : ctx.circles)
            if (c.motion == Motion::dynamic) c.velocity += ctx.def.gravity * dt;
        for (RigidBody& b : ctx.bodies)
            if (isBlock(b) && b.motion == Motion::dynamic) b.velocity += ctx.def.gravity * dt;
        int events = 0;
        for (int i = 0; i < static_cast<int>(ctx.circles.size()); ++i)
            if (ctx.circles[i].motion == Motion::dynamic && takeTurn(ctx, i, dt)) ++events;
        // Lecture 3's blocks take their turns after the circles, in index order.
        for (int i = 0; i < static_cast<int>(ctx.bodies.size()); ++i)
            if (isBlock(ctx.bodies[i]) && ctx.bodies[i].motion == Motion::dynamic && takeBlockTurn(ctx, i, dt))
                ++events;
        for (RigidBody& b : ctx.bodies)
            if (isBlock(b) && b.motion == Motion::kinematic) b.position += b.velocity * dt;
        // Kinematic bodies follow their scripts over the whole step; the turns saw them doing so.
        for (Circle& c : ctx.circles)
            if (c.motion == Motion::kinematic) c.position += c.velocity * dt;
        for (Segment& s : ctx.segments) {
            if (s.motion() != Motion::kinematic) continue;
            s.a += s.velocity * dt;
            s.b += s.velocity * dt;
        }
        ctx.stats.maxEventsInStep = std::max(ctx.stats.maxEventsInStep, events);
    }

private:
    // Moves circle i over dt or to its first impact; returns whether it resolved one.
    static bool takeTurn(StepContext& ctx, int i, double dt) {
        double elapsed = 0.0;
        bool impacted = false;
        TurnImpact last; // the still surface the previous piece of the turn ended on (other < 0: none)
        for (int piece = 0; piece < kPiecesPerTurn; ++piece) {
            // A still surface (a static line, a fixed body) is where it is for the whole turn, so an
            // impact on it need not end the turn: the circle goes on with its new velocity for the rest
            // of the step (sliding along it after a resting impact), and its position stays the one
            // integration of its velocity. Against a body that moves in its own turn, the turn ends (lecture 3).
            const TurnEnd end = moveUntilImpact(ctx, i, dt - elapsed, ctx.time + elapsed, last);
            impacted = impacted || end.impact;
            if (!end.goesOn) break;
            elapsed += end.time;
        }
        return impacted;
    }

    // How a piece of a turn ended: at `time`, at a real impact or not, and whether the turn goes on.
    struct TurnEnd {
        bool impact = false;
        bool goesOn = false;
        double time = 0.0;
    };

    // True when `a` and `b` name the same body (a segment's face and cap are one body).
    static bool sameOther(const TurnImpact& a, Other kind, int other) {
        const auto body = [](Other k) { return k == Other::segmentCap ? Other::segment : k; };
        return a.other == other && body(a.kind) == body(kind);
    }

    // Moves circle i over dt or to its first impact and resolves it. `rested` (the surface the turn
    // just slid from) is not searched: it is convex and holds still, so a velocity along it cannot
    // meet it again, and round-off would otherwise find it at t = 0 for ever.
    static TurnEnd moveUntilImpact(StepContext& ctx, int i, double dt, double now, TurnImpact& rested) {
        Circle& c = ctx.circles[i];
        std::optional<TurnImpact> first;
        const auto consider = [&](const std::optional<Collision>& hit, TurnImpact impact) {
            if (!hit || (first && first->collision.timeOfImpact <= hit->timeOfImpact)) return;
            if (rested.other >= 0 && sameOther(rested, impact.kind, impact.other)) return;
            impact.collision = *hit;
            first = impact;
        };
        // The other dynamic bodies stand still during this turn (lecture 3 tip). Scripted bodies
        // move on regardless, so they are met with the velocity relative to them.
        for (int k = 0; k < static_cast<int>(ctx.segments.size()); ++k) {
            const Segment& s = ctx.segments[k];
            const bool scripted = s.motion() == Motion::kinematic;
            // A turning segment is met as translating with its surface's velocity nearest the circle.
            const Vec2 surface = velocityTowards(s, c.position);
            const CircleMotion motion{c.position, c.velocity - surface, c.radius, {}};
            const auto hit = circleSegmentCollision(motion, s.a, s.b, s.radius, dt);
            consider(hit, TurnImpact{{},
                                     hit && hit->lineCap ? Other::segmentCap : Other::segment,
                                     k,
                                     surface,
                                     0.0,
                                     pairBounciness(c.material, s.material),
                                     scripted});
        }
        for (int j = 0; j < static_cast<int>(ctx.circles.size()); ++j) {
            const Circle& o = ctx.circles[j];
            if (j == i) continue;
            const bool scripted = o.motion == Motion::kinematic;
            const Vec2 relative = scripted ? c.velocity - o.velocity : c.velocity;
            consider(
                circleCircleCollision({c.position, relative, c.radius, {}}, o.position, o.radius, dt),
                TurnImpact{
                    {}, Other::circle, j, o.velocity, o.inverseMass, pairBounciness(c.material, o.material), scripted});
        }
        // Blocks stand still too; the block's motion relative to the circle is the circle's reversed.
        for (int b = 0; b < static_cast<int>(ctx.bodies.size()); ++b) {
            const RigidBody& o = ctx.bodies[b];
            if (!isBlock(o)) continue;
            const bool scripted = o.motion == Motion::kinematic;
            const Vec2 relative = scripted ? c.velocity - o.velocity : c.velocity;
            const auto hit = blockCircleCollision({o.position, -relative, o.halfExtents, {}}, c.position, c.radius, dt);
            if (!hit) continue;
            // Seen from the circle: its centre then, and the normal from the block towards it.
            const Collision seen{hit->timeOfImpact, c.position + relative * hit->timeOfImpact, -hit->normal,
                                 hit->contactPoint + relative * hit->timeOfImpact, hit->lineCap};
            consider(
                seen,
                TurnImpact{
                    {}, Other::body, b, o.velocity, o.inverseMass, pairBounciness(c.material, o.material), scripted});
        }
        if (!first) {
            c.position += c.velocity * dt;
            return {false, false, dt};
        }
        const Collision& hit = first->collision;
        const double t = hit.timeOfImpact;
        // The collision was found where the other stands still: a scripted one has moved on by v t.
        const Vec2 carried = first->scripted ? first->otherVelocity * t : Vec2{};
        c.position = hit.pointOfImpact + carried;
        // Newton with the other's velocity, only if approaching (lecture 3 tip: the relative velocity decides).
        // An approach slower than restingSpeed (what gravity gives within a step) is resting contact,
        // resolved with C = 0 as the exact method does: a resting ball with C = 1 would hop g dt every step.
        Vec2 otherVelocity = first->otherVelocity;
        const bool resting = approachSpeed(c.velocity, otherVelocity, hit.normal) < ctx.restingSpeed;
        const double approach = resolveImpact(c.velocity, c.inverseMass, otherVelocity, first->otherInverseMass,
                                              hit.normal, resting ? 0.0 : first->bounciness);
        if (first->kind == Other::circle && ctx.circles[first->other].motion == Motion::dynamic)
            ctx.circles[first->other].velocity = otherVelocity;
        if (first->kind == Other::body && ctx.bodies[first->other].motion == Motion::dynamic)
            ctx.bodies[first->other].velocity = otherVelocity;
        // The turn ends at the impact. Against a scripted body, which does not stop, the circle moves
        // on with its new velocity for the rest of the step: it would lag a step behind otherwise,
        // and a ball on a rising platform would sink through it.
        if (first->scripted) c.position += c.velocity * (dt - t);
        // Held by a surface that stands still for good (a static line, a fixed body): a resting
        // approach leaves the turn going on along it; a real impact ends the turn (lecture 3).
        const bool holdsStill = !first->scripted && first->otherInverseMass == 0.0;
        TurnEnd goesOn{false, holdsStill, t};
        // Against two still surfaces at an angle within one turn (a V, a corner), it is wedged: at rest
        // on both, or still driven into the first, the only velocity both leave is zero. Projected
        // on each in turn it would lose only |cos| of their angle per impact (1.5 % in a 5-degree V)
        // and, ending its turns at t = 0, never move again while gravity fed it.
        if (holdsStill && rested.other >= 0 && std::abs(rested.collision.normal.cross(hit.normal)) > kParallelSine &&
            (resting || c.velocity.dot(rested.collision.normal) < 0.0)) {
            c.velocity = {};
            goesOn.goesOn = false;
        }
        if (holdsStill) rested = *first;
        if (!(approach > 0.0)) return goesOn;
        ctx.impacts.push_back(
            Impact{i, first->kind, first->other, now + t, hit.contactPoint + carried, hit.normal, approach});
        ++ctx.stats.impacts;
        if (resting) {
            ++ctx.stats.restingContacts;
            return goesOn;
        }
        goesOn.impact = true;
        return goesOn;
    }

    // A block's turn (lecture 3's Assignment 3.3): it moves over dt or to its first impact against the
    // others where they stand, and that impact is resolved on the axis of impact.
    static bool takeBlockTurn(StepContext& ctx, int i, double dt) {
        RigidBody& b = ctx.bodies[i];
        const BlockEvent event = earliestBlockImpact(ctx, i, BlockSearch{{}, dt, false, true, {}});
        if (event.block < 0) {
            b.position += b.velocity * dt;
            return false;
        }
        const double t = event.time;
        const BlockPartner partner = blockPartner(ctx, event.kind, event.other);
        const bool scripted = partner.inverseMass == 0.0 && partner.velocity != Vec2{};
        // Its own velocity over t: the relative motion plus what a scripted other carried it by.
        b.position += b.velocity * t;
        const double approach = approachSpeed(b.velocity, partner.velocity, event.normal);
        resolveBlockImpact(ctx, event, ctx.time + t, false, approach > 0.0);
        // The turn ends at the impact, except against a scripted body, which does not stop.
        if (scripted) b.position += b.velocity * (dt - t);
        return approach > 0.0;
    }
};

} // namespace

std::unique_ptr<StepMethod> makeTurnBasedMethod() { return std::make_unique<TurnBasedMethod>(); }

} // namespace rube
