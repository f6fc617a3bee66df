// Is the world entirely asleep and still (quiet_step.hpp)? One pass over the circles, the segments
// and the ropes, which stops at the first thing that a step would move.
#include "quiet_step.hpp"

namespace rube {

namespace {

/// As rope_constraint.cpp weighs an end: only a dynamic circle moves.
bool movable(const Circle& c) { return c.motion == Motion::dynamic && c.inverseMass > 0.0; }

/// How far apart the rope pass (enforceRopes) sees a rope's ends.
Vec2 span(std::span<const Circle> circles, const Rope& rope) {
    return circles[static_cast<std::size_t>(rope.circle)].position -
           (rope.other >= 0 ? circles[static_cast<std::size_t>(rope.other)].position : rope.anchor);
}

/// The rope pass's first loop leaves this rope and its circles exactly as they are.
bool ropeRests(std::span<const Circle> circles, const Rope& rope) {
    const Circle& a = circles[static_cast<std::size_t>(rope.circle)];
    const Circle* b = rope.other >= 0 ? &circles[static_cast<std::size_t>(rope.other)] : nullptr;
    if (!movable(a)) return !(b && movable(*b)); // no end moves: the pass skips it; else it may swing
    // Its circle asleep (checked by the caller) and its far end asleep or immovable: a sleeping rope,
    // left alone while its ends are no farther apart than its length, squared.
    return span(circles, rope).lengthSquared() <= rope.length * rope.length;
}

/// Its chain passes leave it: they test the length itself, rounded otherwise than its square.
bool ropeRestsInChain(std::span<const Circle> circles, const Rope& rope) {
    const bool moves = movable(circles[static_cast<std::size_t>(rope.circle)]) ||
                       (rope.other >= 0 && movable(circles[static_cast<std::size_t>(rope.other)]));
    return !moves || span(circles, rope).length() <= rope.length;
}

} // namespace

Stillness asleepAndStill(std::span<const Circle> circles, std::span<const Segment> segments,
                         std::span<const Rope> ropes) {
    // x - x is 0 for a finite x and NaN otherwise, so one sum tests every number (as allBodiesFinite).
    double zero = 0.0;
    for (const Circle& c : circles) {
        if (c.sleep.asleep) {
            // Still while nothing set its velocity or spin (SleepIslands::wakeReached's test), and
            // then both are finite.
            if (!((c.velocity.x == 0.0) & (c.velocity.y == 0.0) & (c.angularVelocity == 0.0))) return Stillness::moving;
            zero += (c.position.x - c.position.x) + (c.position.y - c.position.y) + (c.angle - c.angle);
            continue;
        }
        // Anything awake must be fixed: a dynamic circle moves, a kinematic one follows its path.
        if (c.motion != Motion::fixed) return Stillness::moving;
        zero += (c.position.x - c.position.x) + (c.position.y - c.position.y) + (c.velocity.x - c.velocity.x) +
                (c.velocity.y - c.velocity.y) + (c.angle - c.angle) + (c.angularVelocity - c.angularVelocity);
    }
    if (!(zero == 0.0)) return Stillness::moving;
    for (const Segment& s : segments)
        if (s.path >= 0) return Stillness::moving;
    bool chained = false; // some rope joins two circles: the rope pass then makes chain passes
    for (const Rope& rope : ropes) {
        if (rope.cut) continue;
        if (!ropeRests(circles, rope)) return Stillness::ropesToPull;
        chained = chained || rope.other >= 0;
    }
    if (chained)
        for (const Rope& rope : ropes)
            if (!rope.cut && !ropeRestsInChain(circles, rope)) return Stillness::ropesToPull;
    return Stillness::still;
}

} // namespace rube
