// `rube edit [LEVEL]`: the editor's options.
#include "command_line.hpp"

#include "edit_window.hpp"

#include <iostream>
#include <string>

namespace rube::game::cli {

namespace {

// `rube edit [LEVEL]`: the editor's options.
class EditCommand final : public Subcommand {
public:
    explicit EditCommand(CLI::App& app);
    bool chosen() const override { return static_cast<bool>(*command_); }
    ExitCode run() override;

private:
    CLI::App* command_ = nullptr;
    EditOptions options_;
    std::string size_ = "1280x720";
    CLI::Option* sizeOption_ = nullptr;
};

EditCommand::EditCommand(CLI::App& app) {
    command_ = app.add_subcommand("edit", "Make a level (or change LEVEL) in a window, and save it with its solution");
    command_->footer("A click places the kind shown on the bar (Tab picks the next; every kind, without limit) or\n"
                     "  picks up a part to move it; [ ] or the wheel turns it by 15 degrees; right-click or Delete\n"
                     "  removes a part or a zone. Z switches to zones: a drag draws a placement zone, a drag from a\n"
                     "  zone's corner resizes it. P marks the part under the cursor as the player's: it is saved as\n"
                     "  a placement of NAME.solution.toml and counted into the inventory (P again makes it fixed);\n"
                     "  I and K add and take a spare of the kind shown. T makes the target or bucket under the\n"
                     "  cursor the goal (10 s; T again on its target: every target), or a zone the area a ball\n"
                     "  must reach (reach-area; then T on a ball, crate, domino or rocket: that one must, again:\n"
                     "  any ball); Up and Down change the time limit by 1 s; O types the goal's text.\n"
                     "  V fits the view to the parts and zones; C shows\n"
                     "  three times as much around it (the wheel zooms) and a drag there draws the view (C again:\n"
                     "  no change). E over a part types its own keys (those 'rube items' lists for its kind; a\n"
                     "  player's part keeps them in its [[place]]; Tab: the next key, Enter sets them, nothing\n"
                     "  typed: the default), checked by the level reader. L on a switch links it to the next part\n"
                     "  it can trigger. H types a hint; J picks the level's hints in turn: Enter changes the one\n"
                     "  shown, Delete removes it. Text is typed in the bar: Enter keeps it, Esc drops it. Space\n"
                     "  tries the level as 'rube play' would, R or Esc comes back. Ctrl+Z and Ctrl+Y undo and redo;\n"
                     "  Ctrl+S saves the level and NAME.solution.toml beside it, with the goal's step as the\n"
                     "  solution's expectation, and says whether the solution still reaches the goal with each\n"
                     "  part moved one 5 cm grid step either way. Esc quits (without saving).\n"
                     "Exit status: 0 done, 1 no window could be opened, 2 bad input (level, its solution, --out).");
    command_->add_option("level", options_.level, "The level file (.toml) to change; none: a new level")
        ->type_name("LEVEL");
    command_->add_option("--out", options_.out, "Save to FILE (default: LEVEL, else new-level.toml)")
        ->type_name("FILE");
    sizeOption_ = command_->add_option("--size", size_, "Level area in pixels (default 1280x720)")
                      ->type_name("WxH")
                      ->check(CLI::Validator(frameSizeError, ""));
}

ExitCode EditCommand::run() {
    if (*sizeOption_) options_.size = *parseFrameSize(size_); // the validator has accepted it
    return editInWindow(options_, std::cout, std::cerr);
}

} // namespace

std::unique_ptr<Subcommand> addEditCommand(CLI::App& app) { return std::make_unique<EditCommand>(app); }

} // namespace rube::game::cli
