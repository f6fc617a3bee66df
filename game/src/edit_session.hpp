#pragma once
/// EditSession: `rube edit`, a level made or changed in a window. Every part kind can be placed,
/// without limit, moved, turned and deleted; placement zones are drawn; a part marked as the
/// player's (P) is saved as a placement of the solution script and counted into the inventory,
/// with spares (I, K);
/// T makes the target (or bucket) under the cursor the goal (again on its target: every target),
/// Up and Down its time limit, O types its text; V fits
/// the view to the parts, C shows more of the world to drag a view anywhere (the wheel zooms); E
/// types a part's own keys (a plank's length, a cannon's speed), checked by the level reader, and
/// the player's parts keep theirs in the solution's [[place]]; H types a hint, J picks
/// one to change (Enter) or remove (Delete); L links a switch to what it triggers; Space tries the level in a
/// PlaySession and R or Esc comes back; Ctrl+S saves the level (level_writer) and
/// NAME.solution.toml beside it. Edits are undone with the play window's EditHistory. Like
/// PlaySession it sees the window only as an InputListener and a DrawList.

#include "edit_history.hpp"
#include "edit_text_field.hpp"
#include "inventory_bar.hpp"
#include "level_view.hpp"
#include "play_session.hpp"

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rube::game {

class EditSession final : public render::InputListener {
public:
    /// Edits `level`, saved to `file` (and NAME.solution.toml beside it), in a window whose level
    /// area is `levelFrame` pixels. `solution`: the player's parts as a solution script gave them.
    EditSession(SceneDesc level, std::filesystem::path file, render::FrameSize levelFrame,
                const std::vector<Placement>& solution = {});
    /// A new level: a floor, the world's defaults, a view 16 m wide.
    static SceneDesc newLevel(const std::string& name);

    void cursorMoved(float x, float y) override;
    void mouseButton(render::MouseButton button, bool pressed) override;
    void scrolled(float notches) override;
    void key(render::Key key, render::KeyAction action) override;
    void typed(char32_t codePoint) override;

    void draw(render::DrawList& list) const;
    render::FrameSize windowSize() const { return bar_.windowSize(); }
    const render::Camera& windowCamera() const { return trying_ ? trying_->windowCamera() : bar_.windowCamera(); }
    render::Point pixelOf(Vec2 world) const { return bar_.toPixel(world); }
    /// Lets real time pass in the level being tried.
    void advance(double seconds);

    /// Writes the level and its solution script, and says on the bar at which step the solution
    /// reaches the goal and whether it still does with each part moved one grid step either way.
    /// False, with the reason on the bar, when the level would not read back or a file could not be
    /// written.
    bool save();

    /// The kind a click places (Tab cycles through every kind).
    ItemKind selectedKind() const { return allPartKinds()[selected_]; }
    /// True while C's drag draws the level's view over a wider part of the world.
    bool drawingView() const { return viewMode_; }
    /// The level as it stands (the fixed parts; the player's are in playerParts()).
    const SceneDesc& level() const { return state_.level; }
    /// The parts marked as the player's, as placements.
    const std::vector<Placement>& playerParts() const { return state_.players; }
    /// The inventory the level is saved with: the player's parts and the spares (I adds, K takes).
    std::map<std::string, int, std::less<>> inventory() const { return savedLevel().level.inventory; }
    /// The level being tried (Space), or nullptr while editing.
    const PlaySession* trying() const { return trying_.get(); }
    PlaySession* trying() { return trying_.get(); }
    const std::string& message() const { return message_; }
    bool quitRequested() const { return quit_; }
    std::size_t undoable() const { return history_.undoable(); }

private:
    struct State {
        SceneDesc level;
        std::vector<Placement> players;
        std::map<std::string, int, std::less<>> spare; // inventory beyond the player's parts (I, K)
    };
    /// What the cursor is on: a fixed item, a player's part or a zone (index), or nothing.
    struct Hit {
        enum class What { none, item, player, zone } what = What::none;
        std::size_t index = 0;
    };

    Hit hitAtCursor() const;
    SceneDesc savedLevel() const;
    std::string nameFor(ItemKind kind) const;
    void say(std::string text, const char* colour = "hud_text");
    void edit(); // before each change: remembered for Ctrl+Z
    void moveDragged();
    void turnAtCursor(double degrees);
    void removeAtCursor();
    void markAtCursor();
    void goalAtCursor();
    void sayGoal();
    void typeGoalText();
    void editKeysAtCursor();
    /// Keys of a part and what was typed for each (TOML values, or words taken as strings).
    using KeyValues = std::vector<std::pair<std::string_view, std::string>>;
    void editKey(Hit part, std::size_t keyIndex, char skip, KeyValues typed);
    /// Sets the own keys of a part (fixed or the player's) to what was typed ("" puts a key back to
    /// its default). False, with the level reader's message on the bar, when it would not read so.
    bool setKeys(Hit part, const KeyValues& values);
    /// A part as an item, its own keys as lines (a player's part too).
    ItemDesc partOf(const Hit& hit) const;
    /// A player's part keeps `item`'s own keys and parameters, as a script's [[place]] holds them.
    static void markOwnKeys(Placement& p, const ItemDesc& item);
    std::string holdsWhenMoved(const SceneDesc& level, const ScriptDesc& script, std::int64_t steps) const;
    void tryIt();
    void changeSpare(int by);
    void fitView();
    void toggleViewMode();
    void setView(const Aabb& box);
    void linkAtCursor();
    void addHint();
    void pickHint(std::size_t index);
    void changeHint(std::size_t index);
    void removeHint(std::size_t index);
    /// Opens the bar's text field: `accept` gets the text on Enter, `next` gets it on Tab (none:
    /// Tab is ignored). `skip`: the character the opening key types.
    void ask(std::string prompt, std::string text, char skip, std::function<void(const std::string&)> accept,
             std::function<void(const std::string&)> next = {});
    void fieldKey(render::Key key, render::KeyAction action);
    void refreshCamera();
    std::optional<std::pair<std::size_t, int>> zoneCornerAtCursor() const;

    State state_;
    std::filesystem::path file_;
    InventoryBar bar_;
    LevelView view_;
    EditHistory<State> history_;
    std::size_t selected_ = 0;
    render::Point cursor_;
    Vec2 cursorWorld_;
    std::optional<Hit> dragging_; // an item or player's part being moved
    Vec2 dragOffset_;             // from the cursor to the dragged part's position
    bool zoneMode_ = false;       // Z: a drag draws a zone
    bool viewMode_ = false;       // C: a drag draws the level's [view], over a wider part of the world
    Aabb wideView_;               // what the window shows meanwhile
    std::optional<Vec2> zoneStart_;                       // where a drag drawing a zone (or the view) began
    std::optional<std::pair<std::size_t, int>> resizing_; // a zone and its corner (0-3) being dragged
    bool control_ = false;
    struct Field {
        TextField text;
        std::function<void(const std::string&)> accept;
        std::function<void(const std::string&)> next; // Tab, with what is typed
    };
    std::optional<Field> field_;            // the bar's text field while something is typed
    std::optional<std::size_t> hintPicked_; // J: the hint Enter changes and Delete removes, until another key
    bool quit_ = false;
    std::string message_;
    render::Color messageColor_;
    std::unique_ptr<PlaySession> trying_;
};

} // namespace rube::game
