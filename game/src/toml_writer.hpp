#pragma once
/// TOML as the level writer writes it: numbers in their shortest exact form (0.2, not toml++'s
/// 0.20000000000000001), so a level written back reads as its author wrote it, and bit for bit.

#include <toml++/toml.h>

#include <string>

namespace rube::game {

/// One value: a string quoted, a number, a boolean, an array or an inline table.
std::string tomlValue(const toml::node& node);
/// `text` as a TOML string.
std::string tomlQuoted(const std::string& text);
/// A table's tables and arrays of tables as `[key]` and `[[key]]` blocks, its other keys as
/// `key = value` lines first (a document's top level, or the lines of one block).
std::string tomlTables(const toml::table& table);

} // namespace rube::game
