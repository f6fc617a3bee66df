// The editor's window loop, as the play window's: poll input, let the level being tried run, draw.
#include "edit_window.hpp"

#include "edit_session.hpp"
#include "play_window.hpp"
#include "scene_file.hpp"

#include "rube/render/renderer.hpp"

#include <chrono>
#include <filesystem>
#include <ostream>

namespace rube::game {

ExitCode editInWindow(const EditOptions& options, std::ostream& out, std::ostream& err) {
    const std::filesystem::path file = !options.out.empty()     ? options.out
                                       : !options.level.empty() ? options.level
                                                                : "new-level.toml";
    if (file.extension() != ".toml") {
        err << "rube edit: --out " << file.string() << ": a level file ends in .toml\n";
        return ExitCode::badInput;
    }
    if (const std::filesystem::path folder = std::filesystem::absolute(file).parent_path();
        !std::filesystem::is_directory(folder)) {
        err << "rube edit: " << file.string() << ": the folder " << folder.string() << " does not exist\n";
        return ExitCode::badInput;
    }
    SceneDesc level = EditSession::newLevel(file.stem().string());
    std::vector<Placement> solution;
    if (!options.level.empty()) {
        const SceneLoad load = loadSceneFile(options.level);
        if (!load.ok()) {
            err << load.errors.front().format() << '\n';
            return ExitCode::badInput;
        }
        level = *load.scene;
        std::filesystem::path script = options.level;
        script.replace_extension(".solution.toml");
        if (std::filesystem::is_regular_file(script)) {
            const ScriptLoad loaded = loadScriptFile(script, level);
            if (!loaded.script) {
                err << loaded.errors.front().format() << '\n';
                return ExitCode::badInput;
            }
            solution = loaded.script->placements;
        }
    }
    if (!hasDisplay()) {
        err << "rube edit: no display (DISPLAY is not set): give it a virtual display with 'xvfb-run rube edit'\n";
        return ExitCode::failed;
    }
    EditSession session(std::move(level), file, options.size, solution);
    std::unique_ptr<render::RenderContext> window;
    try {
        render::WindowOptions windowOptions;
        windowOptions.title = "rube edit: " + file.string();
        window = render::createWindowContext(session.windowSize(), windowOptions);
    } catch (const std::exception& e) {
        err << "rube edit: cannot open a window (" << e.what() << ")\n";
        return ExitCode::failed;
    }
    {
        render::Renderer renderer(*window);
        window->setInputListener(&session);
        render::DrawList list;
        using Clock = std::chrono::steady_clock;
        Clock::time_point last = Clock::now();
        while (!window->closeRequested() && !session.quitRequested()) {
            const Clock::time_point now = Clock::now();
            session.advance(std::chrono::duration<double>(now - last).count());
            last = now;
            session.draw(list);
            renderer.draw(list, session.windowCamera());
            window->present();
        }
        window->setInputListener(nullptr);
    }
    out << "level:            " << file.string() << '\n';
    out << "last message:     " << session.message() << '\n';
    return ExitCode::ok;
}

} // namespace rube::game
