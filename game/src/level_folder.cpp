// Level folders: which file is a level, a solution or a wrong attempt, by the dots of its name.
#include "level_folder.hpp"

#include <algorithm>
#include <ranges>

namespace rube::game {

namespace {

// NAME.a.b.toml -> {NAME, a, b}; the final ".toml" is required and dropped. An empty part (two
// dots together, a leading dot) makes the name of no role.
std::vector<std::string> dottedParts(const std::string& name) {
    constexpr std::string_view kToml = ".toml";
    if (name.size() <= kToml.size() || !name.ends_with(kToml)) return {};
    const std::string stem = name.substr(0, name.size() - kToml.size());
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t dot = stem.find('.', start);
        parts.push_back(stem.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
        if (parts.back().empty()) return {};
        if (dot == std::string::npos) break;
        start = dot + 1;
    }
    return parts;
}

} // namespace

LevelFile classifyLevelFile(const std::filesystem::path& path) {
    LevelFile file{path, LevelFileRole::other, {}, {}};
    const std::vector<std::string> parts = dottedParts(path.filename().string());
    if (parts.size() == 1) {
        file.role = parts[0] == "index" ? LevelFileRole::index : LevelFileRole::level;
        if (file.role == LevelFileRole::level) file.level = parts[0];
    } else if (parts.size() == 2 && parts[1] == "solution") {
        file.role = LevelFileRole::solution;
        file.level = parts[0];
    } else if (parts.size() == 3 && (parts[1] == "solution" || parts[1] == "wrong")) {
        file.role = parts[1] == "solution" ? LevelFileRole::alternative : LevelFileRole::wrong;
        file.level = parts[0];
        file.variant = parts[2];
    }
    return file;
}

std::vector<LevelFile> levelFilesIn(const std::filesystem::path& folder, LevelFileRole role) {
    std::vector<LevelFile> files;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        LevelFile file = classifyLevelFile(entry.path());
        if (file.role == role && entry.is_regular_file()) files.push_back(std::move(file));
    }
    std::ranges::sort(files, {}, [](const LevelFile& f) { return f.path.filename().string(); });
    return files;
}

std::filesystem::path levelOfScript(const LevelFile& script) {
    const bool isScript = script.role == LevelFileRole::solution || script.role == LevelFileRole::alternative ||
                          script.role == LevelFileRole::wrong;
    if (!isScript) return {};
    return script.path.parent_path() / (script.level + ".toml");
}

} // namespace rube::game
