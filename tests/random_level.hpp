#pragma once
// A seeded generator of random *plays* of a shipped level (issue 27): random placements of its
// inventory (counts up to what it gives, centres inside its placement zones, any angle for the
// kinds that turn) and random actions at random steps on the items that take them (aim, fire,
// fire-when, detonate, toggle, cut). The placements are not checked here: the caller keeps those
// checkPlacements() accepts. The draws come from SceneRng (splitmix64), so every compiler plays
// the same seed alike.
#include "random_scene.hpp"
#include "script_file.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace rube::test {

/// A random play of one level: what the player placed and did.
struct RandomPlay {
    std::vector<game::Placement> placements; ///< named "random-0", "random-1", ... so actions can name them
    std::vector<game::Action> actions;       ///< sorted by frame
};

/// Placements of `level`'s inventory: each kind up to its count, each centre inside a random zone.
/// Mostly the zone shrunk by the item's half-extent (so the item fits), one in five the whole zone
/// (so the zone rule refuses some); overlaps are left to checkPlacements.
inline std::vector<game::Placement> randomPlacements(const game::SceneDesc& level, SceneRng& rng) {
    std::vector<game::Placement> placements;
    if (level.level.zones.empty()) return placements;
    for (const auto& [kindName, count] : level.level.inventory) {
        const game::ItemKind kind = game::findPartKind(kindName);
        if (!kind) continue;
        const int placed = rng.below(count + 1);
        for (int i = 0; i < placed; ++i) {
            game::Placement p;
            p.kind = kind;
            if (p.kind->turns()) {
                // Whole degrees, as a player or script writes them; sometimes level, sometimes any.
                p.angleDegrees = rng.chance(0.3) ? 0.0 : static_cast<double>(rng.below(360) - 180);
                p.angle = game::scriptRadians(p.angleDegrees);
            }
            const game::Zone& zone =
                level.level.zones[static_cast<std::size_t>(rng.below(static_cast<int>(level.level.zones.size())))];
            Vec2 lo = zone.box.min, hi = zone.box.max;
            if (!rng.chance(0.2)) {
                game::ItemDesc probe = game::defaultItem(p.kind, {});
                probe.angle = p.angle;
                const Aabb extent = game::itemExtent(probe); // about the origin: the centre's margin
                lo = lo - extent.min;
                hi = hi - extent.max;
                if (lo.x > hi.x) lo.x = hi.x = 0.5 * (zone.box.min.x + zone.box.max.x);
                if (lo.y > hi.y) lo.y = hi.y = 0.5 * (zone.box.min.y + zone.box.max.y);
            }
            p.position = {rng.in(lo.x, hi.x), rng.in(lo.y, hi.y)};
            p.name = "random-" + std::to_string(placements.size());
            placements.push_back(p);
        }
    }
    // The order of placement decides which of two overlapping items is refused: shuffle it.
    for (std::size_t i = placements.size(); i > 1; --i)
        std::swap(placements[i - 1], placements[static_cast<std::size_t>(rng.below(static_cast<int>(i)))]);
    return placements;
}

/// Up to five actions at random steps before `steps` on the named items of the level and the
/// placements that take them: cannons are aimed (an angle, a point, a target on either arc), fired
/// or fired-when; bombs detonated; switches, fans, magnets and rockets toggled; named ropes cut.
inline std::vector<game::Action> randomActions(const game::SceneDesc& level,
                                               const std::vector<game::Placement>& placements, std::int64_t steps,
                                               SceneRng& rng) {
    using game::ActionKind;
    std::vector<game::ItemDesc> items = level.level.items;
    for (const game::Placement& p : placements) items.push_back(game::placedItem(p));
    std::vector<std::string> cannons, bombs, toggles, targets, ropes;
    for (const game::ItemDesc& item : items) {
        if (item.name.empty()) continue;
        if (item.kind->plays(game::PartRole::fire)) cannons.push_back(item.name);
        if (item.kind->plays(game::PartRole::detonate)) bombs.push_back(item.name);
        if (item.kind->plays(game::PartRole::toggle)) toggles.push_back(item.name);
        if (item.kind->plays(game::PartRole::aimTarget)) targets.push_back(item.name);
    }
    for (const std::string& rope : level.ropeNames)
        if (!rope.empty()) ropes.push_back(rope);
    const auto pick = [&](const std::vector<std::string>& names) {
        return names[static_cast<std::size_t>(rng.below(static_cast<int>(names.size())))];
    };
    std::vector<game::Action> actions;
    const int count = rng.below(6);
    for (int i = 0; i < count; ++i) {
        game::Action a;
        a.step = rng.below(static_cast<int>(steps));
        switch (rng.below(4)) {
        case 0: // a cannon: aim, fire or fire-when
            if (cannons.empty()) continue;
            a.item = pick(cannons);
            switch (rng.below(5)) {
            case 0:
                a.kind = ActionKind::aim;
                a.angleDegrees = static_cast<double>(rng.below(360) - 180);
                a.angle = game::scriptRadians(a.angleDegrees);
                break;
            case 1: {
                a.kind = ActionKind::aim;
                const Aabb& b = level.world.bounds;
                a.point = Vec2{rng.in(std::max(b.min.x, -20.0), std::min(b.max.x, 20.0)),
                               rng.in(std::max(b.min.y, -20.0), std::min(b.max.y, 20.0))};
                a.highArc = rng.chance(0.5);
                break;
            }
            case 2:
                if (targets.empty()) continue;
                a.kind = ActionKind::aim;
                a.target = pick(targets);
                a.highArc = rng.chance(0.5);
                break;
            case 3:
                if (targets.empty()) continue;
                a.kind = ActionKind::fireWhen;
                a.target = pick(targets);
                break;
            default: a.kind = ActionKind::fire; break;
            }
            break;
        case 1:
            if (bombs.empty()) continue;
            a.kind = ActionKind::detonate;
            a.item = pick(bombs);
            break;
        case 2:
            if (toggles.empty()) continue;
            a.kind = ActionKind::toggle;
            a.item = pick(toggles);
            break;
        default:
            if (ropes.empty()) continue;
            a.kind = ActionKind::cut;
            a.item = pick(ropes);
            break;
        }
        actions.push_back(a);
    }
    std::stable_sort(actions.begin(), actions.end(),
                     [](const game::Action& x, const game::Action& y) { return x.step < y.step; });
    return actions;
}

} // namespace rube::test
