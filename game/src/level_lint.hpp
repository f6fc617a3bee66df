#pragma once
/// Level lint: what `rube check LEVEL` warns of in a level that loads, since it is legal but almost
/// certainly not what the designer meant (a level without a goal, a zone nobody can use, a level
/// that wins itself, a solution beside it that no longer wins).

#include "scene.hpp"
#include "scene_errors.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rube::game {

/// The warnings for `level`, read from `file` (whose text `text` is, for the places of its tables),
/// top of the file first; each is a SceneError so it prints as `file:line:col: message`. The
/// headless runs (nothing placed; `solution`, when given, its NAME.solution.toml) take at most the
/// level's time limit, else its duration.
std::vector<SceneError> lintLevel(const SceneDesc& level, const std::string& file, std::string_view text,
                                  const std::optional<std::filesystem::path>& solution);

struct ScriptDesc;

/// The step at which `level`, run headless with `script`'s placements and actions for the script's
/// steps, else the goal's time limit, else the level's duration, reaches its goal; nothing when it
/// does not (or has no goal).
std::optional<std::int64_t> headlessGoalStep(const SceneDesc& level, const ScriptDesc& script);

} // namespace rube::game
