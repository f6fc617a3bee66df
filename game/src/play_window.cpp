// The play window's loop: poll input (through present()), advance the session by the time that
// passed, draw it, present it. The wall clock paces the loop only; the simulation steps by count.
// One window serves the whole visit: the level list (no LEVEL given), a level, the next level (N).
#include "play_window.hpp"

#include "inventory_bar.hpp"
#include "play_visit.hpp"
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
    const std::string level = options.level.empty() ? "LEVEL" : options.level;
    return "render it off-screen with 'rube run " + level +
           " --script FILE --out DIR', or give it a virtual display with 'xvfb-run rube play " + options.level + "'";
}

// What the window drew of one session, for its summary.
struct FrameCounts {
    std::int64_t drawn = 0;
    std::int64_t running = 0;
    double runningSeconds = 0.0; // from the first frame drawn while running to the last
};

void printSummary(const SceneDesc& level, const PlaySession& session, const FrameCounts& frames, std::ostream& out) {
    out << "level:            " << level.name << '\n';
    out << "placements:       " << session.placements().size() << '\n';
    out << "window frames:    " << frames.drawn << " (" << frames.running << " while running)\n";
    if (frames.running > 1 && frames.runningSeconds > 0.0) {
        char text[64];
        std::snprintf(text, sizeof text, "%.1f fps while running",
                      static_cast<double>(frames.running - 1) / frames.runningSeconds);
        out << "frame rate:       " << text << '\n';
    }
    if (const LevelRun* run = session.run()) {
        out << "steps:            " << run->steps() << '\n';
        out << "goal:             "
            << (run->goalStep() ? "reached at step " + std::to_string(*run->goalStep()) : std::string("not reached"))
            << '\n';
    }
}

} // namespace

bool hasDisplay() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

ExitCode playInWindow(const PlayOptions& options, std::ostream& out, std::ostream& err) {
    std::vector<IndexedLevel> index;
    if (options.level.empty()) {
        if (!options.script.empty()) {
            err << "rube play: --script needs a LEVEL: the script belongs to one level\n";
            return ExitCode::badInput;
        }
        LevelIndexLoad load = loadLevelIndex(options.index);
        if (!load.levels) {
            err << load.errors.front().format() << " (no LEVEL given, so 'rube play' lists the levels of "
                << options.index << ": give a LEVEL or --index FILE)\n";
            return ExitCode::badInput;
        }
        index = std::move(*load.levels);
    } else if (std::filesystem::is_regular_file(options.index)) {
        // Only for N (the next level): a level played on its own needs no index.
        if (LevelIndexLoad load = loadLevelIndex(options.index); load.levels) index = std::move(*load.levels);
    }

    std::optional<SceneDesc> first;
    std::optional<ScriptDesc> script;
    if (!options.level.empty()) {
        const SceneLoad load = loadSceneFile(options.level);
        if (!load.ok()) {
            err << load.errors.front().format() << '\n';
            return ExitCode::badInput;
        }
        if (!load.scene->level.isLevel()) {
            err << "rube play: " << options.level
                << " is a physics scene, not a level (it has no items, inventory or goal): watch it with 'rube run "
                << options.level << " --out DIR'\n";
            return ExitCode::badInput;
        }
        first = *load.scene;
        if (!options.script.empty()) {
            ScriptLoad loaded = loadScriptFile(options.script, *first);
            if (!loaded.script) {
                err << loaded.errors.front().format() << '\n';
                return ExitCode::badInput;
            }
            script = std::move(loaded.script);
        }
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

    std::unique_ptr<render::RenderContext> window;
    const render::FrameSize windowSize{options.size.width, options.size.height + InventoryBar::kHeight};
    try {
        render::WindowOptions windowOptions;
        windowOptions.title = first ? "rube: " + first->name : std::string("rube");
        windowOptions.vsync = options.vsync;
        window = render::createWindowContext(windowSize, windowOptions);
    } catch (const std::exception& e) {
        err << "rube play: cannot open a window (" << e.what() << "): " << noWindowAdvice(options) << '\n';
        return ExitCode::failed;
    }

    FrameCounts frames;
    ExitCode status = ExitCode::ok;
    std::optional<VisitLevel> start;
    if (first) start = VisitLevel{std::move(*first), options.level, std::move(script)};
    VisitOptions visitOptions;
    visitOptions.levelFrame = options.size;
    visitOptions.runAtOnce = options.runAtOnce;
    visitOptions.quitAfter = options.quitAfter;
    visitOptions.stepsPerFrame = options.stepsPerFrame;
    visitOptions.progressFile = Progress::defaultFile();
    PlayVisit visit(
        std::move(index), std::move(start), visitOptions,
        [&](const PlaySession& session, const SceneDesc& level) {
            printSummary(level, session, frames, out);
            frames = {};
        },
        [&](const std::string& message) {
            err << message << '\n';
            if (message.rfind("rube play: progress", 0) != 0) status = ExitCode::badInput;
        });
    {
        render::Renderer renderer(*window);
        window->setInputListener(&visit);
        render::DrawList list;
        using Clock = std::chrono::steady_clock;
        Clock::time_point last = Clock::now();
        Clock::time_point firstRunning;
        while (!visit.finished()) {
            if (window->closeRequested()) {
                visit.close();
                break;
            }
            const Clock::time_point now = Clock::now();
            visit.tick(std::chrono::duration<double>(now - last).count());
            last = now;
            if (visit.finished()) break;
            const PlaySession* session = visit.session();
            const bool running = session && session->mode() == PlaySession::Mode::running;
            visit.draw(list);
            renderer.draw(list, visit.camera());
            window->present(); // input arrives here, through the visit's handlers
            if (!session) continue;
            ++frames.drawn;
            if (running) {
                if (frames.running++ == 0) firstRunning = Clock::now();
                frames.runningSeconds = std::chrono::duration<double>(Clock::now() - firstRunning).count();
            }
        }
        window->setInputListener(nullptr);
    }
    window.reset();
    if (status == ExitCode::ok && visit.lastRunFailed()) status = ExitCode::failed;
    const std::string& recording = visit.lastRecording();
    const std::filesystem::path levelPath = visit.levelFile();

    if (!options.record.empty() && !recording.empty()) {
        if (std::string reason; !writeTextFileAtomically(options.record, recording, reason)) {
            err << "rube play: cannot write " << options.record << ": " << reason << '\n';
            return ExitCode::failed;
        }
        out << "recorded:         " << options.record << " (replay: rube run " << levelPath.string() << " --script "
            << options.record << " --out DIR)\n";
    }
    return status;
}

} // namespace rube::game
