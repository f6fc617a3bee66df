#pragma once
// Internal: the step of a world that is entirely asleep (issue 26). Once every island of a settled
// scene sleeps, a step of the solver changes nothing a body holds: sleepers are fixed for it, no
// contact is made (a contact needs an awake dynamic circle), the rope pass leaves every rope that is
// within its length, and nothing wakes. Such a world still paid for the passes every step makes over
// every body (non-finite checks, speed limits, the solver's set-up and wake test, both rope passes):
// 125,500 instructions a step for 200 weights hanging asleep, 35 % of the same weights awake.
// World::step now checks first, in one pass over the bodies and ropes, that the step would be such a
// step, and then only counts it (StepStats::quietSteps). Not part of the public API.

#include "rube/physics/body.hpp"
#include "rube/physics/rope.hpp"

#include <cstdint>
#include <span>

namespace rube {

/// What a step would do to a world: `moving` unless every dynamic circle is asleep with velocity and
/// spin exactly 0 (what wakes a sleeper from outside is a velocity set on it), every other circle is
/// fixed, no segment is on a path and every circle's state is finite (nothing for isolateNonFinite to
/// freeze). Then `still` when also every uncut rope with a dynamic end is as the rope pass leaves it
/// alone: its ends no farther apart than its length (squared, as enforceRopes tests a sleeping rope;
/// and by the length itself, as its chain passes test, when some rope joins two circles). Else
/// `ropesToPull`: nothing moves but what the rope pass may do (a sleeping weight an ulp past its
/// rope's length is put back on it every step), so the step runs the rope pass. The caller checks
/// the rest: sleep on, no fields, no rigid bodies or joints.
enum class Stillness : std::uint8_t { moving, ropesToPull, still };
Stillness asleepAndStill(std::span<const Circle> circles, std::span<const Segment> segments,
                         std::span<const Rope> ropes);

} // namespace rube
