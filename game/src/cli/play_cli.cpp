// `rube play [LEVEL]`: the window's options.
#include "command_line.hpp"

#include "play_window.hpp"

#include <cstdint>
#include <iostream>
#include <string>

namespace rube::game::cli {

namespace {

constexpr const char* kPlayFooter =
    "The window shows the level as 'rube run' draws it, with the inventory bar below.\n"
    "Levels: with no LEVEL, a list of the levels of levels/index.toml (--index FILE) in order, with\n"
    "  those solved marked; Enter or a click plays one, Esc in a level goes back to the list. Solved\n"
    "  levels are kept in $XDG_DATA_HOME/rube/solved.txt (else ~/.local/share/rube/solved.txt).\n"
    "Editing: drag an item from the bar into a green placement zone; it turns red, with the reason\n"
    "  on the bar, where it may not go. Wheel or [ ] turns planks, ramps and fans by 15 degrees;\n"
    "  drag a placed item to move it, right-click or Delete removes it (or drop it on the bar).\n"
    "  Drag from a cannon to aim it (the predicted arc follows); the wheel over it turns 1 degree.\n"
    "  Ctrl+Z undoes an edit, Ctrl+Y redoes it (100 deep); G turns the 5 cm grid off (1 mm) and on;\n"
    "  the bar's top right shows the cursor's coordinates. H shows the level's next hint.\n"
    "Keys: Space runs the machine, R resets to editing with placements kept, P pauses, S slow\n"
    "  motion (a tenth of real time), D toggles trails, C clears them, Esc quits.\n"
    "Running: click a cannon to fire it, a bomb to set it off, a switch, fan or magnet to flip it.\n"
    "  Past the goal's time_limit without the goal the HUD and bar say TIME UP; R retries. After the\n"
    "  goal, N goes to the next level and W plays the intended solution (NAME.solution.toml).\n"
    "Recording: --record FILE writes the placements, the aims (step-0 actions), the actions taken\n"
    "  while running (at their step numbers) and, if the goal was reached, an expectation that it\n"
    "  is reached again; 'rube run LEVEL --script FILE --out DIR' replays it off-screen, step for\n"
    "  step. The script records the last level's session as it ends: after R, the edits.\n"
    "--quit-after N closes the window when the machine has taken N steps, whatever the frame rate.\n"
    "Without a display, play says so: use 'rube run' or 'xvfb-run rube play LEVEL'.\n"
    "Exit status: 0 done, 1 the last run ended without its goal (as 'rube run') or no window could\n"
    "  be opened, 2 bad input (level, index, script, --record path).";

// `rube play LEVEL`: the window's options.
class PlayCommand final : public Subcommand {
public:
    explicit PlayCommand(CLI::App& app);
    bool chosen() const override { return static_cast<bool>(*command_); }
    ExitCode run() override;

private:
    CLI::App* command_ = nullptr;
    PlayOptions options_;
    std::string size_ = "1280x720";
    std::int64_t quitAfter_ = 0;
    bool noVsync_ = false;
    CLI::Option* sizeOption_ = nullptr;
    CLI::Option* quitAfterOption_ = nullptr;
};

PlayCommand::PlayCommand(CLI::App& app) {
    command_ = app.add_subcommand("play",
                                  "Play a level in a window with the mouse and keys; optionally record it as a script");
    command_->footer(kPlayFooter);
    command_->add_option("level", options_.level, "The level file (.toml) to play; none: the list of levels")
        ->type_name("LEVEL");
    command_
        ->add_option("--index", options_.index,
                     "The levels in order, for the list and N (default levels/index.toml, from where rube runs)")
        ->type_name("FILE");
    command_
        ->add_option("--script", options_.script,
                     "Start from this script: its placements and aims; its other actions play as the machine runs")
        ->type_name("FILE");
    command_
        ->add_option("--record", options_.record,
                     "When the session ends, write it as a script that 'rube run --script' replays")
        ->type_name("FILE");
    sizeOption_ = command_->add_option("--size", size_, "Level area in pixels, as rube run's frames (default 1280x720)")
                      ->type_name("WxH")
                      ->check(CLI::Validator(frameSizeError, ""));
    command_->add_flag("--run", options_.runAtOnce, "Start the machine at once, as if Space were pressed");
    quitAfterOption_ = command_
                           ->add_option("--quit-after", quitAfter_,
                                        "Close the window once the machine has taken N steps")
                           ->type_name("N")
                           ->check(countFromOne("steps"));
    command_
        ->add_option("--steps-per-frame", options_.stepsPerFrame,
                     "Take K steps per frame drawn instead of following real time")
        ->type_name("K")
        ->check(countFromOne("steps"));
    command_->add_flag("--no-vsync", noVsync_,
                       "Draw as fast as possible instead of at the display's refresh (for measuring)");
}

ExitCode PlayCommand::run() {
    if (*quitAfterOption_) options_.quitAfter = quitAfter_;
    if (*sizeOption_) options_.size = *parseFrameSize(size_); // the validator has accepted it
    options_.vsync = !noVsync_;
    return playInWindow(options_, std::cout, std::cerr);
}

} // namespace

std::unique_ptr<Subcommand> addPlayCommand(CLI::App& app) { return std::make_unique<PlayCommand>(app); }

} // namespace rube::game::cli
