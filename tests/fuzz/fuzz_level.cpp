// libFuzzer target: the scene and level parser. Any bytes must give either a scene or one-line
// errors with a position, never a crash, a hang or an exception escaping.
#include "scene_file.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const rube::game::SceneLoad load = rube::game::parseScene(text, "fuzz.toml");
    // Either it loaded, or it says why: a failure with no message would leave an author guessing.
    if (!load.ok() && load.errors.empty()) __builtin_trap();
    for (const auto& error : load.errors)
        if (error.format().find('\n') != std::string::npos) __builtin_trap(); // one line each
    return 0;
}
