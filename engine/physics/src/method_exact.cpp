// The exact method, lecture 3's ideal time step: find the earliest time of impact over all pairs,
// move every body to it, resolve only that impact, and continue with the rest of the step.
// Dynamic bodies move exactly on their parabola p + v t + g t^2 / 2, so times of impact under
// gravity are roots of a quadratic (line face) or a quartic (circle, line cap).
// Approaches slower than restingSpeed are resting contact: resolved with C = 0, left out of the
// search for the rest of the step, and pushed apart at its end. A resting contact on a static line's
// face holds the ball on it: for the rest of the step it slides along the face under the part of
// gravity the face does not cancel, so its next impact (the other side of a V) is found exactly,
// and a ball held by two faces that are not parallel stands still. A circle on a spring to a fixed
// point moves on the spring's closed form instead (exact_springs.hpp), its times of impact found by
// conservative advancement to round-off (exact_spring_impacts.hpp). Meant for sparse scenes: every
// event costs an O(n^2) search, and a pile of many balls is the solver method's job.
#include "block_pairs.hpp"
#include "exact_held_faces.hpp"
#include "exact_resting_pairs.hpp"
#include "exact_settle.hpp"
#include "exact_spring_impacts.hpp"
#include "magnet_pulls.hpp"
#include "kinematic_pose.hpp"
#include "resolve.hpp"
#include "step_method.hpp"

#include "rube/physics/time_of_impact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace rube {
namespace {

// The earliest impact found so far, and which pair it belongs to.
struct Candidate {
    double time = std::numeric_limits<double>::infinity();
    int circle = -1;
    Other kind = Other::circle;
    int other = -1;
    Vec2 normal;
    BlockEvent block; ///< a block's impact instead, when block.block >= 0 (lecture 3's blocks)
    int face = -1;    ///< instead, the circle held on held_'s face `face` slides off the end of that face
};

class ExactMethod final : public StepMethod {
public:
    void step(StepContext& ctx, double dt) override {
        circleCount_ = static_cast<int>(ctx.circles.size());
        resting_.reset(circleCount_);
        blockResting_.clear();
        held_.reset(ctx.circles.size(), ctx.def.gravity);
        // Throws, before anything moved, when a joint has no closed form (exact_springs.hpp).
        springs_.build(ctx);
        if (!springs_.empty()) keepStart(ctx);
        // Lecture 3's blocks search assuming plain gravity: beside them a magnet's pull stays a kick.
        pulls_.clear();
        if (!ctx.magnets.empty() && ctx.bodies.empty()) pullByMagnets(ctx, dt);

        // "While CurrentTime < TargetTime: compute the earliest collision, move all bodies to it,
        // resolve it" (lecture 3). Work is bounded by def.maxEventsPerStep.
        double elapsed = 0.0;
        int events = 0;
        bool capped = false;
        while (elapsed < dt) {
            const double horizon = dt - elapsed;
            const Candidate next = earliestCollision(ctx, horizon);
            if (next.circle < 0 && next.block.block < 0 && next.face < 0) {
                advance(ctx, horizon);
                break;
            }
            if (events >= ctx.def.maxEventsPerStep) {
                // Give up on exactness for the rest of this step; the clean-up keeps it overlap-free.
                ++ctx.stats.capsHit;
                capped = true;
                advance(ctx, horizon);
                break;
            }
            advance(ctx, next.time);
            elapsed += next.time;
            if (next.face >= 0) {
                release(next.face);
            } else {
                resolve(ctx, next, ctx.time + elapsed);
            }
            ++events;
        }
        if (capped) {
            centres_.resize(ctx.circles.size());
            for (std::size_t i = 0; i < ctx.circles.size(); ++i) centres_[i] = ctx.circles[i].position;
            separateOverlaps(ctx, centres_, 0.0, ctx.time + dt, false);
            if (!ctx.bodies.empty()) {
                centres_.resize(ctx.bodies.size());
                for (std::size_t i = 0; i < ctx.bodies.size(); ++i) centres_[i] = ctx.bodies[i].position;
                separateBlockOverlaps(ctx, centres_, 0.0, ctx.time + dt);
            }
        }
        settle_.settle(ctx, dt, resting_, springs_, blockResting_, pulls_);
        pulls_.finish(ctx.circles, ctx.magnets, dt);
        ctx.stats.maxEventsInStep = std::max(ctx.stats.maxEventsInStep, events);
    }

private:
    // The earliest time of impact over all pairs within the horizon, in index order on ties.
    Candidate earliestCollision(const StepContext& ctx, double horizon) const {
        Candidate best;
        const Vec2 g = ctx.def.gravity;
        const auto consider = [&](const std::optional<Collision>& hit, int circle, Other kind, int other) {
            if (hit && hit->timeOfImpact < best.time)
                best = Candidate{hit->timeOfImpact, circle, kind, other, hit->normal, {}, -1};
        };
        for (int i = 0; i < circleCount_; ++i) {
            const Circle& c = ctx.circles[i];
            if (c.motion != Motion::dynamic) continue;
            for (int j = 0; j < circleCount_; ++j) {
                const Circle& o = ctx.circles[j];
                const bool dynamicOther = o.motion == Motion::dynamic;
                if (j == i || (dynamicOther && j < i) || resting_.resting(i, Other::circle, j)) continue;
                // Two falling balls share gravity: relative to each other they move in straight lines
                // (the lecture's quadratic); against a kinematic circle the relative motion is a parabola.
                // A ball held on a face accelerates with what the face leaves of gravity.
                const Vec2 a = held_.acceleration(i);
                if (!springs_.empty() && (springs_.pathOf(i) || springs_.pathOf(j))) {
                    // A spring's closed form is no polynomial: the gap's first root by advancement.
                    consider(trajectoryCircleCollision(trajectoryOf(ctx, i, horizon), c.radius,
                                                       trajectoryOf(ctx, j, horizon), o.radius, horizon),
                             i, Other::circle, j);
                    continue;
                }
                const CircleMotion motion{c.position, c.velocity - o.velocity, c.radius,
                                          dynamicOther ? a - held_.acceleration(j) : a};
                consider(circleCircleCollision(motion, o.position, o.radius, horizon), i, Other::circle, j);
            }
            for (int k = 0; k < static_cast<int>(ctx.segments.size()); ++k) {
                const Segment& s = ctx.segments[k];
                if (resting_.resting(i, Other::segment, k)) continue;
                if (!springs_.empty() && springs_.pathOf(i)) {
                    const auto hit = trajectorySegmentCollision(trajectoryOf(ctx, i, horizon), c.radius, s.a, s.b,
                                                                velocityTowards(s, c.position), s.radius, horizon);
                    consider(hit, i, hit && hit->lineCap ? Other::segmentCap : Other::segment, k);
                    continue;
                }
                const CircleMotion motion{c.position, c.velocity - velocityTowards(s, c.position), c.radius,
                                          held_.acceleration(i)};
                const auto hit = circleSegmentCollision(motion, s.a, s.b, s.radius, horizon);
                consider(hit, i, hit && hit->lineCap ? Other::segmentCap : Other::segment, k);
            }
        }
        // Lecture 3's blocks against everything; a world without bodies never enters the loop.
        const BlockSearch search{g, horizon, true, false, blockResting_};
        for (int b = 0; b < static_cast<int>(ctx.bodies.size()); ++b) {
            if (!isBlock(ctx.bodies[b])) continue;
            const BlockEvent event = earliestBlockImpact(ctx, b, search);
            if (event.time < best.time)
                best = Candidate{event.time, -1, event.kind, event.other, event.normal, event, -1};
        }
        // A held circle leaves its face where its centre passes the face's end: from there on its cap.
        for (int f = 0; f < held_.size(); ++f) {
            const auto leaves = held_.leavesFace(ctx, f, std::min(horizon, best.time));
            if (leaves && *leaves < best.time) {
                best = Candidate{};
                best.time = *leaves;
                best.face = f;
            }
        }
        return best;
    }

    // A magnet's pull moves a circle as gravity does (magnet_pulls.hpp): it meets what holds it at
    // the speed the gap allows and rests there (C = 0), and a face it rests on holds it with what it
    // leaves of g + a0 (exact_held_faces.hpp). A spring's circle keeps its closed form and the kick.
    void pullByMagnets(StepContext& ctx, double dt) {
        pulls_.takeBack(ctx.circles, ctx.magnets, dt,
                        [&](std::size_t i) { return !springs_.empty() && springs_.pathOf(static_cast<int>(i)); });
        for (int i = 0; i < circleCount_; ++i) {
            const Vec2 kick = pulls_.kick(static_cast<std::size_t>(i));
            if (kick == Vec2{}) continue;
            ctx.circles[static_cast<std::size_t>(i)].velocity -= kick;
            held_.setFreeAcceleration(i, ctx.def.gravity + kick / dt);
        }
    }

    // Circle i's motion from now: a spring's closed form, its parabola, or a straight line.
    Trajectory trajectoryOf(const StepContext& ctx, int i, double horizon) const {
        const Circle& c = ctx.circles[static_cast<std::size_t>(i)];
        if (const SpringPath* path = springs_.pathOf(i)) return springTrajectory(*path, c.position, c.velocity);
        const Vec2 a = c.motion == Motion::dynamic ? held_.acceleration(i) : Vec2{};
        return parabolaTrajectory(c.position, c.velocity, a, horizon);
    }

    // Moves every body over t: dynamic ones exactly along their parabola (or spring's closed form),
    // kinematic ones linearly.
    void advance(StepContext& ctx, double t) const {
        if (t <= 0.0) return;
        for (std::size_t i = 0; i < ctx.circles.size(); ++i) {
            Circle& c = ctx.circles[i];
            if (const SpringPath* path = springs_.empty() ? nullptr : springs_.pathOf(static_cast<int>(i))) {
                springMove(*path, c.position, c.velocity, t);
            } else if (c.motion == Motion::dynamic) {
                const Vec2 a = held_.acceleration(i);             // gravity, or what the faces holding it leave of it
                c.position += c.velocity * t + a * (0.5 * t * t); // p + v t + a t^2 / 2
                c.velocity += a * t;
            } else if (c.motion == Motion::kinematic) {
                c.position += c.velocity * t;
            }
        }
        for (Segment& s : ctx.segments) {
            if (s.motion() != Motion::kinematic) continue;
            s.a += s.velocity * t;
            s.b += s.velocity * t;
        }
        if (!ctx.bodies.empty()) advanceBlocks(ctx, t);
    }

    // Resolves one impact at world time `time`; slow approaches are resting contact (C = 0).
    void resolve(StepContext& ctx, const Candidate& hit, double time) {
        if (hit.block.block >= 0) {
            resolveBlock(ctx, hit.block, time);
            return;
        }
        Circle& c = ctx.circles[hit.circle];
        Vec2 otherVelocity;
        double otherInverseMass = 0.0;
        double bounciness = 0.0;
        Circle* dynamicOther = nullptr;
        if (hit.kind == Other::circle) {
            Circle& o = ctx.circles[hit.other];
            otherVelocity = o.velocity;
            otherInverseMass = o.inverseMass;
            bounciness = pairBounciness(c.material, o.material);
            if (o.motion == Motion::dynamic) dynamicOther = &o;
        } else {
            const Segment& s = ctx.segments[hit.other];
            otherVelocity = s.velocityAt(c.position - hit.normal * c.radius); // v + omega x r on a turning segment
            bounciness = pairBounciness(c.material, s.material);
        }
        const double approach = approachSpeed(c.velocity, otherVelocity, hit.normal);
        const bool isResting = approach < ctx.restingSpeed;
        resolveImpact(c.velocity, c.inverseMass, otherVelocity, otherInverseMass, hit.normal,
                      isResting ? 0.0 : bounciness);
        if (dynamicOther) dynamicOther->velocity = otherVelocity;

        // The surfaces touch one radius from the centre, against the normal.
        ctx.impacts.push_back(Impact{hit.circle, hit.kind, hit.other, time, c.position - hit.normal * c.radius,
                                     hit.normal, std::max(approach, 0.0)});
        ++ctx.stats.impacts;
        if (isResting) {
            // Touching with no normal speed under gravity, the pair would be found again at t = 0 for
            // ever: leave it out for the rest of the step and push it apart at the end instead.
            ++ctx.stats.restingContacts;
            std::uint8_t state = kRestingPlus;
            if (hit.kind != Other::circle) {
                const Segment& s = ctx.segments[hit.other];
                if ((s.b - s.a).normal().dot(hit.normal) < 0.0) state = kRestingMinus;
            }
            resting_.set(hit.circle, hit.kind, hit.other, state);
            // A spring-held circle keeps its closed form: a face does not hold it.
            if (hit.kind == Other::segment && ctx.bodies.empty() && !springs_.pathOf(hit.circle))
                held_.hold(ctx, hit.circle, hit.other, hit.normal);
        } else {
            // A real impact may drive a body into what it rests on: search those pairs again.
            searchAgain(hit.circle);
            if (dynamicOther) searchAgain(hit.other);
        }
        if (!springs_.empty()) {
            stillClosedForm(ctx, hit.circle);
            if (dynamicOther) stillClosedForm(ctx, hit.other);
        }
    }

    // The step's start, kept while springs move: an impact that knocks a spring-held circle off its
    // closed form puts everything back before the method throws.
    void keepStart(const StepContext& ctx) {
        circlesAtStart_.assign(ctx.circles.begin(), ctx.circles.end());
        segmentsAtStart_.assign(ctx.segments.begin(), ctx.segments.end());
        impactsAtStart_ = ctx.impacts.size();
        statsAtStart_ = ctx.stats;
    }

    // Throws SpringNotExact (with the step put back) when circle i's spring lost its closed form.
    void stillClosedForm(StepContext& ctx, int i) {
        const std::string why = springs_.recheck(ctx, i);
        if (why.empty()) return;
        std::copy(circlesAtStart_.begin(), circlesAtStart_.end(), ctx.circles.begin());
        std::copy(segmentsAtStart_.begin(), segmentsAtStart_.end(), ctx.segments.begin());
        ctx.impacts.resize(impactsAtStart_);
        ctx.stats = statsAtStart_;
        throw SpringNotExact("method 'exact' cannot follow circle " + std::to_string(i) + " after an impact: " + why,
                             i);
    }

    void searchAgain(int circle) {
        if (!held_.empty()) held_.letGo(circle);
        resting_.forgetCircle(circle);
        if (!blockResting_.empty()) forgetResting(Other::circle, circle);
    }

    // Held face `f` ends: its circle is searched against it again (its cap now) and falls freely.
    void release(int f) {
        const HeldFace held = held_.release(f);
        resting_.forgetSegment(held.circle, held.segment);
    }

    // Leaves out of blockResting_ every pair with this circle (kind circle) or block (kind body).
    void forgetResting(Other kind, int index) {
        std::erase_if(blockResting_, [&](const BlockPair& p) {
            return (p.kind == kind && p.other == index) || (kind == Other::body && p.block == index);
        });
    }

    // A block's impact, as a circle's: slow approaches are resting contact (C = 0), left out of the
    // search for the rest of the step; a real impact makes both bodies' pairs searched again.
    void resolveBlock(StepContext& ctx, const BlockEvent& event, double time) {
        const BlockPartner partner = blockPartner(ctx, event.kind, event.other);
        const double approach = approachSpeed(ctx.bodies[event.block].velocity, partner.velocity, event.normal);
        const bool isResting = approach < ctx.restingSpeed;
        resolveBlockImpact(ctx, event, time, isResting, true);
        if (isResting) {
            ++ctx.stats.restingContacts;
            const Other kind = event.kind == Other::segmentCap ? Other::segment : event.kind;
            blockResting_.push_back(BlockPair{event.block, kind, event.other, event.normal});
            return;
        }
        forgetResting(Other::body, event.block);
        if (event.kind == Other::body) forgetResting(Other::body, event.other);
        if (event.kind == Other::circle && partner.dynamic) searchAgain(event.other);
    }

    int circleCount_ = 0;
    RestingPairs resting_;                ///< pairs left out of the search for the rest of the step
    ExactSettle settle_;                  ///< the end-of-step settle
    std::vector<Vec2> centres_;           ///< the clean-up's side reference after a cap hit
    std::vector<BlockPair> blockResting_; ///< blocks' pairs resting for the rest of the step (few)
    HeldFaces held_;                      ///< circles held on static faces for the rest of the step (few)
    MagnetPulls pulls_;                   ///< the magnets' kicks taken back this step (magnet_pulls.hpp)
    ExactSprings springs_;                ///< circles on springs to fixed points (closed forms)
    std::vector<Circle> circlesAtStart_;  ///< the step's start, while springs move
    std::vector<Segment> segmentsAtStart_;
    std::size_t impactsAtStart_ = 0;
    StepStats statsAtStart_;
};

} // namespace

std::unique_ptr<StepMethod> makeExactMethod() { return std::make_unique<ExactMethod>(); }

} // namespace rube
