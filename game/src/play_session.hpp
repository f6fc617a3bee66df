#pragma once
/// PlaySession: one player at one level, as `rube play` shows it in a window. It holds the
/// editing state (items placed from the inventory, cannon aims), runs the machine, and remembers
/// it all as a script that `rube run` replays off-screen. It sees the window only as an
/// InputListener and a DrawList, so a test drives it with made-up events exactly as GLFW would.
/// Its members are defined by responsibility: play_session.cpp (state, running, the script),
/// play_input.cpp, play_editing.cpp and play_drawing.cpp.

#include "debug_overlays.hpp"
#include "inventory_bar.hpp"
#include "level_run.hpp"
#include "level_view.hpp"
#include "script_file.hpp"

#include "rube/render/window_input.hpp"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rube::game {

class PlaySession final : public render::InputListener {
public:
    /// Editing or running the machine.
    enum class Mode { editing, running };

    /// A session at `level` (read from `levelPath`, named in the recorded script), drawn into a
    /// window whose level area is `levelFrame` pixels with the inventory bar below it.
    PlaySession(SceneDesc level, std::string levelPath, render::FrameSize levelFrame);

    /// Starts from a script: its placements; its step-0 aims and rotations as the cannons' aims
    /// (which the player may change); and its other actions, taken at their frames in every run
    /// (and recorded like the player's own).
    void load(const ScriptDesc& script);

    // The window's input (render::InputListener). Each is also how a test plays.
    void cursorMoved(float x, float y) override;
    void mouseButton(render::MouseButton button, bool pressed) override;
    void scrolled(float notches) override;
    void key(render::Key key, render::KeyAction action) override;

    /// Starts the machine from the editing state (Space), as the placements and aims stand.
    void start();
    /// Back to editing with every placement and aim kept (R); the run and its actions are dropped.
    void reset();
    /// Lets `seconds` of real time pass: while running and not paused, takes the steps due at the
    /// level's time step (a tenth as many in slow motion), at most a few per call so a slow
    /// machine slows down rather than stalls. The simulation itself never reads a clock.
    void advance(double seconds);
    /// Takes one step now, if the machine runs (paused or not): for fixed pacing and tests.
    void step();

    /// Fills `list` with the window's frame: the level as `rube run` draws it (with the zones,
    /// the item being dragged and the hovered item while editing), then the inventory bar.
    void draw(render::DrawList& list) const;

    /// The whole window's size: the level area and the bar below it.
    render::FrameSize windowSize() const { return bar_.windowSize(); }
    /// The level area's size: the frames `rube run` writes for the recorded script.
    render::FrameSize levelFrame() const { return bar_.levelFrame(); }
    /// The camera the whole window is drawn through.
    const render::Camera& windowCamera() const { return bar_.windowCamera(); }
    /// Where a world point lands in the window, pixels from the top-left (what cursorMoved takes).
    render::Point pixelOf(Vec2 world) const;
    /// The centre of the bar's slot for `kind`, pixels from the top-left; nothing if the level has none.
    std::optional<render::Point> slotPixel(ItemKind kind) const { return bar_.slotCentre(kind); }

    Mode mode() const { return run_ ? Mode::running : Mode::editing; }
    bool paused() const { return paused_; }
    bool slowMotion() const { return slow_; }
    bool trailsShown() const { return showTrails_; }
    /// True once the player asked to quit (Escape).
    bool quitRequested() const { return quit_; }
    /// The items placed so far, in the order they were placed.
    const std::vector<Placement>& placements() const { return placements_; }
    /// How many of `kind` are left to place.
    int remaining(ItemKind kind) const;
    /// The running machine, or nullptr while editing.
    const LevelRun* run() const { return run_.get(); }
    /// Actions taken in the present run, in order.
    const std::vector<Action>& actions() const { return actions_; }
    /// The bar's message line: why a placement was refused, what was done, or the goal's state.
    const std::string& message() const { return message_; }

    /// The session as a playthrough script: the placements, the aims as step-0 actions, the
    /// actions of the present (or last) run at their frames, and, if the goal was reached, an
    /// expectation that it is reached again. `rube run LEVEL --script FILE` replays it.
    std::string recordedScript() const;

private:
    struct Drag {
        Placement placement;
        std::optional<std::size_t> liftedFrom; // the index it held before the player picked it up
        Placement original;                    // and where it was then
        std::optional<PlacementRefusal> refusal;
    };

    void rebuildPreview();
    void updateDrag();
    void drop();
    void turn(double degrees);
    void removeAt(std::size_t index);
    void aimAtCursor();
    void useItemAtCursor();
    int placedItemAtCursor() const;
    int levelItemAtCursor(bool (*fits)(ItemKind)) const;
    void takeByHand(ActionKind kind, int item);
    void takeScripted();
    void say(std::string text, const char* colour = "hud_text");
    void drawEditing(render::DrawList& list) const;

    SceneDesc level_;
    std::string levelPath_;
    InventoryBar bar_;
    LevelView view_;
    std::vector<Placement> placements_;
    std::map<int, Action> aims_;        // cannon item -> its step-0 aim, set while editing
    std::unique_ptr<LevelRun> preview_; // the machine at step 0, as placed (editing)
    std::unique_ptr<LevelRun> run_;     // the machine running
    std::vector<Action> actions_;       // taken in the present run, by hand or from a loaded script
    std::vector<Action> scripted_;      // a loaded script's actions other than its step-0 aims
    std::size_t nextScripted_ = 0;      // the first of them not yet taken in this run
    std::optional<Drag> drag_;
    int aiming_ = -1;      // the cannon being aimed by dragging, or -1
    render::Point cursor_; // pixels from the top-left
    Vec2 cursorWorld_;
    std::string message_;
    render::Color messageColor_;
    bool paused_ = false;
    bool slow_ = false;
    bool showTrails_ = false;
    std::unique_ptr<Trails> trails_;
    double owedSeconds_ = 0.0;
    bool quit_ = false;
};

} // namespace rube::game
