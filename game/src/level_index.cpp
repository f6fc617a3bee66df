// The level index: levels/index.toml read with the same TableReader (and so the same messages) as
// scenes and scripts.
#include "level_index.hpp"

#include "part_kind.hpp"
#include "toml_reader.hpp"

#include <system_error>

namespace rube::game {

namespace {

constexpr std::string_view kTopKeys[] = {"level"};
constexpr std::string_view kLevelKeys[] = {"file",       "title",        "difficulty",
                                           "introduces", "solve_budget", "solve_fraction"};

// `introduces` names part kinds; a typo would make a tutorial claim a part nobody has.
std::vector<std::string> readIntroduces(TableReader& level) {
    std::vector<std::string> kinds;
    const toml::node* node = level.find("introduces");
    if (!node) return kinds;
    const toml::array* array = node->as_array();
    if (!array) {
        level.error(level.valuePlace("introduces"),
                    "introduces must be an array of part kinds, got " + std::string(typeName(*node)));
        return kinds;
    }
    std::vector<std::string_view> known;
    for (ItemKind kind : allPartKinds()) known.push_back(kind->name());
    for (const toml::node& element : *array) {
        const auto* name = element.as_string();
        if (!name) {
            level.error(placeOf(element.source()),
                        "introduces must hold part kinds (strings), got " + std::string(typeName(element)));
            continue;
        }
        if (!findPartKind(name->get())) {
            level.error(placeOf(element.source()),
                        "unknown part kind '" + name->get() + "'" + unknownNameHint(name->get(), known, "kinds", "none"));
            continue;
        }
        kinds.push_back(name->get());
    }
    return kinds;
}

} // namespace

LevelIndexLoad parseLevelIndex(std::string_view text, const std::string& fileName, const std::filesystem::path& folder) {
    Diagnostics diag(fileName);
    const std::optional<toml::table> document = parseToml(text, fileName, diag);
    if (!document) return {std::nullopt, diag.sorted()};
    TableReader root(*document, "at the top level", kTopKeys, diag);
    std::vector<IndexedLevel> levels;
    for (const toml::table* table : root.arrayOfTables("level")) {
        TableReader level(*table, "in [[level]]", kLevelKeys, diag);
        IndexedLevel entry;
        entry.place = level.tablePlace();
        const std::optional<std::string> file = level.string("file", Need::required);
        const std::optional<std::string> title = level.string("title", Need::required);
        const std::optional<std::int64_t> difficulty = level.integer("difficulty", 1, 5, Need::required);
        entry.introduces = readIntroduces(level);
        entry.solveBudget = level.integer("solve_budget", 1, 1'000'000'000);
        entry.solveFraction = level.number("solve_fraction", NumberRange::unit());
        // A fraction means nothing without the budget it was measured with (rube solve --budget).
        if (entry.solveFraction && !entry.solveBudget)
            level.error(level.valuePlace("solve_fraction"),
                        "solve_fraction needs solve_budget, the runs it was measured with");
        if (!file || !title || !difficulty) continue;
        entry.file = folder / *file;
        entry.title = *title;
        entry.difficulty = static_cast<int>(*difficulty);
        std::error_code ec;
        if (!std::filesystem::is_regular_file(entry.file, ec)) {
            level.error(level.valuePlace("file"), "no level file '" + *file + "' beside the index");
            continue;
        }
        bool listed = false;
        for (const IndexedLevel& earlier : levels)
            if (earlier.file == entry.file) {
                level.error(level.valuePlace("file"),
                            "'" + *file + "' is listed already, at line " + std::to_string(earlier.place.line));
                listed = true;
            }
        if (!listed) levels.push_back(std::move(entry));
    }
    if (!diag.empty()) return {std::nullopt, diag.sorted()};
    return {std::move(levels), {}};
}

LevelIndexLoad loadLevelIndex(const std::filesystem::path& indexFile) {
    SceneError error;
    const std::optional<std::string> text = readTextFile(indexFile, error);
    if (!text) return {std::nullopt, {error}};
    return parseLevelIndex(*text, indexFile.string(), indexFile.parent_path());
}

} // namespace rube::game
