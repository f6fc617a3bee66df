#pragma once
/// LevelView: a level in play as a DrawList. Each item kind has its own greybox look, cannons
/// show their aim and the arc a shot would take, projectiles point along their velocity,
/// explosions expand as rings, and the HUD says how the goal stands.

#include "level_run.hpp"

#include "rube/render/camera.hpp"
#include "rube/render/draw_list.hpp"

#include <string>
#include <vector>

namespace rube::game {

/// What a level's frames show beyond the game's own look (`rube run --labels`, `--zones`).
struct LevelViewOptions {
    bool labels = false; ///< each named item's name beside it
    bool zones = false;  ///< the placement zones, as the play window shows them while editing
};

/// The placement zones of `level` as the play window shows them: translucent green boxes.
void drawZones(const LevelDesc& level, render::DrawList& list);

/// `text` broken at spaces into lines at most `width` pixels wide at `scale`, at most `maxLines` of
/// them; when it does not fit, the last line is cut short and ends in "...".
std::vector<std::string> wrapText(const std::string& text, int width, int scale, int maxLines);

/// Draws one level run, frame after frame, through a camera fixed for the whole run.
class LevelView {
public:
    /// A view named `levelName` in the HUD, through `camera` into frames of `frame` pixels.
    LevelView(std::string levelName, render::Camera camera, render::FrameSize frame, LevelViewOptions options = {});

    /// Clears `list` and fills it with the run as it is now, after `step` steps (the HUD shows it).
    void draw(const LevelRun& run, std::int64_t step, render::DrawList& list) const;
    /// The HUD's goal line: the goal's text and whether it is reached.
    std::string goalLine(const LevelRun& run) const;
    /// The HUD's goal line as drawn: wrapped to the frame's width, at most two lines.
    std::vector<std::string> goalLines(const LevelRun& run) const;
    /// The camera every frame is drawn through.
    const render::Camera& camera() const { return camera_; }

private:
    void drawBodies(const LevelRun& run, render::DrawList& list) const;
    void drawItems(const LevelRun& run, render::DrawList& list) const;
    void drawHud(const LevelRun& run, std::int64_t step, render::DrawList& list) const;
    void drawLabels(const LevelRun& run, render::DrawList& list) const;

    std::string levelName_;
    render::Camera camera_;
    render::FrameSize frame_;
    LevelViewOptions options_;
};

} // namespace rube::game
