// Sleeping islands for the solver: who wakes before a step, who falls asleep after it.
#include "solver_sleep.hpp"

#include <algorithm>
#include <cmath>

namespace rube {

namespace {

/// m/s^2: a slow circle is held when what gravity pushes it with, less what its contacts can cancel,
/// is under this. Left asleep it would have slid under 0.5 mm in 10 s; a frictionless ball on a line
/// tilted 0.01 degree is pushed 1.7e-3 m/s^2 along it and keeps sliding.
constexpr double kUnheldAcceleration = 1e-5;

/// Per circle in update: not an awake dynamic circle, awake but not slow for long enough, or ready to sleep.
enum : std::uint8_t { other, awake, ready };

void wake(Circle& c) { c.sleep = SleepState{}; }

bool movingKinematic(const Circle& c) { return c.motion == Motion::kinematic && c.velocity != Vec2{}; }

bool movingKinematic(const Segment& s) {
    return s.motion() == Motion::kinematic && (s.velocity != Vec2{} || s.angularVelocity != 0.0);
}

} // namespace

void wakeAll(std::span<Circle> circles) {
    for (Circle& c : circles)
        if (c.sleep.asleep) wake(c);
}

bool SleepIslands::wakeReached(std::span<Circle> circles, std::span<const Segment> segments,
                               std::span<const CandidatePair> pairs, std::span<const double> margins,
                               std::span<const BoundingBox> circleBoxes, std::span<const BoundingBox> segmentBoxes,
                               std::span<const BoundingBox> bulletPaths) {
    const int circleCount = static_cast<int>(circles.size());
    asleep_.clear();
    for (int i = 0; i < circleCount; ++i)
        if (circles[static_cast<std::size_t>(i)].sleep.asleep) asleep_.push_back(i);
    if (asleep_.empty()) return false;
    // Reached islands are marked first and woken in one pass at the end, so waking many islands
    // costs one pass over the sleepers, not one per island.
    islandReached_.assign(static_cast<std::size_t>(circleCount), 0);
    const auto reach = [&](int i) {
        islandReached_[static_cast<std::size_t>(circles[static_cast<std::size_t>(i)].sleep.island)] = 1;
    };
    // Pushed from outside: a sleeper's velocity and spin are exactly zero until something sets them.
    for (const int i : asleep_) {
        const Circle& c = circles[static_cast<std::size_t>(i)];
        if (c.velocity != Vec2{} || c.angularVelocity != 0.0) reach(i);
    }
    // Pairs are (awake dynamic circle, other): an asleep other is reached when the pair would become
    // a contact, its gap within both margins (as islands are joined over every contact, below).
    for (const CandidatePair& p : pairs) {
        if (p.other >= circleCount || !circles[static_cast<std::size_t>(p.other)].sleep.asleep) continue;
        const Circle& a = circles[static_cast<std::size_t>(p.circle)];
        const Circle& b = circles[static_cast<std::size_t>(p.other)];
        const double reachBoth = a.radius + b.radius + margins[static_cast<std::size_t>(p.circle)] +
                                 margins[static_cast<std::size_t>(p.other)];
        if ((a.position - b.position).lengthSquared() < reachBoth * reachBoth) reach(p.other);
    }
    // Bullets are filed where they start, kinematic bodies are never the dynamic side of a pair: both
    // are checked against the sleepers' boxes directly (there are few of them).
    const auto reachBox = [&](const BoundingBox& box) {
        for (const int i : asleep_)
            if (circleBoxes[static_cast<std::size_t>(i)].overlaps(box)) reach(i);
    };
    for (const BoundingBox& path : bulletPaths) reachBox(path);
    for (std::size_t s = 0; s < segments.size(); ++s)
        if (movingKinematic(segments[s])) reachBox(segmentBoxes[s]);
    for (int i = 0; i < circleCount; ++i)
        if (movingKinematic(circles[static_cast<std::size_t>(i)])) reachBox(circleBoxes[static_cast<std::size_t>(i)]);
    bool woke = false;
    for (const int i : asleep_) {
        Circle& c = circles[static_cast<std::size_t>(i)];
        if (!islandReached_[static_cast<std::size_t>(c.sleep.island)]) continue;
        wake(c);
        woke = true;
    }
    return woke;
}

int SleepIslands::find(int i) {
    while (parent_[static_cast<std::size_t>(i)] != i) {
        // Path halving: every other node on the way points to its grandparent.
        parent_[static_cast<std::size_t>(i)] = parent_[static_cast<std::size_t>(parent_[static_cast<std::size_t>(i)])];
        i = parent_[static_cast<std::size_t>(i)];
    }
    return i;
}

void SleepIslands::HoldRays::offer(Vec2 up, Vec2 ray) {
    const double d = up.dot(ray);
    if (up.cross(ray) >= 0.0) {
        if (d > leftDot) left = ray, leftDot = d;
    } else if (d > rightDot) {
        right = ray, rightDot = d;
    }
}

bool SleepIslands::HoldRays::holds(Vec2 up, double push) const {
    // Up lies between the nearest rays on either side when the turn from right to left is at most
    // half a turn: then the contacts can push straight up, and cancel gravity with no remainder.
    if (leftDot > -2.0 && rightDot > -2.0 && right.cross(left) >= 0.0) return true;
    // Otherwise the remainder is gravity's component across the nearest ray, |g| sin(angle), when
    // that ray leans less than a right angle from up (past it, nothing of gravity is cancelled).
    const bool leftNearer = leftDot >= rightDot;
    const double d = leftNearer ? leftDot : rightDot;
    return d > 0.0 && push * std::abs(up.cross(leftNearer ? left : right)) <= kUnheldAcceleration;
}

void SleepIslands::demoteUnheld(std::span<const Circle> circles, std::span<const Segment> segments,
                                std::span<const ContactConstraint> contacts, Vec2 gravity) {
    const double push = gravity.length();
    if (push <= kUnheldAcceleration) return; // nothing pushes: whatever is slow is held
    const Vec2 up = -gravity / push;
    const std::size_t circleCount = circles.size();
    normalRays_.assign(circleCount, HoldRays{});
    coneRays_.assign(circleCount, HoldRays{});
    holding_.assign(circleCount, 0);
    // A contact can push when it pushed in the last substep or started the step overlapping. Its
    // normal pushes along n; with friction mu it can push anywhere within atan(mu) of n (Coulomb's cone).
    const auto offer = [&](int i, Vec2 n, double mu) {
        if (state_[static_cast<std::size_t>(i)] != ready) return;
        ++holding_[static_cast<std::size_t>(i)];
        normalRays_[static_cast<std::size_t>(i)].offer(up, n);
        HoldRays& cone = coneRays_[static_cast<std::size_t>(i)];
        if (mu <= 0.0) return cone.offer(up, n);
        const Vec2 t = n.perpendicular() * mu;
        const double scale = 1.0 / std::sqrt(1.0 + mu * mu);
        cone.offer(up, (n + t) * scale);
        cone.offer(up, (n - t) * scale);
    };
    const int firstSegment = static_cast<int>(circleCount); // solver bodies: circles, then segments
    for (const ContactConstraint& c : contacts) {
        if (!(c.impulse > 0.0 || c.baseSeparation <= 0.0)) continue;
        const Circle& a = circles[static_cast<std::size_t>(c.a)];
        const bool otherIsCircle = c.b < firstSegment;
        const double otherFriction = otherIsCircle
                                         ? circles[static_cast<std::size_t>(c.b)].material.friction
                                         : segments[static_cast<std::size_t>(c.b - firstSegment)].material.friction;
        const double mu = a.material.friction * otherFriction; // the pair's friction, as the solver's
        offer(c.a, c.normal, mu);
        if (otherIsCircle) offer(c.b, -c.normal, mu);
    }
    // A circle on one contact rolls: friction there turns it rather than holding it (the contact force
    // must pass through the centre for the torque to vanish), so friction cones count from two
    // contacts on, or for a circle that cannot turn.
    for (std::size_t i = 0; i < circleCount; ++i) {
        if (state_[i] != ready) continue;
        const bool coneHolds = holding_[i] >= 2 || circles[i].inverseInertia == 0.0;
        if (normalRays_[i].holds(up, push) || (coneHolds && coneRays_[i].holds(up, push))) continue;
        state_[i] = awake;
    }
}

void SleepIslands::update(std::span<Circle> circles, std::span<const Segment> segments,
                          std::span<const ContactConstraint> contacts, double dt, double sleepSpeed, double timeToSleep,
                          Vec2 gravity) {
    const int circleCount = static_cast<int>(circles.size());
    const double limit2 = sleepSpeed * sleepSpeed;
    state_.assign(static_cast<std::size_t>(circleCount), other);
    // Per awake dynamic circle: slow, or slow but spinning (its surface's speed about the centre over
    // sleep_speed), or neither. A spin counts only where it can act: through a pushing contact with
    // friction. Spinning in place on a frictionless floor, a ball touches nothing its spin could turn
    // or be stopped by; sleeping stops that spin, as it would stop any other motion under sleep_speed.
    enum : std::uint8_t { moving, slow, spinning };
    slowness_.assign(static_cast<std::size_t>(circleCount), moving);
    bool anySpinning = false;
    for (int i = 0; i < circleCount; ++i) {
        const Circle& c = circles[static_cast<std::size_t>(i)];
        if (c.motion != Motion::dynamic || c.inverseMass <= 0.0 || c.sleep.asleep) continue;
        const double spin = c.angularVelocity * c.radius;
        if (!(c.velocity.lengthSquared() < limit2)) continue;
        const bool spins = !(spin * spin < limit2);
        slowness_[static_cast<std::size_t>(i)] = spins ? spinning : slow;
        anySpinning = anySpinning || spins;
    }
    if (anySpinning) {
        const int firstSegment = circleCount; // solver bodies: circles, then segments
        const auto grip = [&](int i) {
            std::uint8_t& s = slowness_[static_cast<std::size_t>(i)];
            if (s == spinning) s = moving;
        };
        for (const ContactConstraint& c : contacts) {
            if (!(c.impulse > 0.0 || c.baseSeparation <= 0.0)) continue;
            const double otherFriction = c.b < firstSegment
                                             ? circles[static_cast<std::size_t>(c.b)].material.friction
                                             : segments[static_cast<std::size_t>(c.b - firstSegment)].material.friction;
            if (circles[static_cast<std::size_t>(c.a)].material.friction * otherFriction <= 0.0) continue;
            grip(c.a);
            if (c.b < firstSegment) grip(c.b);
        }
    }
    int readyCount = 0;
    for (int i = 0; i < circleCount; ++i) {
        Circle& c = circles[static_cast<std::size_t>(i)];
        if (c.motion != Motion::dynamic || c.inverseMass <= 0.0 || c.sleep.asleep) continue;
        c.sleep.slowFor = slowness_[static_cast<std::size_t>(i)] != moving ? c.sleep.slowFor + dt : 0.0;
        const bool isReady = c.sleep.slowFor >= timeToSleep;
        state_[static_cast<std::size_t>(i)] = isReady ? ready : awake;
        readyCount += isReady;
    }
    // Model no more than the scene needs: islands are only built once some circle could sleep.
    if (readyCount == 0) return;
    // Slow but not held (sliding down a shallow incline): awake, and its island with it.
    demoteUnheld(circles, segments, contacts, gravity);
    // An island sleeps when every member is ready and none is carried. So only ready circles are
    // joined; a ready circle touching an awake one, or pushed by a moving kinematic body, blocks its
    // whole island instead. Every contact counts, speculative ones too: a neighbour close enough to be
    // one would wake the island straight away (wakeReached), so it must sleep with it or not at all.
    parent_.resize(static_cast<std::size_t>(circleCount));
    for (int i = 0; i < circleCount; ++i) parent_[static_cast<std::size_t>(i)] = i;
    blocked_.assign(static_cast<std::size_t>(circleCount), 0);
    const auto block = [&](int i) { blocked_[static_cast<std::size_t>(i)] = 1; }; // folded into its root below
    for (const ContactConstraint& c : contacts) {
        const std::uint8_t a = state_[static_cast<std::size_t>(c.a)];
        if (a == other) continue;
        if (c.b < circleCount) {
            const std::uint8_t b = state_[static_cast<std::size_t>(c.b)];
            if (a == ready && b == ready) parent_[static_cast<std::size_t>(find(c.a))] = find(c.b);
            else if (a == ready && b == awake) block(c.a);
            else if (a == awake && b == ready) block(c.b);
            else if (a == ready && b == other && c.impulse > 0.0 &&
                     movingKinematic(circles[static_cast<std::size_t>(c.b)]))
                block(c.a);
        } else if (a == ready && c.impulse > 0.0 &&
                   movingKinematic(segments[static_cast<std::size_t>(c.b - circleCount)])) {
            block(c.a);
        }
    }
    for (int i = 0; i < circleCount; ++i)
        if (blocked_[static_cast<std::size_t>(i)]) blocked_[static_cast<std::size_t>(find(i))] = 1;
    for (int i = 0; i < circleCount; ++i) {
        if (state_[static_cast<std::size_t>(i)] != ready) continue;
        const int root = find(i);
        if (blocked_[static_cast<std::size_t>(root)]) continue;
        Circle& c = circles[static_cast<std::size_t>(i)];
        c.velocity = {};
        c.angularVelocity = 0.0;
        c.sleep.asleep = true;
        c.sleep.island = root;
    }
}

} // namespace rube
