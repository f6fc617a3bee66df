// A solution's placements moved one grid step each way (see solution_nudges.hpp).
#include "solution_nudges.hpp"

#include "placement.hpp"

namespace rube::game {

bool reachesGoal(const SceneDesc& level, const ScriptDesc& script, std::int64_t steps) {
    LevelRun run(level, script.placements);
    std::size_t next = 0;
    for (std::int64_t i = 0; i < steps && !run.goalStep(); ++i) {
        for (; next < script.actions.size() && script.actions[next].step == i; ++next)
            if (!takeAction(script.actions[next], run).empty()) return false;
        run.step();
    }
    return run.goalStep().has_value();
}

std::vector<PlacementNudge> nudgePlacements(const SceneDesc& level, const ScriptDesc& script, std::int64_t steps) {
    const Vec2 moves[] = {{kPlacementGrid, 0.0}, {-kPlacementGrid, 0.0}, {0.0, kPlacementGrid}, {0.0, -kPlacementGrid}};
    std::vector<PlacementNudge> nudges;
    for (std::size_t i = 0; i < script.placements.size(); ++i)
        for (const Vec2 step : moves) {
            ScriptDesc moved = script;
            moved.placements[i].position += step;
            PlacementNudge nudge{i, step};
            nudge.refused = checkPlacements(level, moved.placements).has_value();
            if (!nudge.refused) nudge.reached = reachesGoal(level, moved, steps);
            nudges.push_back(nudge);
        }
    return nudges;
}

std::string describeNudge(const ScriptDesc& script, const PlacementNudge& nudge) {
    const Placement& p = script.placements[nudge.placement];
    const char* way = nudge.step.x > 0.0 ? "right" : nudge.step.x < 0.0 ? "left" : nudge.step.y > 0.0 ? "up" : "down";
    const std::string who = p.name.empty() ? std::string(p.kind->name()) : p.name;
    return who + " moved " + std::to_string(static_cast<int>(kPlacementGrid * 100.0 + 0.5)) + " cm " + way;
}

} // namespace rube::game
