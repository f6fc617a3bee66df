// Reading one TOML table against what it may hold: the one place where types and ranges are checked.
#include "toml_reader.hpp"

#include <algorithm>
#include <cmath>

namespace rube::game {

SourcePlace placeOf(const toml::source_region& region) {
    // An empty document has no position at all; its errors still belong at the file's start.
    return {std::max(1, static_cast<int>(region.begin.line)), std::max(1, static_cast<int>(region.begin.column))};
}

std::string_view typeName(const toml::node& node) {
    switch (node.type()) {
    case toml::node_type::string: return "string";
    case toml::node_type::integer: return "integer";
    case toml::node_type::floating_point: return "float";
    case toml::node_type::boolean: return "boolean";
    case toml::node_type::array: return "array";
    case toml::node_type::table: return "table";
    case toml::node_type::date: return "date";
    case toml::node_type::time: return "time";
    case toml::node_type::date_time: return "date-time";
    case toml::node_type::none: break;
    }
    return "nothing";
}

bool NumberRange::contains(double value) const { return (minExcluded ? value > min : value >= min) && value <= max; }

std::string NumberRange::describe() const {
    // A bound that excludes min says so: "between 0 and 100" would let 0 through.
    if (std::isfinite(max) && minExcluded)
        return "greater than " + formatNumber(min) + " and at most " + formatNumber(max);
    if (std::isfinite(max)) return "between " + formatNumber(min) + " and " + formatNumber(max);
    return (minExcluded ? "greater than " : "at least ") + formatNumber(min);
}

std::string syntaxMessage(std::string_view description) {
    constexpr std::string_view prefix = "Error while parsing ";
    if (description.starts_with(prefix)) return "syntax error in " + std::string(description.substr(prefix.size()));
    return "syntax error: " + std::string(description);
}

std::optional<toml::table> parseToml(std::string_view text, const std::string& fileName, Diagnostics& diag) {
    try {
        return toml::parse(text, std::string_view(fileName));
    } catch (const toml::parse_error& e) {
        diag.error(placeOf(e.source()), syntaxMessage(e.description()));
        return std::nullopt;
    }
}

std::optional<double> readNumber(const toml::node& node, std::string_view what, Diagnostics& diag) {
    double value = 0.0;
    if (const auto* i = node.as_integer()) value = static_cast<double>(i->get());
    else if (const auto* f = node.as_floating_point()) value = f->get();
    else {
        diag.error(placeOf(node.source()), std::string(what) + " must be a number, got " + std::string(typeName(node)));
        return std::nullopt;
    }
    // TOML allows nan and inf; no physical quantity in a scene may be either.
    if (!std::isfinite(value)) {
        diag.error(placeOf(node.source()), std::string(what) + " must be finite, got " + formatNumber(value));
        return std::nullopt;
    }
    // Nor so large that squaring it (distances, energies) overflows: no scene needs more than a
    // billion of any unit, and 1e300 is a typo that would turn into infinities a few steps in.
    if (std::abs(value) > kMaxNumberMagnitude) {
        diag.error(placeOf(node.source()),
                   std::string(what) + " must be between -1e9 and 1e9, got " + formatNumber(value));
        return std::nullopt;
    }
    return value;
}

TableReader::TableReader(const toml::table& table, std::string where, std::span<const std::string_view> known,
                         Diagnostics& diag, std::span<const KeyHome> homes, std::span<const std::string_view> unlisted,
                         std::span<const KeyRename> renamed)
    : table_(table), where_(std::move(where)), diag_(diag), renamed_(renamed) {
    for (auto&& [key, value] : table_) {
        const std::string_view name = key.str();
        if (std::find(known.begin(), known.end(), name) != known.end()) continue;
        if (std::find(unlisted.begin(), unlisted.end(), name) != unlisted.end()) continue;
        const auto rename = std::find_if(renamed.begin(), renamed.end(),
                                         [&](const KeyRename& r) { return r.old == name; });
        if (rename != renamed.end()) {
            // Appended piece by piece: GCC 12's -Wrestrict misfires on "'" + std::string(...).
            std::string message = "'";
            message.append(name).append("' is now '").append(rename->now).append("' ").append(where_);
            diag_.error(placeOf(key.source()), std::move(message));
            continue;
        }
        std::string message = "unknown key '" + std::string(name) + "' " + where_;
        const auto home = std::find_if(homes.begin(), homes.end(), [&](const KeyHome& h) { return h.key == name; });
        if (home != homes.end()) message += " (it belongs in " + std::string(home->home) + ")";
        else if (const auto match = closestMatch(name, known))
            message += " (did you mean '" + std::string(*match) + "'?)";
        else message += " (known keys: " + joinNames(known) + ")";
        diag_.error(placeOf(key.source()), std::move(message));
    }
}

SourcePlace TableReader::valuePlace(std::string_view key) const {
    const toml::node* node = find(key);
    return node ? placeOf(node->source()) : tablePlace();
}

void TableReader::error(SourcePlace place, std::string message) { diag_.error(place, std::move(message)); }

const toml::node* TableReader::get(std::string_view key, Need need) {
    const toml::node* node = find(key);
    // A key written under its old name has been reported as renamed; it is not missing as well.
    const bool writtenAsOld = std::any_of(renamed_.begin(), renamed_.end(),
                                          [&](const KeyRename& r) { return r.now == key && find(r.old); });
    if (!node && need == Need::required && !writtenAsOld)
        error(tablePlace(), "missing required key '" + std::string(key) + "' " + where_);
    return node;
}

std::optional<double> TableReader::number(std::string_view key, NumberRange range, Need need) {
    const toml::node* found = get(key, need);
    if (!found) return std::nullopt;
    const toml::node& node = *found;
    const auto value = readNumber(node, key, diag_);
    if (!value) return std::nullopt;
    if (!range.contains(*value)) {
        error(placeOf(node.source()),
              std::string(key) + " must be " + range.describe() + ", got " + formatNumber(*value));
        return std::nullopt;
    }
    return value;
}

std::optional<std::int64_t> TableReader::integer(std::string_view key, std::int64_t min, std::int64_t max, Need need) {
    const toml::node* found = get(key, need);
    if (!found) return std::nullopt;
    const toml::node& node = *found;
    const auto* value = node.as_integer();
    if (!value) {
        error(placeOf(node.source()), std::string(key) + " must be an integer, got " + std::string(typeName(node)));
        return std::nullopt;
    }
    if (value->get() < min || value->get() > max) {
        error(placeOf(node.source()), std::string(key) + " must be between " + std::to_string(min) + " and " +
                                          std::to_string(max) + ", got " + std::to_string(value->get()));
        return std::nullopt;
    }
    return value->get();
}

std::optional<Vec2> TableReader::vec2(std::string_view key, Need need) {
    const toml::node* found = get(key, need);
    if (!found) return std::nullopt;
    const toml::node& node = *found;
    const auto* array = node.as_array();
    if (!array) {
        error(placeOf(node.source()),
              std::string(key) + " must be an array [x, y], got " + std::string(typeName(node)));
        return std::nullopt;
    }
    if (array->size() != 2) {
        error(placeOf(node.source()),
              std::string(key) + " must hold 2 numbers [x, y], got " + std::to_string(array->size()));
        return std::nullopt;
    }
    const auto x = readNumber(*array->get(0), std::string(key) + "'s x", diag_);
    const auto y = readNumber(*array->get(1), std::string(key) + "'s y", diag_);
    if (!x || !y) return std::nullopt;
    return Vec2{*x, *y};
}

std::optional<Vec2> TableReader::vec2(std::string_view key, NumberRange range, Need need) {
    const auto value = vec2(key, need);
    if (value && (!range.contains(value->x) || !range.contains(value->y))) {
        error(valuePlace(key),
              std::string(key) + "'s x and y must be " + range.describe() + ", got " + formatPair(value->x, value->y));
        return std::nullopt;
    }
    return value;
}

std::optional<Vec2> TableReader::numberOrVec2(std::string_view key, NumberRange range, Need need) {
    const toml::node* found = get(key, need);
    if (!found) return std::nullopt;
    const toml::node& node = *found;
    if (!node.is_array() && !node.is_number()) {
        error(placeOf(node.source()),
              std::string(key) + " must be a number or an array [x, y], got " + std::string(typeName(node)));
        return std::nullopt;
    }
    if (!node.is_array()) {
        const auto both = number(key, range);
        return both ? std::optional<Vec2>(Vec2{*both, *both}) : std::nullopt;
    }
    const auto value = vec2(key);
    if (value && (!range.contains(value->x) || !range.contains(value->y))) {
        error(placeOf(node.source()),
              std::string(key) + "'s x and y must be " + range.describe() + ", got " + formatPair(value->x, value->y));
        return std::nullopt;
    }
    return value;
}

std::optional<std::string> TableReader::string(std::string_view key, Need need) {
    const toml::node* found = get(key, need);
    if (!found) return std::nullopt;
    const toml::node& node = *found;
    const auto* value = node.as_string();
    if (!value) {
        error(placeOf(node.source()), std::string(key) + " must be a string, got " + std::string(typeName(node)));
        return std::nullopt;
    }
    return value->get();
}

std::optional<bool> TableReader::boolean(std::string_view key, Need need) {
    const toml::node* found = get(key, need);
    if (!found) return std::nullopt;
    const toml::node& node = *found;
    const auto* value = node.as_boolean();
    if (!value) {
        error(placeOf(node.source()), std::string(key) + " must be true or false, got " + std::string(typeName(node)));
        return std::nullopt;
    }
    return value->get();
}

std::optional<std::size_t> TableReader::choice(std::string_view key, std::span<const std::string_view> names,
                                               Need need) {
    const auto value = string(key, need);
    if (!value) return std::nullopt;
    const auto it = std::find(names.begin(), names.end(), *value);
    if (it != names.end()) return static_cast<std::size_t>(it - names.begin());
    std::string message = std::string(key) + " must be one of " + joinNames(names) + ", got '" + *value + "'";
    if (const auto match = closestMatch(*value, names)) message += " (did you mean '" + std::string(*match) + "'?)";
    error(valuePlace(key), std::move(message));
    return std::nullopt;
}

const toml::table* TableReader::table(std::string_view key, std::string_view shape, Need need) {
    const toml::node* found = get(key, need);
    if (!found) return nullptr;
    const toml::node& node = *found;
    const auto* value = node.as_table();
    if (!value)
        error(placeOf(node.source()),
              std::string(key) + " must be a table " + std::string(shape) + ", got " + std::string(typeName(node)));
    return value;
}

std::vector<const toml::table*> TableReader::arrayOfTables(std::string_view key) {
    std::vector<const toml::table*> result;
    const toml::node* node = find(key);
    if (!node) return result;
    const auto* array = node->as_array();
    // An empty array holds no tables, but it is also no mistake worth an error.
    if (array && array->empty()) return result;
    if (!array || !array->is_array_of_tables()) {
        error(placeOf(node->source()), std::string(key) + " must be an array of tables, written [[" + std::string(key) +
                                           "]], got " + std::string(typeName(*node)));
        return result;
    }
    for (const toml::node& element : *array) result.push_back(element.as_table());
    return result;
}

} // namespace rube::game
