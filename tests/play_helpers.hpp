#pragma once
// What the play window's tests do as a player would: load a shipped level, move the cursor to a
// world point, drag a kind from the bar to a point and let go.
#include "play_session.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

namespace rube::game::play_test {

inline const std::filesystem::path kLevels = RUBE_GAME_LEVELS_DIR;

/// And their stock, zone and goal: two planks and a heavy ball, the zone [-4, 1] to [4, 6], a hit
/// on the target "flag" (which each level places).
inline constexpr const char* kTestStock = R"(
[inventory]
plank = 2
heavy = 1
[[zone]]
min = [-4, 1]
max = [4, 6]
[goal]
text = "hit the flag"
condition = "target-hit"
target = "flag"
)";

/// The test levels' common part: a 0.01 s step, a view 16 m wide, a floor and a cannon "gun".
inline constexpr const char* kTestBench = R"(
[world]
time_step = 0.01
bounds = { min = [-20, -5], max = [20, 30] }
[view]
min = [-8, -1]
max = [8, 8]
[[segment]]
a = [-8, 0]
b = [8, 0]
[[item]]
kind = "cannon"
name = "gun"
position = [-6, 0.6]
angle = 30
speed = 10
)";

inline SceneDesc loadLevel(const std::string& name) {
    const SceneLoad load = loadSceneFile(kLevels / (name + ".toml"));
    REQUIRE(load.ok());
    return *load.scene;
}

inline void moveTo(PlaySession& s, Vec2 world) {
    const render::Point p = s.pixelOf(world);
    s.cursorMoved(p.x, p.y);
}

// Drags a kind from the bar to a world point and lets go.
inline void place(PlaySession& s, ItemKind kind, Vec2 at) {
    const auto slot = s.slotPixel(kind);
    REQUIRE(slot);
    s.cursorMoved(slot->x, slot->y);
    s.mouseButton(render::MouseButton::left, true);
    moveTo(s, at);
    s.mouseButton(render::MouseButton::left, false);
}

} // namespace rube::game::play_test
