#pragma once
/// Reading one TOML table against what it may hold: typed values, ranges and unknown keys,
/// each problem reported once at the place it was written.

#include "scene_errors.hpp"

#include "rube/physics/vec2.hpp"

#include <toml++/toml.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rube::game {

/// Where a toml++ node or key begins.
SourcePlace placeOf(const toml::source_region& region);

/// The TOML type of a node as messages name it: "string", "integer", "float", "boolean", "array", ...
std::string_view typeName(const toml::node& node);

/// The interval a number must lie in; `describe` gives the words for the error message.
struct NumberRange {
    double min = -std::numeric_limits<double>::infinity(); ///< lowest allowed value
    double max = std::numeric_limits<double>::infinity();  ///< highest allowed value, always included
    bool minExcluded = false;                              ///< true for "greater than min"

    /// Any finite number.
    static NumberRange any() { return {}; }
    /// Greater than zero: sizes, masses, time steps.
    static NumberRange positive() { return {0.0, std::numeric_limits<double>::infinity(), true}; }
    /// Zero or more: thicknesses, friction, speeds.
    static NumberRange nonNegative() { return {0.0, std::numeric_limits<double>::infinity(), false}; }
    /// From 0 to 1 inclusive: the coefficient of restitution C (lecture 3).
    static NumberRange unit() { return {0.0, 1.0, false}; }
    // The ranges below keep every product the physics forms finite and resolvable (issue 27; a mass
    // of 4.9e-324 made 1/m infinite, a pivot at [1e9, 1e9] lost the joint's metres to round-off).
    // Every shipped level and scene lies well inside them: masses 0.01 to 1,571 kg, sizes 0.0286 to
    // 3 m, positions within 40 m.
    /// Masses, kg: a milligram to a thousand tonnes. The largest ratio, 1e12, still leaves 1/m and
    /// impulse sums (m v, m v^2 at speeds up to 1e9 m/s) far from overflow and underflow.
    static NumberRange mass() { return {1e-6, 1e6, false}; }
    /// Body sizes (radii, half extents), m: 0.1 mm to 10 km. I = k m r^2 >= 1e-14 keeps 1/I finite.
    static NumberRange size() { return {1e-4, 1e4, false}; }
    /// Thicknesses (a segment's radius), m: 0 (the lecture's thin line) up to 10 km.
    static NumberRange thickness() { return {0.0, 1e4, false}; }
    /// Coordinates of positions and anchors, m: within the world's escape bounds (+-1e6, WorldDef::bounds),
    /// where a double still resolves 1e-10 m, so contact gaps of a millimetre are exact to round-off.
    static NumberRange coordinate() { return {-1e6, 1e6, false}; }

    /// True when `value` lies in the interval.
    bool contains(double value) const;
    /// "greater than 0", "at least 0", "between 0 and 1", "greater than 0 and at most 100".
    std::string describe() const;
};

/// Whether a missing key is an error or takes its default.
enum class Need { optional, required };

/// A key that belongs in another table, for the hint "(it belongs in [world])".
struct KeyHome {
    std::string_view key;  ///< the key as written
    std::string_view home; ///< the table it belongs in, as the message shows it: "[world]"
};

/// A key that was renamed, for the message "'frame' is now 'step' in [[action]]": an old file is told
/// the new word rather than offered the nearest known key.
struct KeyRename {
    std::string_view old; ///< the key as files used to write it
    std::string_view now; ///< the key it became
};

/// toml++ says "Error while parsing key-value pair: expected value"; this keeps its precise words but
/// makes them read as one of ours, in scenes and scripts alike: "syntax error in key-value pair: expected value".
std::string syntaxMessage(std::string_view description);

/// Parses TOML text, or records its syntax error (one line, at its place) in `diag` and returns nothing.
std::optional<toml::table> parseToml(std::string_view text, const std::string& fileName, Diagnostics& diag);

/// The largest magnitude any number in a scene or script may have: 1e9 (of metres, seconds, kilograms...).
inline constexpr double kMaxNumberMagnitude = 1e9;

/// Reads a node as a finite number (TOML integers count) of at most kMaxNumberMagnitude, or reports
/// "`what` must be a number, got string", "`what` must be finite, got nan" or
/// "`what` must be between -1e9 and 1e9, got 1e+300" at the node.
std::optional<double> readNumber(const toml::node& node, std::string_view what, Diagnostics& diag);

/// Reads the values of one table. Construction reports every key the table may not hold,
/// with the closest known key as a suggestion; each getter then reports a wrong type, a value
/// out of range, or a missing required key, and returns nothing in those cases.
class TableReader {
public:
    /// `where` ends the messages: "in [[circle]]", "in [world]", "at the top level". `unlisted` keys
    /// are accepted but not offered in "known keys" lists (the level additions to physics tables);
    /// a `renamed` key is reported with its new name, and the new one is then not also missing.
    TableReader(const toml::table& table, std::string where, std::span<const std::string_view> known, Diagnostics& diag,
                std::span<const KeyHome> homes = {}, std::span<const std::string_view> unlisted = {},
                std::span<const KeyRename> renamed = {});

    /// The value under `key`, or null.
    const toml::node* find(std::string_view key) const { return table_.get(key); }
    /// The value under `key`, or null, reporting the key as missing when it is required.
    const toml::node* get(std::string_view key, Need need);
    /// Where the table begins: its [[header]], its `{`, or 1:1 for the whole file.
    SourcePlace tablePlace() const { return placeOf(table_.source()); }
    /// Where the value of `key` begins, or the table's place when the key is absent.
    SourcePlace valuePlace(std::string_view key) const;

    /// A finite number within `range`.
    std::optional<double> number(std::string_view key, NumberRange range = NumberRange::any(),
                                 Need need = Need::optional);
    /// A whole number within [min, max].
    std::optional<std::int64_t> integer(std::string_view key, std::int64_t min, std::int64_t max,
                                        Need need = Need::optional);
    /// An [x, y] pair of finite numbers.
    std::optional<Vec2> vec2(std::string_view key, Need need = Need::optional);
    /// As vec2, and both coordinates must lie in `range` (NumberRange::coordinate() for positions).
    std::optional<Vec2> vec2(std::string_view key, NumberRange range, Need need = Need::optional);
    /// Either one number, used for both x and y, or an [x, y] pair.
    std::optional<Vec2> numberOrVec2(std::string_view key, NumberRange range, Need need = Need::optional);
    /// A string.
    std::optional<std::string> string(std::string_view key, Need need = Need::optional);
    /// true or false.
    std::optional<bool> boolean(std::string_view key, Need need = Need::optional);
    /// A string that must be one of `names`; returns its index in `names`.
    std::optional<std::size_t> choice(std::string_view key, std::span<const std::string_view> names,
                                      Need need = Need::optional);
    /// A nested table such as `bounds = { min = [..], max = [..] }`; `shape` shows how to write it.
    const toml::table* table(std::string_view key, std::string_view shape, Need need = Need::optional);
    /// The tables of an array of tables such as [[circle]]; none when the key is absent.
    std::vector<const toml::table*> arrayOfTables(std::string_view key);

    /// Reports an error about this table's contents.
    void error(SourcePlace place, std::string message);
    /// The diagnostics this reader reports to.
    Diagnostics& diagnostics() { return diag_; }

private:
    const toml::table& table_;
    std::string where_;
    Diagnostics& diag_;
    std::span<const KeyRename> renamed_;
};

} // namespace rube::game
