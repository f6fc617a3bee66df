// The `solver` time-step method: a substepped sequential-impulse contact solver with soft contacts,
// relax passes and restitution at the end (the "soft step" of Box2D v3), speculative contacts found
// once per step through a uniform grid, and a continuous sweep for circles faster than their margin.
// The class is in solver_method.hpp, finding the step's contacts in solver_find_contacts.cpp.
#include "solver_method.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rube {

namespace {

// The contact tuning, chosen by measuring the 1000-ball pile of tests/solver_test.cpp and 16 variants
// of its spawn jitter (largest overlap in the last second, settling) against the time per step.
/// Stiffness of contacts between dynamic circles. The resting overlap is the load over the spring,
/// F / (m omega^2), so the deepest force chain in a 40-ball pile sets how stiff it must be.
constexpr double kContactHertz = 200.0;
/// Stiffer than this fraction of the substep rate and the pile never comes to rest (Box2D v3 stops
/// at a quarter with one relax pass; three relax passes hold it at 0.42, two at 0.35: at 8 substeps
/// of 60 Hz that caps the contacts at 168 Hz, and two passes at 200 Hz left piles jiggling).
constexpr double kMaxHertzPerSubstepRate = 0.35;
/// Contacts against infinite mass move one body only: twice as stiff is as stable (Box2D v3).
constexpr double kStaticHertzScale = 2.0;
/// Heavily over-damped: overlap is pushed out without bouncing.
constexpr double kDampingRatio = 10.0;
/// m/s: the soft push-out never exceeds this, so deep overlaps resolve gently.
constexpr double kMaxPushSpeed = 3.0;
/// Rigid passes after each substep's position update. Two passes at 168 Hz cost a third less than
/// three at 200 Hz; the worst overlap in the last second over spawn variants of the pile went from
/// 3.2 mm (16 variants) to 3.8 mm (32 variants; limit 5 mm), all settled. One pass needs a quarter of
/// the substep rate (120 Hz), and then the worst pile overlaps 12 mm; two at 0.31 hit 7.9 mm once.
/// With pushing contacts swept first in their group (orderContacts), 96 spawn variants: worst 4.7 mm,
/// mean 3.05 (4.4 and 2.99 in the order before); one still crept at 1.2 cm/s after 10 s (at rest by 12 s).
constexpr int kRelaxIterations = 2;
/// Of those passes, the stacking contacts (RigidContact::stacking: between shapes that no pivot or
/// joint holds) take part in this many; the pivots, the joints and every other contact in all.
/// One pass holds Box2D's 5050-box pyramid (largest move 0.20 m, top box 0.14 m down, with
/// rigid_softness.cpp's 70 Hz stacking contacts) in about 15 % less time a step. A mechanism needs the
/// second: with one, a catapult's paddle (the belt-drive level) threw its ball 4.6 cm further by the
/// top of its arc, past the flag, its pivot and the ball's contact not yet agreeing after the
/// push-out; a hammer's head came 1.7 to 1.9 mm off its handle on striking a ball, where the weld
/// holds it within 1 mm (tests/parts/hammer_test.cpp).
constexpr int kRigidContactRelaxPasses = 1;

} // namespace

void SolverMethod::solve(const StepContext& ctx, double dt) {
    const int substeps = std::max(1, ctx.def.substeps);
    const double h = dt / substeps;
    const double hertz = std::min(kContactHertz, kMaxHertzPerSubstepRate / h);
    const Softness softness[2] = {makeSoftness(hertz, kDampingRatio, h),
                                  makeSoftness(kStaticHertzScale * hertz, kDampingRatio, h)};
    const Vec2 gravityStep = ctx.def.gravity * h;
    gaps_.resize(contacts_.size());
    const int relaxIterations = fastStep_ ? kFastRelaxIterations : kRelaxIterations;
    // Friction is solved with the soft sweep only: the relax passes restore the normal velocities
    // the push-out added, which friction does not depend on (and a third of the cost is saved).
    FrictionState frictionState{frictions_, frictionBodies_, omega_};
    const FrictionState* friction = anyRotation_ ? &frictionState : nullptr;
    if (hasRigid_) rigid_.bind(bodies_, anyRotation_ ? std::span<double>(omega_) : std::span<double>{}, ctx.circles);
    if (!hasRigid_) markWarmContacts();
    takeBackMagnetKicks(ctx, dt);
    for (int k = 0; k < substeps; ++k) {
        for (int i = 0; i < circleCount_; ++i)
            if (isDynamic_[i]) bodies_[i].velocity += gravityStep;
        for (std::size_t i = 0; i < pulls_.size(); ++i) bodies_[i].velocity += pulls_.kick(i) / substeps;
        if (hasRigid_) rigid_.integrateVelocities(gravityStep);
        if (hasRigid_) rigid_.warmStart();
        warmStartContacts(contacts_, bodies_, inverseMass_, friction);
        if (hasRigid_) rigid_.solve(h, true);
        solveContacts(contacts_, records_, bodies_, inverseMass_, softness, h, k, kMaxPushSpeed, friction);
        for (SolverBody& b : bodies_) b.displacement += b.velocity * h;
        for (std::size_t r = 0; r < rotating_.size(); ++r)
            turn_[r] += omega_[static_cast<std::size_t>(rotating_[r])] * h;
        if (hasRigid_) rigid_.integratePositions(h);
        for (int r = 0; r < relaxIterations; ++r) {
            if (hasRigid_) rigid_.solve(h, false, r >= kRigidContactRelaxPasses);
            relaxContacts(contacts_, records_, bodies_, inverseMass_, gaps_, r == 0, h, k);
        }
    }
    if (hasRigid_) rigid_.applyRestitution(ctx.restingSpeed);
    if (!hasRigid_) flyFreeCirclesExactly(ctx, dt);
    if (!pulls_.empty()) restPulledContacts(ctx, dt);
    // Rigid bodies hold circles through their own contacts, which the count of a circle's contacts
    // does not see; bullets are bounced by the continuous pass.
    // A circle a magnet pulls is not carried either: the carried flight knows gravity only.
    if (!hasRigid_)
        carryPastImpact(contacts_, records_, bodies_, ctx.circles, inverseMass_,
                        pulls_.empty() ? std::span<const std::uint8_t>(isBullet_) : notCarried(), circleCount_,
                        ctx.restingSpeed, ctx.def.gravity, dt, h);
    applyRestitution(contacts_, records_, bodies_, inverseMass_, ctx.restingSpeed, gravityStep);
    if (turning_) turningContacts_.detach(contacts_);
    tangentImpulses_.clear();
    if (anyRotation_)
        for (const FrictionTerms& f : frictions_) tangentImpulses_.push_back(f.impulse);
    cache_.store(contacts_, tangentImpulses_, circleCount_, segmentCount_);
}

// A magnet's pull moves a circle as gravity does (magnet_pulls.hpp): its kick is taken back here
// and given a share each substep, so the contact holds the ball as it holds one resting under
// gravity. Asleep circles are not dynamic this step: the kick has woken any it reached.
void SolverMethod::takeBackMagnetKicks(const StepContext& ctx, double dt) {
    pulls_.takeBack(ctx.circles.first(static_cast<std::size_t>(circleCount_)), ctx.magnets, dt,
                    [&](std::size_t i) { return !isDynamic_[i]; });
    for (std::size_t i = 0; i < pulls_.size(); ++i) bodies_[i].velocity -= pulls_.kick(i);
}

// A touch no faster than the pull and gravity give in a step rests (MagnetPulls::restingSpeed, as
// exact's settle has it), or the ball the magnet holds would bounce off it every step.
void SolverMethod::restPulledContacts(const StepContext& ctx, double dt) {
    const auto threshold = [&](int body) {
        return body < circleCount_ ? pulls_.restingSpeed(static_cast<std::size_t>(body), ctx.def.gravity, dt) : 0.0;
    };
    for (std::size_t k = 0; k < contacts_.size(); ++k) {
        ContactRecord& r = records_[k];
        if (r.firstTouch < 0 || r.bounciness == 0.0) continue;
        if (r.approachSpeed <= std::max(threshold(contacts_[k].a), threshold(contacts_[k].b))) r.bounciness = 0.0;
    }
}

void SolverMethod::markWarmContacts() {
    // A contact that starts the step warm (pushing since the last step) may push without ever being
    // marked as touching (ContactRecord::firstTouch): its circles are held, not in flight.
    inContact_.assign(isDynamic_.size(), 0);
    for (const ContactConstraint& c : contacts_) {
        if (c.impulse <= 0.0) continue;
        inContact_[static_cast<std::size_t>(c.a)] = 1;
        if (c.b < circleCount_) inContact_[static_cast<std::size_t>(c.b)] = 1;
    }
}

void SolverMethod::flyFreeCirclesExactly(const StepContext& ctx, double dt) {
    // The substeps' semi-implicit Euler (v += g h, then x += v h) puts a falling circle at
    // x0 + v0 t + g t (t + h) / 2: half a substep of gravity ahead of the exact parabola. A circle no
    // contact pushed this step (none warm at its start, none touching within it: its speculative
    // contacts only watched) felt nothing but gravity within the step (fields, drag and ropes act
    // between steps, in World; rigid bodies' steps are left alone), so it flies the exact method's
    // free flight instead: x1 = x0 + v0 dt + g dt^2 / 2, v1 = v0 + g dt. Its flight then starts every
    // bounce from the state as given, as the exact method's does. The substeps' path lies below the
    // exact one by g t h / 2, so a floor it did not touch the exact path does not touch either.
    for (std::size_t k = 0; k < contacts_.size(); ++k) {
        if (records_[k].firstTouch < 0) continue;
        const ContactConstraint& c = contacts_[k];
        inContact_[static_cast<std::size_t>(c.a)] = 1;
        if (c.b < circleCount_) inContact_[static_cast<std::size_t>(c.b)] = 1;
    }
    const Vec2 g = ctx.def.gravity;
    for (int i = 0; i < circleCount_; ++i) {
        if (!isDynamic_[i] || inContact_[static_cast<std::size_t>(i)]) continue;
        const Vec2 v0 = ctx.circles[static_cast<std::size_t>(i)].velocity;
        const Vec2 pull = pulls_.kick(static_cast<std::size_t>(i));
        if (pull == Vec2{}) {
            bodies_[i] = {v0 + g * dt, v0 * dt + g * (0.5 * dt * dt)};
            continue;
        }
        // Pulled by a magnet: v0 less its kick, then g and the pull a = kick / dt as one acceleration.
        const Vec2 u = v0 - pull;
        bodies_[i] = {u + g * dt + pull, u * dt + (g * dt + pull) * (0.5 * dt)};
    }
}

void SolverMethod::finish(StepContext& ctx, double dt) {
    for (int i = 0; i < circleCount_; ++i) {
        Circle& c = ctx.circles[i];
        if (isDynamic_[i]) {
            c.position = start_[i] + bodies_[i].displacement;
            c.velocity = bodies_[i].velocity;
        } else if (c.motion == Motion::kinematic) {
            c.position = start_[i] + c.velocity * dt; // straight along this step's velocity
        }
    }
    pulls_.finish(ctx.circles, ctx.magnets, dt);
    if (hasRigid_) rigid_.finish(ctx);
    for (std::size_t r = 0; r < rotating_.size(); ++r) {
        Circle& c = ctx.circles[static_cast<std::size_t>(rotating_[r])];
        c.angularVelocity = omega_[static_cast<std::size_t>(rotating_[r])];
        c.angle += turn_[r];
    }
    const std::size_t firstImpact = ctx.impacts.size();
    // The sweep sees segments at their start, moving with their velocity over the step.
    inFlight_.assign(isDynamic_.begin(), isDynamic_.end());
    if (hasRigid_)
        std::fill(inFlight_.begin(), inFlight_.end(), std::uint8_t{0}); // boxes' contacts are not listed here
    for (std::size_t k = 0; k < contacts_.size(); ++k) {
        const ContactConstraint& c = contacts_[k];
        if (c.impulse <= 0.0 && records_[k].firstTouch < 0) continue;
        inFlight_[static_cast<std::size_t>(c.a)] = 0;
        if (c.b < circleCount_) inFlight_[static_cast<std::size_t>(c.b)] = 0;
    }
    const SweepInput sweepInput{
        start_, margins_, bullets_, isBullet_, isDynamic_, cache_, inFlight_, kMaxSweepCellsPerAxis, connected_};
    int impacts = sweep_.run(sweepInput, grid_, ctx, dt);
    if (hasRigid_) impacts += rigid_.sweep(ctx, dt);
    for (Segment& seg : ctx.segments) {
        if (seg.motion() != Motion::kinematic) continue;
        seg.a += seg.velocity * dt;
        seg.b += seg.velocity * dt;
    }
    impacts += recordContactImpacts(contacts_, records_, ctx.circles, ctx);
    if (hasRigid_) impacts += rigid_.recordImpacts(ctx);
    // Report in time order; ties by circle and other body, so the order never depends on the sort.
    std::sort(ctx.impacts.begin() + static_cast<std::ptrdiff_t>(firstImpact), ctx.impacts.end(),
              [](const Impact& a, const Impact& b) {
                  if (a.time != b.time) return a.time < b.time;
                  if (a.circle != b.circle) return a.circle < b.circle;
                  if (a.otherKind != b.otherKind) return a.otherKind < b.otherKind;
                  if (a.other != b.other) return a.other < b.other;
                  return a.body < b.body;
              });
    ctx.stats.maxEventsInStep = std::max(ctx.stats.maxEventsInStep, impacts);
    if (ctx.sleep)
        sleep_.update(ctx.circles, ctx.segments, contacts_, dt, ctx.def.sleepSpeed, ctx.def.timeToSleep,
                      ctx.def.gravity, rigidSleep(ctx));
}

std::unique_ptr<StepMethod> makeSolverMethod() { return std::make_unique<SolverMethod>(); }

} // namespace rube
