// libFuzzer target: the playthrough script parser, against the first level (ramp). Any bytes must
// give a script or one-line errors, never a crash; a script that loads must write back to a script
// that loads (and writes the same text again), and play a few steps.
#include "level_run.hpp"
#include "scene_file.hpp"
#include "script_file.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
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
    // What the writer makes of a script that loaded must load too, and write again to the same text.
    const std::string written = rube::game::writeScript(*load.script);
    const rube::game::ScriptLoad again = rube::game::parseScript(written, "fuzz.written.toml", level());
    if (!again.script || rube::game::writeScript(*again.script) != written) __builtin_trap();
    // A script that loaded has placements that passed every rule: playing them must not crash.
    if (rube::game::checkPlacements(level(), load.script->placements)) return 0;
    rube::game::LevelRun run(level(), load.script->placements);
    for (int i = 0; i < 20; ++i) run.step();
    return 0;
}
