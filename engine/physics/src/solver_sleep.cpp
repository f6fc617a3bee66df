// Sleeping islands for the solver: who wakes before a step, who falls asleep after it.
#include "solver_sleep.hpp"

#include <algorithm>

namespace rube {

namespace {

void wake(Circle& c) { c.sleep = SleepState{}; }

bool movingKinematic(const Circle& c) { return c.motion == Motion::kinematic && c.velocity != Vec2{}; }

bool movingKinematic(const Segment& s) {
    return s.motion() == Motion::kinematic && (s.velocity != Vec2{} || s.angularVelocity != 0.0);
}

} // namespace

int wakeAll(std::span<Circle> circles) {
    int woken = 0;
    for (Circle& c : circles) {
        if (!c.sleep.asleep) continue;
        wake(c);
        ++woken;
    }
    return woken;
}

bool SleepIslands::wakeReached(std::span<Circle> circles, std::span<const Segment> segments,
                               std::span<const CandidatePair> pairs, std::span<const double> margins, std::span<const BoundingBox> circleBoxes,
                               std::span<const BoundingBox> segmentBoxes, std::span<const BoundingBox> bulletPaths) {
    const int circleCount = static_cast<int>(circles.size());
    asleep_.clear();
    for (int i = 0; i < circleCount; ++i)
        if (circles[static_cast<std::size_t>(i)].sleep.asleep) asleep_.push_back(i);
    if (asleep_.empty()) return false;
    woke_ = false;
    const auto reach = [&](int i) {
        Circle& c = circles[static_cast<std::size_t>(i)];
        if (c.sleep.asleep) wakeIsland(circles, c.sleep.island);
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
        const double reachBoth = a.radius + b.radius + margins[static_cast<std::size_t>(p.circle)] + margins[static_cast<std::size_t>(p.other)];
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
    return woke_;
}

void SleepIslands::wakeIsland(std::span<Circle> circles, int island) {
    woke_ = true;
    for (const int i : asleep_) {
        Circle& c = circles[static_cast<std::size_t>(i)];
        if (c.sleep.asleep && c.sleep.island == island) wake(c);
    }
}

int SleepIslands::find(int i) {
    while (parent_[static_cast<std::size_t>(i)] != i) {
        // Path halving: every other node on the way points to its grandparent.
        parent_[static_cast<std::size_t>(i)] = parent_[static_cast<std::size_t>(parent_[static_cast<std::size_t>(i)])];
        i = parent_[static_cast<std::size_t>(i)];
    }
    return i;
}

void SleepIslands::update(std::span<Circle> circles, std::span<const Segment> segments,
                          std::span<const ContactConstraint> contacts, double dt, double sleepSpeed, double timeToSleep) {
    const int circleCount = static_cast<int>(circles.size());
    const double limit2 = sleepSpeed * sleepSpeed;
    const auto awakeDynamic = [&](int i) {
        const Circle& c = circles[static_cast<std::size_t>(i)];
        return c.motion == Motion::dynamic && c.inverseMass > 0.0 && !c.sleep.asleep;
    };
    int ready = 0;
    for (int i = 0; i < circleCount; ++i) {
        if (!awakeDynamic(i)) continue;
        Circle& c = circles[static_cast<std::size_t>(i)];
        const double spin = c.angularVelocity * c.radius; // the surface's speed about the centre
        const bool slow = c.velocity.lengthSquared() < limit2 && spin * spin < limit2;
        c.sleep.slowFor = slow ? c.sleep.slowFor + dt : 0.0;
        if (c.sleep.slowFor >= timeToSleep) ++ready;
    }
    // Model no more than the scene needs: islands are only built once some circle could sleep.
    if (ready == 0) return;
    parent_.resize(static_cast<std::size_t>(circleCount));
    for (int i = 0; i < circleCount; ++i) parent_[static_cast<std::size_t>(i)] = i;
    islandCarried_.assign(static_cast<std::size_t>(circleCount), 0);
    for (const ContactConstraint& c : contacts) {
        // Every contact joins, speculative ones too: a neighbour close enough to be one would wake
        // the island straight away (wakeReached), so it must sleep with it or not at all.
        if (!awakeDynamic(c.a)) continue;
        if (c.b < circleCount) {
            const Circle& other = circles[static_cast<std::size_t>(c.b)];
            if (awakeDynamic(c.b)) parent_[static_cast<std::size_t>(find(c.a))] = find(c.b);
            else if (c.impulse > 0.0 && movingKinematic(other)) islandCarried_[static_cast<std::size_t>(c.a)] = 1;
        } else if (c.impulse > 0.0 && movingKinematic(segments[static_cast<std::size_t>(c.b - circleCount)])) {
            islandCarried_[static_cast<std::size_t>(c.a)] = 1; // folded into its root below
        }
    }
    islandSlowFor_.assign(static_cast<std::size_t>(circleCount), timeToSleep);
    std::vector<std::uint8_t>& carried = islandCarried_;
    for (int i = 0; i < circleCount; ++i) {
        if (!awakeDynamic(i)) continue;
        const auto root = static_cast<std::size_t>(find(i));
        islandSlowFor_[root] = std::min(islandSlowFor_[root], circles[static_cast<std::size_t>(i)].sleep.slowFor);
        if (carried[static_cast<std::size_t>(i)]) carried[root] = 1;
    }
    for (int i = 0; i < circleCount; ++i) {
        if (!awakeDynamic(i)) continue;
        const int root = find(i);
        if (carried[static_cast<std::size_t>(root)] || islandSlowFor_[static_cast<std::size_t>(root)] < timeToSleep) continue;
        Circle& c = circles[static_cast<std::size_t>(i)];
        c.velocity = {};
        c.angularVelocity = 0.0;
        c.sleep.asleep = true;
        c.sleep.island = root;
    }
}

} // namespace rube
