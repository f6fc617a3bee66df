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

void wake(Circle& c) { c.sleep = SleepState{}; }

bool movingKinematic(const Circle& c) { return c.motion == Motion::kinematic && c.velocity != Vec2{}; }

bool movingKinematic(const Segment& s) {
    return s.motion() == Motion::kinematic && (s.velocity != Vec2{} || s.angularVelocity != 0.0);
}

bool movingKinematic(const RigidBody& b) {
    return b.motion == Motion::kinematic && (b.velocity != Vec2{} || b.angularVelocity != 0.0);
}

bool dynamicBody(const RigidBody& b) { return b.motion == Motion::dynamic && b.inverseMass > 0.0; }

/// A running motor drives its island: it never sleeps. A motor at speed 0 only brakes, and may; so
/// may one stalled at a limit (a glove's piston punched out to the end of its stroke), which only
/// presses into it: it moves nothing until something wakes the island, or a new speed (World::
/// setJointMotor wakes its ends).
bool drives(const Joint& j, bool stalled) { return j.def.motor.on() && j.def.motor.speed != 0.0 && !stalled; }

/// Calls f(node) for each end of joint j that is a circle or rigid body (nodes: circles, then bodies);
/// a gear's ends are those of the two joints it couples (World::joints() slots, as `joints`).
template <class F>
void forEachEnd(std::span<const Joint> joints, const Joint& j, int circleCount, F f) {
    if (j.circleA >= 0) f(j.circleA);
    if (j.bodyA >= 0) f(circleCount + j.bodyA);
    if (j.circleB >= 0) f(j.circleB);
    if (j.bodyB >= 0) f(circleCount + j.bodyB);
    for (const int coupled : {j.jointA, j.jointB})
        if (coupled >= 0 && static_cast<std::size_t>(coupled) < joints.size() &&
            &joints[static_cast<std::size_t>(coupled)] != &j)
            forEachEnd(std::span<const Joint>{}, joints[static_cast<std::size_t>(coupled)], circleCount, f);
}

} // namespace

void wakeAll(std::span<Circle> circles, std::span<RigidBody> bodies) {
    for (Circle& c : circles)
        if (c.sleep.asleep) wake(c);
    for (RigidBody& b : bodies)
        if (b.sleep.asleep) b.sleep = SleepState{};
}

bool SleepIslands::wakeReached(std::span<Circle> circles, std::span<const Segment> segments,
                               std::span<const CandidatePair> pairs, std::span<const double> margins,
                               std::span<const BoundingBox> circleBoxes, std::span<const BoundingBox> segmentBoxes,
                               std::span<const BoundingBox> bulletPaths, const RigidSleepInput& rigid) {
    const int circleCount = static_cast<int>(circles.size());
    const int bodyCount = static_cast<int>(rigid.bodies.size());
    asleep_.clear();
    for (int i = 0; i < circleCount; ++i)
        if (circles[static_cast<std::size_t>(i)].sleep.asleep) asleep_.push_back(i);
    asleepBodies_.clear();
    for (int i = 0; i < bodyCount; ++i)
        if (rigid.bodies[static_cast<std::size_t>(i)].sleep.asleep) asleepBodies_.push_back(i);
    if (asleep_.empty() && asleepBodies_.empty()) return false;
    // Reached islands are marked first and woken in one pass at the end, so waking many islands
    // costs one pass over the sleepers, not one per island. An island is named by a circle's index,
    // or by -1 - a body's when it has no circle.
    islandReached_.assign(static_cast<std::size_t>(circleCount), 0);
    rigidIslandReached_.assign(static_cast<std::size_t>(bodyCount), 0);
    const auto reachIsland = [&](int island) {
        if (island >= 0) islandReached_[static_cast<std::size_t>(island)] = 1;
        else rigidIslandReached_[static_cast<std::size_t>(-1 - island)] = 1;
    };
    const auto reach = [&](int i) { reachIsland(circles[static_cast<std::size_t>(i)].sleep.island); };
    const auto reachBody = [&](int i) { reachIsland(rigid.bodies[static_cast<std::size_t>(i)].sleep.island); };
    const auto islandReached = [&](int island) {
        return island >= 0 ? islandReached_[static_cast<std::size_t>(island)] != 0
                           : rigidIslandReached_[static_cast<std::size_t>(-1 - island)] != 0;
    };
    for (const int i : asleepBodies_) {
        const RigidBody& b = rigid.bodies[static_cast<std::size_t>(i)];
        if (b.velocity != Vec2{} || b.angularVelocity != 0.0) reachBody(i);
    }
    for (const int node : rigid.reached) node >= 0 ? reach(node) : reachBody(-1 - node);
    // A joint from an awake body or a moving one pulls its asleep end (both sleep together otherwise).
    for (const Joint& j : rigid.joints) {
        bool pulls = false, anyAsleep = false;
        forEachEnd(rigid.joints, j, circleCount, [&](int node) {
            if (node < circleCount) {
                const Circle& c = circles[static_cast<std::size_t>(node)];
                anyAsleep = anyAsleep || c.sleep.asleep;
                pulls = pulls || (!c.sleep.asleep && c.motion == Motion::dynamic) || movingKinematic(c);
            } else {
                const RigidBody& b = rigid.bodies[static_cast<std::size_t>(node - circleCount)];
                anyAsleep = anyAsleep || b.sleep.asleep;
                pulls = pulls || (!b.sleep.asleep && dynamicBody(b)) || movingKinematic(b);
            }
        });
        if (!pulls || !anyAsleep) continue;
        forEachEnd(rigid.joints, j, circleCount, [&](int node) {
            if (node < circleCount) {
                if (circles[static_cast<std::size_t>(node)].sleep.asleep) reach(node);
            } else if (rigid.bodies[static_cast<std::size_t>(node - circleCount)].sleep.asleep) {
                reachBody(node - circleCount);
            }
        });
    }
    // A rope from an awake or moving circle pulls its asleep end, as a joint does.
    if (!rigid.ropes.empty()) {
        ropeReached(circles, rigid.ropes, ropeReached_);
        for (const int i : ropeReached_) reach(i);
    }
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
        if (!islandReached(c.sleep.island)) continue;
        wake(c);
        woke = true;
    }
    for (const int i : asleepBodies_) {
        RigidBody& b = rigid.bodies[static_cast<std::size_t>(i)];
        if (!islandReached(b.sleep.island)) continue;
        b.sleep = SleepState{};
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

void SleepIslands::join(int a, int b) {
    const int ra = find(a), rb = find(b);
    if (ra < rb) parent_[static_cast<std::size_t>(rb)] = ra;
    else parent_[static_cast<std::size_t>(ra)] = rb;
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
                                std::span<const ContactConstraint> contacts, Vec2 gravity,
                                const RigidSleepInput& rigid) {
    const double g = gravity.length();
    if (g <= kUnheldAcceleration) return; // nothing pushes: whatever is slow is held
    const Vec2 up = -gravity / g;
    const std::size_t circleCount = circles.size();
    const std::size_t nodeCount = circleCount + rigid.bodies.size();
    normalRays_.assign(nodeCount, HoldRays{});
    coneRays_.assign(nodeCount, HoldRays{});
    holding_.assign(nodeCount, 0);
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
    // A rigid contact's normal runs from A to B: it pushes B along n and A against it, once per point
    // that pushed in the last substep (a box flat on the floor has two).
    const auto node = [&](BodySide side) {
        return side.rigid ? firstSegment + side.index : side.index < firstSegment ? side.index : -1;
    };
    for (const RigidContact& c : rigid.contacts) {
        const int a = node(c.a), b = node(c.b);
        for (int k = 0; k < c.count; ++k) {
            if (!(c.points[k].normalImpulse > 0.0)) continue;
            if (a >= 0) offer(a, -c.normal, c.friction);
            if (b >= 0) offer(b, c.normal, c.friction);
        }
    }
    if (!rigid.ropes.empty()) offerRopeRays(circles, rigid.ropes, up);
    // A circle on one contact rolls: friction there turns it rather than holding it (the contact force
    // must pass through the centre for the torque to vanish), so friction cones count from two
    // contacts on, or for a body that cannot turn. A joint or pivot can pull any way: what it ends on is held.
    for (std::size_t i = 0; i < nodeCount; ++i) {
        if (state_[i] != ready || jointHeld_[i]) continue;
        const bool isCircle = i < circleCount;
        const double inverseInertia = isCircle ? circles[i].inverseInertia
                                               : rigid.bodies[i - circleCount].inverseInertia;
        const double push = isCircle ? g : g * std::abs(rigid.bodies[i - circleCount].gravityScale);
        if (push <= kUnheldAcceleration) continue;
        const bool coneHolds = holding_[i] >= 2 || inverseInertia == 0.0;
        if (normalRays_[i].holds(up, push) || (coneHolds && coneRays_[i].holds(up, push))) continue;
        state_[i] = awake;
    }
}

void SleepIslands::countSlowBodies(const RigidSleepInput& rigid, int circleCount, double dt, double sleepSpeed,
                                   double timeToSleep, int& readyCount) {
    const double limit2 = sleepSpeed * sleepSpeed;
    for (std::size_t i = 0; i < rigid.bodies.size(); ++i) {
        RigidBody& b = rigid.bodies[i];
        if (!dynamicBody(b) || b.sleep.asleep) continue;
        // Slow: the centre and every point's speed about it (omega times the bounding radius).
        const double spin = b.angularVelocity * boundingRadius(b);
        const bool slow = b.velocity.lengthSquared() < limit2 && spin * spin < limit2;
        b.sleep.slowFor = slow ? b.sleep.slowFor + dt : 0.0;
        const bool isReady = b.sleep.slowFor >= timeToSleep;
        state_[static_cast<std::size_t>(circleCount) + i] = isReady ? ready : awake;
        readyCount += isReady;
    }
    // Joints and pivots hold what they end on; a running motor keeps both its ends awake.
    jointHeld_.assign(state_.size(), 0);
    for (const Pivot& p : rigid.pivots)
        if (p.body >= 0) jointHeld_[static_cast<std::size_t>(circleCount + p.body)] = 1;
    for (std::size_t k = 0; k < rigid.joints.size(); ++k) {
        const Joint& j = rigid.joints[k];
        const bool motor = drives(j, k < rigid.stalledMotors.size() && rigid.stalledMotors[k] != 0);
        forEachEnd(rigid.joints, j, circleCount, [&](int node) {
            jointHeld_[static_cast<std::size_t>(node)] = 1;
            std::uint8_t& s = state_[static_cast<std::size_t>(node)];
            if (motor && s == ready) s = awake, --readyCount;
        });
    }
}

void SleepIslands::joinRigid(std::span<const Circle> circles, std::span<const Segment> segments,
                             const RigidSleepInput& rigid) {
    const int circleCount = static_cast<int>(circles.size());
    const auto block = [&](int i) { blocked_[static_cast<std::size_t>(i)] = 1; };
    // What a side is to the islands: a node, or something outside them that may carry it (kinematic).
    const auto node = [&](BodySide side) {
        return side.rigid ? circleCount + side.index : side.index < circleCount ? side.index : -1;
    };
    const auto carries = [&](BodySide side) {
        if (side.rigid) return movingKinematic(rigid.bodies[static_cast<std::size_t>(side.index)]);
        if (side.index < circleCount) return movingKinematic(circles[static_cast<std::size_t>(side.index)]);
        return movingKinematic(segments[static_cast<std::size_t>(side.index - circleCount)]);
    };
    const auto link = [&](int a, int b, bool aCarries, bool bCarries) {
        const std::uint8_t sa = a >= 0 ? state_[static_cast<std::size_t>(a)] : std::uint8_t{other};
        const std::uint8_t sb = b >= 0 ? state_[static_cast<std::size_t>(b)] : std::uint8_t{other};
        if (sa == ready && sb == ready) join(a, b);
        else if (sa == ready && (sb == awake || bCarries)) block(a);
        else if (sb == ready && (sa == awake || aCarries)) block(b);
    };
    for (const RigidContact& c : rigid.contacts) {
        bool pushes = false;
        for (int k = 0; k < c.count; ++k) pushes = pushes || c.points[k].normalImpulse > 0.0;
        link(node(c.a), node(c.b), pushes && carries(c.a), pushes && carries(c.b));
    }
    // A joint ties its ends into one island; one end carried by a moving kinematic body keeps it awake.
    const auto carrier = [&](int circle, int body) {
        return (circle >= 0 && movingKinematic(circles[static_cast<std::size_t>(circle)])) ||
               (body >= 0 && movingKinematic(rigid.bodies[static_cast<std::size_t>(body)]));
    };
    for (const Joint& j : rigid.joints) {
        const bool carried = carrier(j.circleA, j.bodyA) || carrier(j.circleB, j.bodyB);
        int first = -1;
        forEachEnd(rigid.joints, j, circleCount, [&](int n) {
            if (carried && state_[static_cast<std::size_t>(n)] == ready) block(n);
            if (first < 0) first = n;
            else link(first, n, false, false);
        });
    }
}

void SleepIslands::update(std::span<Circle> circles, std::span<const Segment> segments,
                          std::span<const ContactConstraint> contacts, double dt, double sleepSpeed, double timeToSleep,
                          Vec2 gravity, const RigidSleepInput& rigid) {
    const int circleCount = static_cast<int>(circles.size());
    const int nodeCount = circleCount + static_cast<int>(rigid.bodies.size());
    const double limit2 = sleepSpeed * sleepSpeed;
    state_.assign(static_cast<std::size_t>(nodeCount), other);
    // Per awake dynamic circle: slow, or slow but spinning (its surface's speed about the centre over
    // sleep_speed), or neither. A spin counts only where it can act: through a pushing contact with
    // friction. Spinning in place on a frictionless floor, a ball touches nothing its spin could turn
    // or be stopped by; sleeping stops that spin, as it would stop any other motion under sleep_speed.
    enum : std::uint8_t { moving, slow, spinning };
    slowness_.assign(static_cast<std::size_t>(circleCount), moving);
    bool anySpinning = false;
    // A roped circle is as slow as the rope pass will leave it (solver_sleep_ropes.cpp).
    const std::span<const Vec2> velocities = rigid.ropes.empty() ? std::span<const Vec2>{}
                                                                 : ropeVelocities(circles, rigid.ropes);
    for (int i = 0; i < circleCount; ++i) {
        const Circle& c = circles[static_cast<std::size_t>(i)];
        if (c.motion != Motion::dynamic || c.inverseMass <= 0.0 || c.sleep.asleep) continue;
        const double spin = c.angularVelocity * c.radius;
        const Vec2 v = velocities.empty() ? c.velocity : velocities[static_cast<std::size_t>(i)];
        if (!(v.lengthSquared() < limit2)) continue;
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
        // A spinning circle a joint ends on is a wheel on its axle: its spin is motion the joint can
        // pass on (a gear, a belt, a weld), and nothing but friction stops it, so it counts.
        for (const Joint& j : rigid.joints)
            forEachEnd(rigid.joints, j, circleCount, [&](int node) {
                if (node < circleCount) grip(node);
            });
        // A spinning circle pressed with friction against a rigid body turns it, or is turned by it.
        for (const RigidContact& c : rigid.contacts) {
            if (c.friction <= 0.0) continue;
            bool pushes = false;
            for (int k = 0; k < c.count; ++k) pushes = pushes || c.points[k].normalImpulse > 0.0;
            if (!pushes) continue;
            if (!c.a.rigid && c.a.index < circleCount) grip(c.a.index);
            if (!c.b.rigid && c.b.index < circleCount) grip(c.b.index);
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
    countSlowBodies(rigid, circleCount, dt, sleepSpeed, timeToSleep, readyCount);
    // Model no more than the scene needs: islands are only built once some body could sleep.
    if (readyCount == 0) return;
    // Slow but not held (sliding down a shallow incline): awake, and its island with it.
    demoteUnheld(circles, segments, contacts, gravity, rigid);
    // An island sleeps when every member is ready and none is carried. So only ready nodes are
    // joined; a ready node touching an awake one, or pushed by a moving kinematic body, blocks its
    // whole island instead. Every contact counts, speculative ones too: a neighbour close enough to be
    // one would wake the island straight away (wakeReached), so it must sleep with it or not at all.
    parent_.resize(static_cast<std::size_t>(nodeCount));
    for (int i = 0; i < nodeCount; ++i) parent_[static_cast<std::size_t>(i)] = i;
    blocked_.assign(static_cast<std::size_t>(nodeCount), 0);
    const auto block = [&](int i) { blocked_[static_cast<std::size_t>(i)] = 1; }; // folded into its root below
    for (const ContactConstraint& c : contacts) {
        const std::uint8_t a = state_[static_cast<std::size_t>(c.a)];
        if (a == other) continue;
        if (c.b < circleCount) {
            const std::uint8_t b = state_[static_cast<std::size_t>(c.b)];
            if (a == ready && b == ready) join(c.a, c.b);
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
    if (!rigid.bodies.empty() || !rigid.joints.empty()) joinRigid(circles, segments, rigid);
    if (!rigid.ropes.empty()) joinRopes(circles, rigid.ropes);
    for (int i = 0; i < nodeCount; ++i)
        if (blocked_[static_cast<std::size_t>(i)]) blocked_[static_cast<std::size_t>(find(i))] = 1;
    // An island is named by its lowest node (join keeps it the root): a circle's index when it has one.
    for (int i = 0; i < nodeCount; ++i) {
        if (state_[static_cast<std::size_t>(i)] != ready) continue;
        const int root = find(i);
        if (blocked_[static_cast<std::size_t>(root)]) continue;
        const int island = root < circleCount ? root : -1 - (root - circleCount);
        if (i < circleCount) {
            Circle& c = circles[static_cast<std::size_t>(i)];
            c.velocity = {};
            c.angularVelocity = 0.0;
            c.sleep.asleep = true;
            c.sleep.island = island;
        } else {
            RigidBody& b = rigid.bodies[static_cast<std::size_t>(i - circleCount)];
            b.velocity = {};
            b.angularVelocity = 0.0;
            b.sleep.asleep = true;
            b.sleep.island = island;
        }
    }
}

} // namespace rube
