// `rube check`: every error of every file, so a level designer fixes them in one pass.
#include "check_command.hpp"

#include "scene_file.hpp"

#include <ostream>

namespace rube::game {

ExitCode checkScenes(std::span<const std::string> files, std::ostream& out, std::ostream& err) {
    ExitCode status = ExitCode::ok;
    for (const std::string& file : files) {
        const SceneLoad load = loadSceneFile(file);
        if (load.ok()) {
            out << file << ": ok\n";
            continue;
        }
        for (const SceneError& error : load.errors) err << error.format() << '\n';
        status = ExitCode::badInput;
    }
    return status;
}

} // namespace rube::game
