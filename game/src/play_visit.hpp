#pragma once
/// PlayVisit: everything one `rube play` does in its window, from the level list (no LEVEL given)
/// through the levels played, one after another with N, to the end. It passes the window's input
/// to the screen shown (the list or a PlaySession), keeps the progress file, and ends a session on
/// Escape (back to the list, if it came from there), N, --quit-after or the window's closing. The
/// window loop (play_window.cpp) only paces it; a test drives it with made-up events.

#include "level_select.hpp"
#include "play_session.hpp"
#include "progress.hpp"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace rube::game {

/// How a visit plays: the options of `rube play` it needs.
struct VisitOptions {
    render::FrameSize levelFrame{1280, 720}; ///< each level's area; the window adds the bar
    bool runAtOnce = false;                  ///< start each level's machine at once (--run)
    std::optional<std::int64_t> quitAfter;   ///< end the visit when a run has taken this many steps
    int stepsPerFrame = 0;                   ///< fixed pace per tick(); 0 follows real time
    std::filesystem::path progressFile;      ///< where solved levels are kept (empty: not kept)
};

/// A level as the visit opens it.
struct VisitLevel {
    SceneDesc scene;
    std::filesystem::path file;
    std::optional<ScriptDesc> script; ///< --script, for the level given on the command line
};

/// How one level's session ended, for the summary: the session itself, and whether the window
/// drew it while running (counted by the window loop).
using SessionEnded = std::function<void(const PlaySession& session, const SceneDesc& level)>;

class PlayVisit final : public render::InputListener {
public:
    /// A visit that starts at `first` if given, else at the list of `index`. Each session's end
    /// is reported to `ended`; a level of the index that does not load to `failedLevel` (its error).
    PlayVisit(std::vector<IndexedLevel> index, std::optional<VisitLevel> first, VisitOptions options,
              SessionEnded ended, std::function<void(const std::string&)> failedLevel);

    void cursorMoved(float x, float y) override;
    void mouseButton(render::MouseButton button, bool pressed) override;
    void scrolled(float notches) override;
    void key(render::Key key, render::KeyAction action) override;

    /// One frame's worth: `seconds` of real time pass in the level played (or stepsPerFrame steps),
    /// then the screens change as the player asked (a level chosen, Escape, N, --quit-after).
    void tick(double seconds);
    /// The window is closing: the level played ends (and is reported).
    void close();
    /// Fills `list` with the screen shown.
    void draw(render::DrawList& list) const;
    /// The camera the screen shown is drawn through.
    render::Camera camera() const;
    /// The window's size: a level area and the bar.
    render::FrameSize windowSize() const;

    /// True when the visit is over: Escape on the list (or in a level given on the command line),
    /// --quit-after, or a level that would not load.
    bool finished() const { return finished_; }
    /// True when --quit-after ended it.
    bool quitAfterReached() const { return quitAfterReached_; }
    /// The level being played, or nullptr while the list is shown.
    const PlaySession* session() const { return session_.get(); }
    PlaySession* session() { return session_.get(); }
    /// The list, or nullptr while a level is played.
    const LevelSelect* list() const { return list_.get(); }
    /// The file of the level played (or last played).
    const std::filesystem::path& levelFile() const { return levelFile_; }
    /// The progress as kept so far.
    const Progress& progress() const { return progress_; }
    /// The last session's recording, "" when no level was played.
    const std::string& lastRecording() const { return recording_; }
    /// True when the last level played ended with a run that missed its goal (exit status 1).
    bool lastRunFailed() const { return lastRunFailed_; }

private:
    render::InputListener* screen();
    void open(VisitLevel level, std::optional<std::size_t> at);
    void openIndexed(std::size_t at);
    void showList(std::size_t selected);
    void endSession();

    std::vector<IndexedLevel> index_;
    VisitOptions options_;
    SessionEnded ended_;
    std::function<void(const std::string&)> failedLevel_;
    Progress progress_;
    std::unique_ptr<LevelSelect> list_;
    std::unique_ptr<PlaySession> session_;
    SceneDesc level_; // the level of session_
    std::filesystem::path levelFile_;
    std::optional<std::size_t> at_; // where the level played stands in the index
    bool fromList_ = false;         // Escape in a level goes back to the list
    bool finished_ = false;
    bool quitAfterReached_ = false;
    bool lastRunFailed_ = false;
    std::string recording_;
};

} // namespace rube::game
