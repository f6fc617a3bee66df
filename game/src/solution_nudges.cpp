// A solution's placements moved one grid step each way (see solution_nudges.hpp).
#include "solution_nudges.hpp"

#include "solve_search.hpp"

namespace rube::game {

std::vector<PlacementNudge> nudgePlacements(const SceneDesc& level, const ScriptDesc& script, std::int64_t steps) {
    const Vec2 moves[] = {{kPlacementGrid, 0.0}, {-kPlacementGrid, 0.0}, {0.0, kPlacementGrid}, {0.0, -kPlacementGrid}};
    std::vector<PlacementNudge> nudges;
    for (std::size_t i = 0; i < script.placements.size(); ++i)
        for (const Vec2 step : moves) {
            ScriptDesc moved = script;
            moved.placements[i].position += step;
            const RunOutcome run = runCandidate(level, moved, steps, false);
            nudges.push_back({i, step, !run.valid, run.goal.has_value()});
        }
    return nudges;
}

std::string gridStepWords() { return std::to_string(static_cast<int>(kPlacementGrid * 100.0 + 0.5)) + " cm"; }

std::string describeNudge(const ScriptDesc& script, const PlacementNudge& nudge) {
    const Placement& p = script.placements[nudge.placement];
    const char* way = nudge.step.x > 0.0 ? "right" : nudge.step.x < 0.0 ? "left" : nudge.step.y > 0.0 ? "up" : "down";
    const std::string who = p.name.empty() ? std::string(p.kind->name()) : p.name;
    return who + " moved " + gridStepWords() + " " + way;
}

} // namespace rube::game
