// Level lint: the checks `rube check` makes beyond the format, reported as warnings at the place
// the file wrote what they are about.
#include "level_lint.hpp"

#include "level_run.hpp"
#include "script_file.hpp"
#include "toml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rube::game {

namespace {

bool inside(const Aabb& outer, const Aabb& inner) {
    return inner.min.x >= outer.min.x && inner.min.y >= outer.min.y && inner.max.x <= outer.max.x &&
           inner.max.y <= outer.max.y;
}

std::string boxWords(const Aabb& box) {
    return formatPair(box.min.x, box.min.y) + " to " + formatPair(box.max.x, box.max.y);
}

std::string itemWords(const ItemDesc& item) {
    std::string words(itemKindName(item.kind));
    if (!item.name.empty()) words += " '" + item.name + "'";
    return words + " at line " + std::to_string(item.place.line);
}

// Where the file wrote top-level table `key` ([inventory], [goal]), else the top of the file.
SourcePlace tablePlace(const std::optional<toml::table>& document, std::string_view key) {
    if (document)
        if (const toml::node* node = document->get(key)) return placeOf(node->source());
    return {1, 1};
}

void lintZones(const SceneDesc& level, Diagnostics& warn, SourcePlace inventoryPlace) {
    const LevelDesc& l = level.level;
    for (const Zone& zone : l.zones) {
        if (level.view && !inside(*level.view, zone.box))
            warn.error(zone.place, "zone " + boxWords(zone.box) + " is not wholly inside the [view] " +
                                       boxWords(*level.view) + ": the player cannot see all of it");
        if (!inside(level.world.bounds, zone.box))
            warn.error(zone.place, "zone " + boxWords(zone.box) + " is not wholly inside the world's bounds " +
                                       boxWords(level.world.bounds) + ": what is placed there escapes");
    }
    const int pieces = std::accumulate(l.inventory.begin(), l.inventory.end(), 0,
                                       [](int n, const auto& kv) { return n + kv.second; });
    if (pieces > 0 && l.zones.empty())
        warn.error(inventoryPlace, "the inventory gives " + std::to_string(pieces) + " item" +
                                       (pieces == 1 ? "" : "s") + " but the level has no [[zone]] to place them in");
    if (pieces == 0 && !l.zones.empty())
        warn.error(l.zones.front().place, "the level has placement zones but no [inventory] to place from");
}

// Where the file wrote the goal's `area`, else its [goal] (tablePlace).
SourcePlace goalAreaPlace(const std::optional<toml::table>& document) {
    if (document)
        if (const toml::table* goal = document->get_as<toml::table>("goal"))
            if (const toml::node* area = goal->get("area")) return placeOf(area->source());
    return tablePlace(document, "goal");
}

// A reach-area goal the player cannot see, or that a ball would have to leave the world to reach.
void lintGoalArea(const SceneDesc& level, Diagnostics& warn, SourcePlace place) {
    const std::optional<Goal>& goal = level.level.goal;
    if (!goal || goal->kind != GoalKind::reachArea) return;
    if (level.view && !inside(*level.view, goal->area))
        warn.error(place, "the goal's area " + boxWords(goal->area) + " is not wholly inside the [view] " +
                              boxWords(*level.view) + ": the player cannot see all of it");
    if (!inside(level.world.bounds, goal->area))
        warn.error(place, "the goal's area " + boxWords(goal->area) + " is not wholly inside the world's bounds " +
                              boxWords(level.world.bounds) + ": a ball leaves the world before it gets there");
}

} // namespace

std::optional<std::int64_t> headlessGoalStep(const SceneDesc& level, const ScriptDesc& script) {
    if (!level.level.goal) return std::nullopt;
    LevelRun run(level, script.placements);
    const std::int64_t steps = script.steps.value_or(levelSteps(level));
    std::size_t next = 0;
    for (std::int64_t i = 0; i < steps && !run.goalStep(); ++i) {
        for (; next < script.actions.size() && script.actions[next].step == i; ++next)
            (void)takeAction(script.actions[next], run);
        run.step();
    }
    return run.goalStep();
}

std::vector<SceneError> lintLevel(const SceneDesc& level, const std::string& file, std::string_view text,
                                  const std::optional<std::filesystem::path>& solution) {
    Diagnostics warn(file);
    if (!level.level.isLevel()) return {};
    Diagnostics ignored(file);
    const std::optional<toml::table> document = parseToml(text, file, ignored);
    if (!level.level.goal) warn.error({1, 1}, "the level has no [goal]: nothing can win it");
    lintZones(level, warn, tablePlace(document, "inventory"));
    lintGoalArea(level, warn, goalAreaPlace(document));
    for (const auto& [i, j] : overlappingItems(level)) {
        const ItemDesc& a = level.level.items[i];
        const ItemDesc& b = level.level.items[j];
        warn.error(b.place, "the fixed " + itemWords(b) + " overlaps the fixed " + itemWords(a) +
                                ": the physics pushes them apart on the first step");
    }
    if (level.level.goal) {
        if (const auto step = headlessGoalStep(level, ScriptDesc{}))
            warn.error(tablePlace(document, "goal"), "the goal is reached at step " + std::to_string(*step) +
                                                         " with nothing placed: the level solves itself");
    }
    if (solution) {
        const ScriptLoad load = loadScriptFile(*solution, level);
        if (!load.script)
            for (const SceneError& e : load.errors) warn.error({1, 1}, "its solution does not read: " + e.format());
        else if (level.level.goal && !headlessGoalStep(level, *load.script))
            warn.error(tablePlace(document, "goal"),
                       "its solution " + solution->filename().string() + " does not reach the goal");
    }
    return warn.sorted();
}

} // namespace rube::game
