// The TOML writer: toml++ parses and quotes strings; numbers go through scriptNumber, the one
// shortest-exact spelling the scripts use too.
#include "toml_writer.hpp"

#include "script_file.hpp"

#include <sstream>

namespace rube::game {

namespace {

bool isTableArray(const toml::node& node) {
    const toml::array* array = node.as_array();
    return array && !array->empty() && array->is_array_of_tables();
}

// The `key = value` lines of a table: with `blocks`, its tables and arrays of tables are left to
// their own [key] and [[key]] blocks (a document's top level); else they are written inline.
std::string keyValueLines(const toml::table& table, bool blocks) {
    std::string text;
    for (const auto& [key, value] : table) {
        if (blocks && (value.is_table() || isTableArray(value))) continue;
        text += key.str();
        text += " = ";
        text += tomlValue(value);
        text += '\n';
    }
    return text;
}

} // namespace

std::string tomlValue(const toml::node& node) {
    if (const auto* s = node.as_string()) {
        std::ostringstream out;
        out << *s;
        return out.str();
    }
    if (const auto* i = node.as_integer()) return std::to_string(i->get());
    if (const auto* f = node.as_floating_point()) return scriptNumber(f->get());
    if (const auto* b = node.as_boolean()) return b->get() ? "true" : "false";
    if (const auto* array = node.as_array()) {
        std::string text = "[";
        for (std::size_t i = 0; i < array->size(); ++i) {
            if (i > 0) text += ", ";
            text += tomlValue(*array->get(i));
        }
        return text += "]";
    }
    if (const auto* table = node.as_table()) {
        std::string text = "{";
        bool first = true;
        for (const auto& [key, value] : *table) {
            text += first ? " " : ", ";
            text += key.str();
            text += " = ";
            text += tomlValue(value);
            first = false;
        }
        return text += first ? "}" : " }";
    }
    std::ostringstream out; // dates and times: no scene has them, but toml++ can spell them
    node.visit([&](const auto& value) { out << value; });
    return out.str();
}

std::string tomlQuoted(const std::string& text) { return tomlValue(toml::value<std::string>(text)); }

std::string tomlTables(const toml::table& table) {
    std::string text = keyValueLines(table, true);
    for (const auto& [key, value] : table) {
        if (const toml::table* block = value.as_table()) {
            text += "\n[";
            text += key.str();
            text += "]\n";
            text += keyValueLines(*block, false);
        } else if (isTableArray(value)) {
            for (const toml::node& element : *value.as_array()) {
                text += "\n[[";
                text += key.str();
                text += "]]\n";
                text += keyValueLines(*element.as_table(), false);
            }
        }
    }
    return text;
}

} // namespace rube::game
