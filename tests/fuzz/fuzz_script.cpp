// libFuzzer target: the playthrough script parser, against the first level (ramp). Any bytes must
// give a script or one-line errors, never a crash; a script that loads must also play a few steps.
#include "level_run.hpp"
#include "scene_file.hpp"
#include "script_file.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace {

const rube::game::SceneDesc& level() {
    static const rube::game::SceneDesc scene = [] {
        const rube::game::SceneLoad load = rube::game::loadSceneFile(RUBE_FUZZ_LEVEL);
        if (!load.ok()) __builtin_trap();
        return *load.scene;
    }();
    return scene;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const rube::game::ScriptLoad load = rube::game::parseScript(text, "fuzz.solution.toml", level());
    if (!load.script) {
        if (load.errors.empty()) __builtin_trap();
        return 0;
    }
    // A script that loaded has placements that passed every rule: playing them must not crash.
    if (rube::game::checkPlacements(level(), load.script->placements)) return 0;
    rube::game::LevelRun run(level(), load.script->placements);
    for (int i = 0; i < 20; ++i) run.step();
    return 0;
}
