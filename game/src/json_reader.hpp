#pragma once
/// A small JSON reader for the files rube writes itself (`rube solve --json`, read back by
/// `--merge`): objects, arrays, strings, numbers, true, false and null. Numbers keep their text, so
/// an integer past 2^53 reads back exactly.

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rube::game {

/// One JSON value.
struct JsonValue {
    enum class Type { null, boolean, number, string, array, object };
    Type type = Type::null;
    bool boolean = false;
    std::string text;                        ///< a string's characters, or a number as written
    std::vector<JsonValue> array;            ///< in order
    std::map<std::string, JsonValue> object; ///< by key

    /// The member `key` of an object, or nullptr.
    const JsonValue* find(std::string_view key) const;
};

/// The value of `text`, or nothing with `error` set to "line:col: message".
std::optional<JsonValue> parseJson(std::string_view text, std::string& error);

/// `text` as a JSON string, quoted and escaped.
std::string jsonString(std::string_view text);

} // namespace rube::game
