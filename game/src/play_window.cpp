// The play window's loop: poll input (through present()), advance the session by the time that
// passed, draw it, present it. The wall clock paces the loop only; the simulation steps by count.
#include "play_window.hpp"

#include "play_session.hpp"
#include "scene_errors.hpp"
#include "scene_file.hpp"

#include "rube/render/renderer.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <ostream>

namespace rube::game {

namespace {

std::string noWindowAdvice(const PlayOptions& options) {
    return "render it off-screen with 'rube run " + options.level +
           " --script FILE --out DIR', or give it a virtual display with 'xvfb-run rube play " + options.level + "'";
}

bool hasDisplay() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

} // namespace

ExitCode playInWindow(const PlayOptions& options, std::ostream& out, std::ostream& err) {
    const SceneLoad load = loadSceneFile(options.level);
    if (!load.ok()) {
        err << load.errors.front().format() << '\n';
        return ExitCode::badInput;
    }
    const SceneDesc& level = *load.scene;
    if (!level.level.isLevel()) {
        err << "rube play: " << options.level
            << " is a physics scene, not a level (it has no items, inventory or goal): watch it with 'rube run "
            << options.level << " --out DIR'\n";
        return ExitCode::badInput;
    }
    std::optional<ScriptDesc> script;
    if (!options.script.empty()) {
        ScriptLoad loaded = loadScriptFile(options.script, level);
        if (!loaded.script) {
            err << loaded.errors.front().format() << '\n';
            return ExitCode::badInput;
        }
        script = std::move(loaded.script);
    }
    if (!options.record.empty()) {
        const std::filesystem::path folder = std::filesystem::absolute(options.record).parent_path();
        if (!std::filesystem::is_directory(folder)) {
            err << "rube play: --record " << options.record << ": the folder " << folder.string()
                << " does not exist\n";
            return ExitCode::badInput;
        }
        if (std::filesystem::is_directory(options.record)) {
            err << "rube play: --record " << options.record << ": is a folder; give a file name such as play.toml\n";
            return ExitCode::badInput;
        }
    }
    if (!hasDisplay()) {
        err << "rube play: no display (DISPLAY is not set): " << noWindowAdvice(options) << '\n';
        return ExitCode::failed;
    }

    PlaySession session(level, options.level, options.size);
    if (script) session.load(*script);
    std::unique_ptr<render::RenderContext> window;
    try {
        render::WindowOptions windowOptions;
        windowOptions.title = "rube: " + level.name;
        windowOptions.vsync = options.vsync;
        window = render::createWindowContext(session.windowSize(), windowOptions);
    } catch (const std::exception& e) {
        err << "rube play: cannot open a window (" << e.what() << "): " << noWindowAdvice(options) << '\n';
        return ExitCode::failed;
    }
    std::int64_t framesDrawn = 0;
    std::int64_t framesRunning = 0;
    double runningSeconds = 0.0; // from the first frame drawn while running to the last

    {
        render::Renderer renderer(*window);
        window->setInputListener(&session);
        if (options.runAtOnce) session.start();
        render::DrawList list;
        using Clock = std::chrono::steady_clock;
        Clock::time_point last = Clock::now();
        Clock::time_point firstRunning;
        while (!window->closeRequested() && !session.quitRequested()) {
            const Clock::time_point now = Clock::now();
            const double seconds = std::chrono::duration<double>(now - last).count();
            last = now;
            const bool running = session.mode() == PlaySession::Mode::running;
            if (running && options.quitAfter && framesRunning >= *options.quitAfter) break;
            if (options.stepsPerFrame > 0) {
                if (running && !session.paused())
                    for (int i = 0; i < options.stepsPerFrame; ++i) session.step();
            } else {
                session.advance(seconds);
            }
            session.draw(list);
            renderer.draw(list, session.windowCamera());
            window->present(); // input arrives here, through the session's handlers
            ++framesDrawn;
            if (running) {
                if (framesRunning++ == 0) firstRunning = Clock::now();
                runningSeconds = std::chrono::duration<double>(Clock::now() - firstRunning).count();
            }
        }
        window->setInputListener(nullptr);
    }
    window.reset();

    out << "level:            " << level.name << '\n';
    out << "placements:       " << session.placements().size() << '\n';
    out << "window frames:    " << framesDrawn << " (" << framesRunning << " while running)\n";
    if (framesRunning > 1 && runningSeconds > 0.0) {
        char text[64];
        std::snprintf(text, sizeof text, "%.1f fps while running",
                      static_cast<double>(framesRunning - 1) / runningSeconds);
        out << "frame rate:       " << text << '\n';
    }
    if (const LevelRun* run = session.run()) {
        out << "steps:            " << run->steps() << '\n';
        out << "goal:             "
            << (run->goalStep() ? "reached at step " + std::to_string(*run->goalStep()) : std::string("not reached"))
            << '\n';
    }
    if (!options.record.empty()) {
        if (std::string reason; !writeTextFileAtomically(options.record, session.recordedScript(), reason)) {
            err << "rube play: cannot write " << options.record << ": " << reason << '\n';
            return ExitCode::failed;
        }
        out << "recorded:         " << options.record << " (replay: rube run " << options.level << " --script "
            << options.record << " --out DIR)\n";
    }
    return ExitCode::ok;
}

} // namespace rube::game
