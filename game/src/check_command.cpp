// `rube check`: every error of every file, so a level designer fixes them in one pass, and the
// warnings of a level (level_lint.hpp) that loads but is likely not what was meant.
#include "check_command.hpp"

#include "level_folder.hpp"
#include "level_index.hpp"
#include "level_lint.hpp"
#include "scene_file.hpp"
#include "script_file.hpp"
#include "toml_reader.hpp"

#include <optional>
#include <ostream>

namespace rube::game {

namespace {

constexpr std::string_view kScriptSuffix = ".solution.toml";
// Top-level keys no scene has: any of them makes a file a script.
constexpr std::string_view kScriptOnlyKeys[] = {"level", "steps", "capture", "place", "action", "expect"};

// NAME.toml beside NAME.solution.toml, NAME.solution.WORD.toml or NAME.wrong.WORD.toml (level_folder.hpp);
// nothing for a script named otherwise.
std::optional<std::filesystem::path> levelBeside(const std::filesystem::path& script) {
    const std::filesystem::path level = levelOfScript(classifyLevelFile(script));
    if (level.empty()) return std::nullopt;
    return level;
}

std::filesystem::path solutionBeside(const std::filesystem::path& level) {
    return level.parent_path() / (level.stem().string() + std::string(kScriptSuffix));
}

void print(const std::vector<SceneError>& errors, std::ostream& err) {
    for (const SceneError& error : errors) err << error.format() << '\n';
}

// A script, checked against the level --level names or the one beside it.
bool checkScript(const CheckOptions& options, const std::string& file, std::ostream& out, std::ostream& err) {
    const std::optional<std::filesystem::path> beside = levelBeside(file);
    if (options.level.empty() && (!beside || !std::filesystem::exists(*beside))) {
        err << file << ": a script is checked against its level, and "
            << (beside ? beside->string() + " does not exist"
                       : std::string("it is not named NAME.solution.toml, NAME.solution.WORD.toml or "
                                         "NAME.wrong.WORD.toml beside NAME.toml"))
            << ": name the level with --level LEVEL\n";
        return false;
    }
    const std::filesystem::path levelFile = options.level.empty() ? *beside : std::filesystem::path(options.level);
    const SceneLoad level = loadSceneFile(levelFile);
    if (!level.ok()) {
        err << file << ": its level " << levelFile.string() << " does not load:\n";
        print(level.errors, err);
        return false;
    }
    const ScriptLoad load = loadScriptFile(file, *level.scene);
    if (!load.script) {
        print(load.errors, err);
        return false;
    }
    out << file << ": ok (a script for " << levelFile.string() << ")\n";
    return true;
}

// A scene or level; a level is linted too. Returns errors and warnings counted.
bool checkScene(const CheckOptions& options, const std::string& file, const std::string& text, std::ostream& out,
                std::ostream& err) {
    const SceneLoad load = parseScene(text, file);
    if (!load.ok()) {
        print(load.errors, err);
        return false;
    }
    const std::filesystem::path solution = solutionBeside(file);
    const bool hasSolution = solution != std::filesystem::path(file) && std::filesystem::exists(solution);
    const std::vector<SceneError> warnings = lintLevel(
        *load.scene, file, text, hasSolution ? std::optional<std::filesystem::path>(solution) : std::nullopt);
    for (SceneError warning : warnings) {
        warning.message = (options.strict ? "error (--strict): " : "warning: ") + warning.message;
        err << warning.format() << '\n';
    }
    if (warnings.empty()) out << file << ": ok\n";
    else if (!options.strict)
        out << file << ": ok, " << warnings.size() << " warning" << (warnings.size() == 1 ? "" : "s") << '\n';
    return warnings.empty() || !options.strict;
}

// The level index (levels/index.toml): its [[level]] tables name files, which must exist beside it.
bool checkIndex(const std::string& file, const std::string& text, std::ostream& out, std::ostream& err) {
    const LevelIndexLoad load = parseLevelIndex(text, file, std::filesystem::path(file).parent_path());
    if (!load.levels) {
        print(load.errors, err);
        return false;
    }
    out << file << ": ok (a level index of " << load.levels->size() << " levels)\n";
    return true;
}

// A script's `level` is a string; an index's is an array of [[level]] tables.
bool looksLikeIndex(const std::string& file, const std::string& text) {
    Diagnostics ignored(file);
    const std::optional<toml::table> document = parseToml(text, file, ignored);
    return document && document->get_as<toml::array>("level") != nullptr;
}

} // namespace

bool looksLikeScript(const std::string& file, const std::string& text) {
    if (!levelOfScript(classifyLevelFile(file)).empty()) return true;
    Diagnostics ignored(file);
    const std::optional<toml::table> document = parseToml(text, file, ignored);
    if (!document) return false;
    for (std::string_view key : kScriptOnlyKeys)
        if (document->contains(key)) return true;
    return false;
}

ExitCode checkFiles(const CheckOptions& options, std::ostream& out, std::ostream& err) {
    bool ok = true;
    for (const std::string& file : options.files) {
        SceneError error;
        const std::optional<std::string> text = readTextFile(file, error);
        if (!text) {
            err << error.format() << '\n';
            ok = false;
            continue;
        }
        const bool good = looksLikeIndex(file, *text)    ? checkIndex(file, *text, out, err)
                          : looksLikeScript(file, *text) ? checkScript(options, file, out, err)
                                                         : checkScene(options, file, *text, out, err);
        ok = ok && good;
    }
    return ok ? ExitCode::ok : ExitCode::badInput;
}

} // namespace rube::game
