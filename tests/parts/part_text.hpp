#pragma once
// What the parts' tests share to write levels as text and read their first error.
#include "scene_file.hpp"

#include <cstdio>
#include <string>

namespace rube::test {

/// `v` as a TOML number that reads back as the same double.
inline std::string num(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

/// The first error reading `text` as t.toml gives, formatted, or "no error".
inline std::string firstError(const std::string& text) {
    const game::SceneLoad load = game::parseScene(text, "t.toml");
    return load.errors.empty() ? std::string("no error") : load.errors.front().format();
}

} // namespace rube::test
