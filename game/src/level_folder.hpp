#pragma once
/// The files of a level folder and what each one is, by its name: a level (NAME.toml), the index
/// (index.toml), its intended solution (NAME.solution.toml), another intended solution
/// (NAME.solution.WORD.toml) and a plausible wrong attempt that must fail (NAME.wrong.WORD.toml).
/// One reading of the names, so the tests, `rube check` and the tools agree on which file is which.

#include <filesystem>
#include <string>
#include <vector>

namespace rube::game {

/// What a file in a level folder is.
enum class LevelFileRole {
    level,       ///< NAME.toml: a level
    index,       ///< index.toml: the order the levels are met in
    solution,    ///< NAME.solution.toml: the intended solution
    alternative, ///< NAME.solution.WORD.toml: another intended solution, reaching the goal another way
    wrong,       ///< NAME.wrong.WORD.toml: a plausible attempt that must not reach the goal
    other,       ///< anything else (not .toml, or a name of another shape)
};

/// One file of a level folder, read by its name.
struct LevelFile {
    std::filesystem::path path; ///< the file
    LevelFileRole role = LevelFileRole::other;
    std::string level;   ///< NAME: the level the file is or belongs to ("" for the index and others)
    std::string variant; ///< WORD of an alternative or wrong script ("" otherwise)
};

/// What `path` is, by its file name alone.
LevelFile classifyLevelFile(const std::filesystem::path& path);

/// Every file of `folder` with the given role, sorted by file name (an empty list when the folder
/// cannot be read).
std::vector<LevelFile> levelFilesIn(const std::filesystem::path& folder, LevelFileRole role);

/// The level a script belongs to (NAME.toml beside it) for a solution, alternative or wrong script;
/// empty for any other file.
std::filesystem::path levelOfScript(const LevelFile& script);

} // namespace rube::game
