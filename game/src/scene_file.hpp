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

/// One item read again: the item when it reads, else every error the reader finds.
struct ItemLoad {
    std::optional<ItemDesc> item;   ///< present exactly when there are no errors
    std::vector<SceneError> errors; ///< in the text's places
};

/// Item `index` of `level` read from `itemToml`, one [[item]] table, as a level file's reader reads
/// it among the level's other items (a switch may name them; their names are taken): the editor's
/// check of a part's own keys, with the reader's own messages.
ItemLoad readItemAgain(const SceneDesc& level, std::size_t index, std::string_view itemToml);

} // namespace rube::game
