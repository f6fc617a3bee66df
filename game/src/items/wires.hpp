#pragma once
/// Wires: what a trigger (a timer, a pressure plate, a detector) names in its `triggers` key: one
/// name or an array of names, each a part that plays PartRole::triggered (its own trigger() says
/// what being switched does: a cannon fires, a fan flips, a laser lights) or a [[rope]] (cut).
/// One reading, check, switching and drawing for every trigger kind, so no trigger names a kind.
/// Internal to game/src/items (header only: every .cpp here is a part kind).

#include "level.hpp"
#include "part_common.hpp"

#include <string>
#include <vector>

namespace rube::game::parts {

/// The names a trigger switches, and where the file wrote them.
struct Wires {
    std::vector<std::string> names; ///< in file order
    std::vector<SourcePlace> at;    ///< where each name was written, for the message when it names nothing that fits
};

/// The docs' words for a `triggers` key.
inline constexpr std::string_view kWiresDoc =
    "a name or [names] of what it switches: parts that are switched (cannon, bomb, fan, ...) or [[rope]]s (cut)";

/// Reads `triggers` (`need` says whether it is required): a string, or an array of strings.
inline Wires readWires(TableReader& table, Need need) {
    Wires wires;
    const toml::node* node = table.get("triggers", need);
    if (!node) return wires;
    const auto take = [&](const toml::node& element) {
        const auto* name = element.as_string();
        if (!name || name->get().empty()) {
            table.error(placeOf(element.source()), "triggers must be a name or an array of names");
            return;
        }
        wires.names.push_back(name->get());
        wires.at.push_back(placeOf(element.source()));
    };
    if (const toml::array* array = node->as_array()) {
        if (array->empty()) table.error(table.valuePlace("triggers"), "triggers must name at least one thing");
        for (const toml::node& element : *array) take(element);
    } else {
        take(*node);
    }
    return wires;
}

/// Reports each name that is neither a switched part nor a [[rope]] (checked once every item is read).
inline void checkWires(const Wires& wires, SceneReading& reading) {
    for (std::size_t i = 0; i < wires.names.size(); ++i) {
        if (reading.scene.findRope(wires.names[i]) >= 0) continue;
        if (std::string message = itemReferenceError(reading.scene.level, "triggers", wires.names[i],
                                                     PartRole::triggered, "", &reading.scene.ropeNames);
            !message.empty())
            reading.diag.error(wires.at[i], std::move(message));
    }
}

/// Switches everything `wires` names, in file order: cuts a rope, or triggers a part.
inline void switchWired(LevelRun& run, const Wires& wires) {
    for (const std::string& name : wires.names) {
        if (run.scene().findRope(name) >= 0) {
            run.cutRope(name);
        } else if (const int target = run.find(name); target >= 0) {
            run.items()[static_cast<std::size_t>(target)].kind->trigger(run, target);
        }
    }
}

/// Where a wire ends on what it switches: the part's centre now, or a rope's anchor.
inline Vec2 wireEnd(const LevelRun& run, const std::string& name) {
    if (const int target = run.find(name); target >= 0) return run.itemPosition(target);
    const int rope = run.scene().findRope(name);
    return rope >= 0 ? run.scene().ropes[static_cast<std::size_t>(rope)].anchor : Vec2{};
}

/// A thin line from `from` (the trigger) to each thing it switches, always drawn in greybox so a
/// player sees what sets off what; `live` once the trigger has switched.
inline void drawWires(const PartDrawing& d, Vec2 from, const Wires& wires, bool live) {
    const render::Palette& palette = render::Palette::greybox();
    for (const std::string& name : wires.names)
        d.list.line(pt(from), pt(wireEnd(d.run, name)), live ? 2.0f : 1.0f, palette[live ? "highlight" : "wire"]);
}

} // namespace rube::game::parts
