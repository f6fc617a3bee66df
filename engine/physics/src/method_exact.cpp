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
#include "exact_spring_impacts.hpp"
#include "kinematic_pose.hpp"
#include "resolve.hpp"
#include "step_method.hpp"

#include "rube/physics/time_of_impact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace rube {
namespace {

// Passes over the contacts at the end of a step. Ordered from the ground up, one pass settles a
// stack; more are needed only where a body rests on two others. Stops once nothing overlaps more
// than kSettledDepth.
constexpr int kSettlePasses = 16;
constexpr double kSettledDepth = 1e-12;

// A pair's state: searched, or resting for the rest of the step (and, for a segment, on which
// side of its line the circle rests). Only resting pairs are stored (restingOf_).
enum PairState : std::uint8_t { kSearched = 0, kRestingPlus = 1, kRestingMinus = 2 };

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

// A pair resting for the rest of the step, in one circle's list: the other circle's index, or
// circleCount_ + a segment's; and its PairState.
struct RestingPair {
    int column = 0;
    std::uint8_t state = kSearched;
};

// A pair touching (or nearly) at the end of a step, to be settled; `side` is a segment face's side.
struct Contact {
    int circle = -1;
    Other kind = Other::circle;
    int other = -1;
    Vec2 side;
    int support = 0; ///< +1: the other holds the circle up against gravity; -1: the reverse; 0: side by side
};

// A contact supports when its normal has a real component against gravity; a vertical wall does not
// (with its normal off horizontal only by rounding).
constexpr double kSupportSine = 1e-6;

class ExactMethod final : public StepMethod {
public:
    void step(StepContext& ctx, double dt) override {
        circleCount_ = static_cast<int>(ctx.circles.size());
        dt_ = dt;
        // Memory O(n + resting pairs): a table of every pair's state was n x (n + segments) bytes,
        // 10 GB for 100,000 circles, and clearing it cost O(n^2) every step.
        restingOf_.resize(ctx.circles.size());
        for (std::vector<RestingPair>& list : restingOf_) list.clear(); // capacity kept: no allocation once grown
        blockResting_.clear();
        held_.reset(ctx.circles.size(), ctx.def.gravity);
        // Throws, before anything moved, when a joint has no closed form (exact_springs.hpp).
        springs_.build(ctx);
        if (!springs_.empty()) keepStart(ctx);

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
        settleContacts(ctx, dt);
        ctx.stats.maxEventsInStep = std::max(ctx.stats.maxEventsInStep, events);
    }

private:
    // Whether the pair rests for the rest of the step.
    bool resting(int circle, Other kind, int other) const { return pairState(circle, kind, other) != kSearched; }
    // A pair's column in a circle's list: the other circle's index, or circleCount_ + a segment's.
    int columnOf(Other kind, int other) const { return kind == Other::circle ? other : circleCount_ + other; }
    std::uint8_t pairState(int circle, Other kind, int other) const {
        // A circle rests on a handful of others at most: a short scan beats hashing.
        const int column = columnOf(kind, other);
        for (const RestingPair& pair : restingOf_[static_cast<std::size_t>(circle)])
            if (pair.column == column) return pair.state;
        return kSearched;
    }
    // Records the pair in the circle's list and, for two circles, in the other's too.
    void setResting(int circle, Other kind, int other, std::uint8_t state) {
        const auto mark = [&](int owner, int column) {
            std::vector<RestingPair>& list = restingOf_[static_cast<std::size_t>(owner)];
            for (RestingPair& pair : list)
                if (pair.column == column) return void(pair.state = state);
            list.push_back(RestingPair{column, state});
        };
        mark(circle, columnOf(kind, other));
        if (kind == Other::circle) mark(other, circle);
    }

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
                if (j == i || (dynamicOther && j < i) || resting(i, Other::circle, j)) continue;
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
                if (resting(i, Other::segment, k)) continue;
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

    // The settle's resting threshold for a pair: the world's (2 |g| dt + 1e-3 unless set), or as much
    // for the acceleration a spring gives a circle of the pair, |omega^2 (p - x_eq) + 2 zeta omega v|,
    // which may be far above g: a spring-held ball resting on the floor (its pair left out of the
    // search) sinks |a| dt^2 / 2 within the step and must be settled at rest, not bounced off with the
    // speed the spring gave it. Impacts within the step keep the world's: they are real approaches.
    double restingSpeedOf(const StepContext& ctx, int i, int j) const {
        if (springs_.empty()) return ctx.restingSpeed;
        double speed = ctx.restingSpeed;
        for (const int k : {i, j}) {
            const SpringPath* path = k >= 0 ? springs_.pathOf(k) : nullptr;
            if (!path) continue;
            const Circle& c = ctx.circles[static_cast<std::size_t>(k)];
            const Vec2 a = (c.position - path->equilibrium) * (path->omega * path->omega) +
                           c.velocity * (2.0 * path->zeta * path->omega);
            speed = std::max(speed, 2.0 * a.length() * dt_ + 1e-3);
        }
        return speed;
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
            setResting(hit.circle, hit.kind, hit.other, state);
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
        // Every resting pair with this circle: its own list, and its entry in each resting partner's.
        std::vector<RestingPair>& list = restingOf_[static_cast<std::size_t>(circle)];
        for (const RestingPair& pair : list)
            if (pair.column < circleCount_)
                std::erase_if(restingOf_[static_cast<std::size_t>(pair.column)],
                              [&](const RestingPair& back) { return back.column == circle; });
        list.clear();
        if (!blockResting_.empty()) forgetResting(Other::circle, circle);
    }

    // Held face `f` ends: its circle is searched against it again (its cap now) and falls freely.
    void release(int f) {
        const HeldFace held = held_.release(f);
        const int column = columnOf(Other::segment, held.segment);
        std::erase_if(restingOf_[static_cast<std::size_t>(held.circle)],
                      [&](const RestingPair& p) { return p.column == column; });
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

    // Resting bodies fell into what they rest on for the rest of the step (g t^2 / 2, a millimetre
    // or so): push every touching pair back out and remove its approaching normal velocity, so
    // resting never sinks. Pairs go from the ground up and the body nearer the ground counts as
    // infinite mass against one above it (shock propagation): one pass settles a whole stack.
    void settleContacts(StepContext& ctx, double dt) {
        collectContacts(ctx, ctx.restingSpeed * dt);
        if (!ctx.bodies.empty()) settleBlockContacts(ctx, ctx.restingSpeed * dt, blockResting_);
        if (contacts_.empty()) return;
        orderFromTheGroundUp(ctx);
        for (int pass = 0; pass < kSettlePasses; ++pass) {
            double deepest = 0.0;
            for (const Contact& contact : contacts_) deepest = std::max(deepest, settle(ctx, contact));
            if (deepest <= kSettledDepth) break;
        }
    }

    // Every pair closer than `slop` (what a resting approach covers in a step): the settle may push
    // a body into a neighbour it was only touching, as a stack's lowest ball into the one above it.
    void collectContacts(const StepContext& ctx, double slop) {
        contacts_.clear();
        for (int i = 0; i < circleCount_; ++i) {
            const Circle& c = ctx.circles[i];
            if (c.motion != Motion::dynamic) continue;
            for (int j = 0; j < circleCount_; ++j) {
                const Circle& o = ctx.circles[j];
                if (j == i || (o.motion == Motion::dynamic && j < i)) continue;
                if (circleCircleOverlap(c.position, c.radius + slop, o.position, o.radius))
                    contacts_.push_back(Contact{i, Other::circle, j, {}});
            }
            for (int k = 0; k < static_cast<int>(ctx.segments.size()); ++k) {
                const Segment& s = ctx.segments[k];
                // A resting circle keeps the side it came from, even if its centre sank past the line.
                const std::uint8_t state = pairState(i, Other::segment, k);
                const Vec2 lineNormal = (s.b - s.a).normal();
                const Vec2 side = state == kRestingPlus    ? lineNormal
                                  : state == kRestingMinus ? -lineNormal
                                                           : segmentSide(s, c.position);
                if (circleSegmentOverlapOnSide(c.position, c.radius + slop, s, side))
                    contacts_.push_back(Contact{i, Other::segment, k, side});
            }
        }
    }

    // Level 0: held up by something of infinite mass; level n + 1: held up by a body of level n.
    // Only contacts against gravity count: a ball squeezed between two walls is not on the ground,
    // and two infinite masses pushing one body from both sides would never settle.
    void orderFromTheGroundUp(const StepContext& ctx) {
        constexpr int kFloating = std::numeric_limits<int>::max();
        const Vec2 down = ctx.def.gravity.normalized();
        levels_.assign(ctx.circles.size(), kFloating);
        for (Contact& contact : contacts_) {
            const Circle& c = ctx.circles[contact.circle];
            const Vec2 below = contact.kind == Other::circle
                                   ? ctx.circles[contact.other].position
                                   : closestPointOnSegment(c.position, ctx.segments[contact.other].a,
                                                           ctx.segments[contact.other].b);
            const Vec2 up = (c.position - below).normalized(); // from the other towards the circle
            const double along = up.dot(down);
            contact.support = along < -kSupportSine ? 1 : along > kSupportSine ? -1 : 0;
            const bool ground = contact.kind != Other::circle || ctx.circles[contact.other].motion != Motion::dynamic;
            if (ground && contact.support > 0) levels_[contact.circle] = 0;
        }
        // Bellman-Ford over the contacts: one round per level of the tallest stack.
        for (bool changed = true; changed;) {
            changed = false;
            for (const Contact& contact : contacts_) {
                if (contact.kind != Other::circle || ctx.circles[contact.other].motion != Motion::dynamic) continue;
                int& lower = contact.support > 0 ? levels_[contact.other] : levels_[contact.circle];
                int& upper = contact.support > 0 ? levels_[contact.circle] : levels_[contact.other];
                if (contact.support != 0 && lower != kFloating && lower + 1 < upper) upper = lower + 1, changed = true;
            }
        }
        // Lower pairs first; ties in index order, so the order is the same on every run.
        const auto key = [&](const Contact& c) {
            const bool dynamicOther = c.kind == Other::circle && ctx.circles[c.other].motion == Motion::dynamic;
            const int lower = dynamicOther ? std::min(levels_[c.circle], levels_[c.other]) : -1;
            return std::make_tuple(lower, c.circle, static_cast<int>(c.kind), c.other);
        };
        std::sort(contacts_.begin(), contacts_.end(),
                  [&](const Contact& x, const Contact& y) { return key(x) < key(y); });
    }

    // Pushes one contact apart and stops a resting approach (C = 0); returns the overlap removed.
    double settle(StepContext& ctx, const Contact& contact) const {
        Circle& c = ctx.circles[contact.circle];
        std::optional<Overlap> overlap;
        Vec2 otherPosition, otherVelocity;
        double inverseMassC = c.inverseMass, inverseMassO = 0.0, bounciness = 0.0;
        Circle* dynamicOther = nullptr;
        if (contact.kind == Other::circle) {
            Circle& o = ctx.circles[contact.other];
            overlap = circleCircleOverlap(c.position, c.radius, o.position, o.radius);
            otherPosition = o.position;
            otherVelocity = o.velocity;
            inverseMassO = o.inverseMass;
            bounciness = pairBounciness(c.material, o.material);
            if (o.motion == Motion::dynamic) dynamicOther = &o;
        } else {
            const Segment& s = ctx.segments[contact.other];
            const auto hit = circleSegmentOverlapOnSide(c.position, c.radius, s, contact.side);
            if (hit) overlap = hit->overlap;
            otherVelocity = hit ? s.velocityAt(hit->overlap.point) : s.velocity;
            bounciness = pairBounciness(c.material, s.material);
        }
        if (!overlap) return 0.0;
        const bool isResting = approachSpeed(c.velocity, otherVelocity, overlap->normal) <
                               restingSpeedOf(ctx, contact.circle, dynamicOther ? contact.other : -1);
        if (dynamicOther && isResting) {
            // The body holding the other up, nearer the ground, holds still as if of infinite mass.
            const int levelC = levels_[contact.circle], levelO = levels_[contact.other];
            if (contact.support < 0 && levelC < levelO) inverseMassC = 0.0;
            if (contact.support > 0 && levelO < levelC) inverseMassO = 0.0;
        }
        pushApart(c.position, inverseMassC, otherPosition, inverseMassO, overlap->normal, overlap->depth);
        resolveImpact(c.velocity, inverseMassC, otherVelocity, inverseMassO, overlap->normal,
                      isResting ? 0.0 : bounciness);
        if (dynamicOther) {
            dynamicOther->position = otherPosition;
            dynamicOther->velocity = otherVelocity;
        }
        return overlap->depth;
    }

    int circleCount_ = 0;
    double dt_ = 0.0;                                 ///< the step's length (spring-held circles' resting threshold)
    std::vector<std::vector<RestingPair>> restingOf_; ///< per circle: the pairs it rests in for the rest of the step
    std::vector<Contact> contacts_;                   ///< the end-of-step settle's pairs
    std::vector<int> levels_;                         ///< per circle: contacts between it and the ground
    std::vector<Vec2> centres_;                       ///< the clean-up's side reference after a cap hit
    std::vector<BlockPair> blockResting_;             ///< blocks' pairs resting for the rest of the step (few)
    HeldFaces held_;                                  ///< circles held on static faces for the rest of the step (few)
    ExactSprings springs_;                            ///< circles on springs to fixed points (closed forms)
    std::vector<Circle> circlesAtStart_;              ///< the step's start, while springs move
    std::vector<Segment> segmentsAtStart_;
    std::size_t impactsAtStart_ = 0;
    StepStats statsAtStart_;
};

} // namespace

std::unique_ptr<StepMethod> makeExactMethod() { return std::make_unique<ExactMethod>(); }

} // namespace rube
