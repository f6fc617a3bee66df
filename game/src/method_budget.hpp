#pragma once
/// What a time-step method affords. discrete, turn-based and exact test every pair of shapes
/// (no broadphase: exact's search, turn-based's turns and discrete's overlap pass are each
/// dynamic bodies x shapes), so a scene too large for them would run for minutes a step; it is
/// refused before it starts, naming the methods that scale (auto and solver use a grid).

#include "scene.hpp"

#include <cstdint>
#include <string>

namespace rube::game {

/// The most pair tests one search (exact, turn-based) or one step (discrete) may cost: 2^22,
/// about 2,048 bodies; the bench's 1000-ball exact pile (about 1.0e6) fits.
inline constexpr std::int64_t kMaxPairTests = std::int64_t{1} << 22;

/// Pair tests a method without a broadphase makes per search: dynamic bodies x every shape.
std::int64_t pairTestsPerSearch(const SceneDesc& scene);

/// Empty when `method` affords `scene`; else the refusal, one line without the file name:
/// "method exact tests every pair: ... : use auto or solver".
std::string methodBudgetRefusal(const SceneDesc& scene, Method method);

} // namespace rube::game
