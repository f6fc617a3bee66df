#pragma once
// Scene text for the scene-file tests: a file's errors as file:line:col: message under the name
// "s.toml", its one error, or the scene it reads into.
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace test {

// The errors of `text`, each as file:line:col: message, under the file name "s.toml".
inline std::vector<std::string> errorsOf(std::string_view text) {
    std::vector<std::string> lines;
    for (const rube::game::SceneError& e : rube::game::parseScene(text, "s.toml").errors) lines.push_back(e.format());
    return lines;
}

// The one error of `text`; fails when there are none or several.
inline std::string errorOf(std::string_view text) {
    const auto errors = errorsOf(text);
    INFO("errors: " << errors.size() << (errors.empty() ? "" : ", first: " + errors.front()));
    REQUIRE(errors.size() == 1);
    return errors.front();
}

inline rube::game::SceneDesc sceneOf(std::string_view text) {
    rube::game::SceneLoad load = rube::game::parseScene(text, "s.toml");
    INFO((load.errors.empty() ? std::string("no errors") : load.errors.front().format()));
    REQUIRE(load.ok());
    return std::move(*load.scene);
}

} // namespace test
