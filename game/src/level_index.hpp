#pragma once
/// The level index (levels/index.toml): the levels in the order a player meets them, with the title
/// the level list shows, a difficulty and the parts each tutorial introduces.

#include "scene_errors.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rube::game {

/// One level of the index.
struct IndexedLevel {
    std::filesystem::path file;          ///< the level, resolved against the index's folder
    std::string title;                   ///< what the level list shows
    int difficulty = 1;                  ///< 1 (a first tutorial) to 5 (a long chain reaction)
    std::vector<std::string> introduces; ///< part kinds this level is the first to give or show
    SourcePlace place;                   ///< where its [[level]] table begins in the index
    std::optional<std::int64_t> solveBudget; ///< runs `rube solve` measured the solve fraction with (seed 1)
    std::optional<double> solveFraction;     ///< the share of valid candidates that solve it, as measured
};

/// The outcome of reading an index: its levels in order when there are no errors.
struct LevelIndexLoad {
    std::optional<std::vector<IndexedLevel>> levels; ///< present exactly when there are no errors
    std::vector<SceneError> errors;                  ///< every error found, top of the file first
};

/// Reads an index: unknown keys, a missing file, a level listed twice, a difficulty outside 1..5,
/// an unknown part kind in `introduces`, a solve_fraction outside 0..1 or without a solve_budget
/// are errors at their place.
LevelIndexLoad loadLevelIndex(const std::filesystem::path& indexFile);

/// The same from text; `fileName` is what errors are reported under, `folder` what files resolve against.
LevelIndexLoad parseLevelIndex(std::string_view text, const std::string& fileName, const std::filesystem::path& folder);

} // namespace rube::game
