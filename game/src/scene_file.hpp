#pragma once
/// Scene files: loading a TOML scene into a SceneDesc, or every reason it cannot be loaded.
///
/// game/scene-format.md describes the format. In short: a top-level `name` and `description`, a
/// `[world]` table, and arrays of tables `[[path]]`, `[[circle]]`, `[[circle_grid]]` and
/// `[[segment]]`. Unknown keys are errors, so a typo never passes silently as a default.

#include "scene.hpp"
#include "scene_errors.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rube::game {

/// The outcome of loading: a scene when there are no errors, else the errors, sorted by place.
struct SceneLoad {
    std::optional<SceneDesc> scene; ///< present exactly when there are no errors
    std::vector<SceneError> errors; ///< every error found, top of the file first
    /// True when the scene loaded.
    bool ok() const { return scene.has_value(); }
};

/// Reads and validates a scene file; an unreadable file is the one error "file: cannot open file".
SceneLoad loadSceneFile(const std::filesystem::path& file);

/// Validates scene text; `fileName` is what the errors are reported under.
SceneLoad parseScene(std::string_view text, const std::string& fileName);

} // namespace rube::game
