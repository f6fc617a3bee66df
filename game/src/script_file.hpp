#pragma once
/// Script files (levels/NAME.solution.toml): a scripted playthrough of one level — the player's
/// placements, actions at given steps, expectations about what must happen, and capture settings.
/// A step is one step of the simulation; a frame is a written picture ([capture] every = K steps).

#include "level_run.hpp"

#include "rube/render/camera.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rube::game {

/// What an action does.
enum class ActionKind : std::uint8_t { rotate, aim, fire, detonate, toggle, fireWhen, cut };

/// One action, taken when the run has taken `step` steps (before the next one).
struct Action {
    std::int64_t step = 0; ///< steps taken before it happens
    ActionKind kind = ActionKind::fire;
    std::string item;            ///< the cannon, bomb or switch it acts on, or the rope it cuts
    std::optional<double> angle; ///< rotate, aim: radians
    double angleDegrees = 0.0;   ///< rotate, aim: the angle as the script wrote it, in degrees
    std::optional<Vec2> point;   ///< aim: a point to hit
    std::string target;          ///< aim: an item to hit (led when it moves); fire-when: the item to time the shot at
    bool highArc = false;        ///< aim at a point or item: the lobbed arc
    SourcePlace place;           ///< where the script wrote it
};

/// An assertion about the run: an event must happen before a step.
struct Expectation {
    EventKind kind = EventKind::goal; ///< hit, shot, explosion or goal
    std::string item;                 ///< the target, cannon or bomb (empty for the goal)
    std::string by;                   ///< hit, goal: what must do it (GameEvent::by), empty for anything
    std::int64_t beforeStep = 0;      ///< it must happen with fewer steps taken than this
    SourcePlace place;                ///< where the script wrote it
    /// "'flag' hit by 'ball' before step 600".
    std::string describe() const;
};

/// A whole script, validated against its level.
struct ScriptDesc {
    std::string level;                     ///< the level's name it plays
    std::optional<std::int64_t> steps;     ///< how long to run, else the level's time limit or duration
    std::optional<render::FrameSize> size; ///< [capture] size of the frames
    std::optional<std::int64_t> every;     ///< [capture] steps between frames
    std::vector<Placement> placements;     ///< [[place]] in file order
    std::vector<Action> actions;           ///< [[action]] sorted by step, file order within a step
    std::vector<Expectation> expectations; ///< [[expect]] in file order
};

/// Degrees as a script writes them, in radians: the one conversion every reader of angles uses,
/// so an angle written back out in degrees (a recorded session) replays to the same radians.
double scriptRadians(double degrees);

/// The word a script's `do` spells an action kind with ("fire-when", "cut", ...).
std::string_view actionVerb(ActionKind kind);

/// Takes one action on a run (the names were checked when the script was read); "" or why it
/// could not be done, such as an aim at a point out of the cannon's reach.
std::string takeAction(const Action& action, LevelRun& run);

/// The outcome of loading a script: a script when there are no errors, else the errors by place.
struct ScriptLoad {
    std::optional<ScriptDesc> script; ///< present exactly when there are no errors
    std::vector<SceneError> errors;   ///< every error found, top of the file first
};

/// Reads a script for `level`, checking every name it uses against the level and its placements;
/// the placements' rules (inventory, zones, overlaps) are checked here too.
ScriptLoad loadScriptFile(const std::filesystem::path& file, const SceneDesc& level);

/// The same from text; `fileName` is what errors are reported under.
ScriptLoad parseScript(std::string_view text, const std::string& fileName, const SceneDesc& level);

/// The shortest decimal that reads back as the same double (std::to_chars' promise), so a written
/// position or angle replays bit for bit: 0.3, not 0.30000000000000004; -0.0 keeps its sign.
std::string scriptNumber(double value);

/// `script` as a script file that parseScript() reads back to the same script (source places
/// aside): `level`, `steps`, [capture], then every [[place]], [[action]] and [[expect]] in order.
/// Angles are written in the degrees the script was read or recorded in. `header` (comment lines,
/// each ending in a newline) comes first.
std::string writeScript(const ScriptDesc& script, std::string_view header = {});

} // namespace rube::game
