// The editor's typed texts, in the bar's one-line field (edit_text_field.hpp): the level's hints
// (H adds one; J picks one, Enter changes it, Delete removes it), loaded ones as new ones; the
// goal's text (O).
#include "edit_session.hpp"

#include <utility>

namespace rube::game {

using render::Key;
using render::KeyAction;

void EditSession::ask(std::string prompt, std::string text, char skip, std::function<void(const std::string&)> accept,
                      std::function<void()> next) {
    field_ = Field{TextField(std::move(prompt), std::move(text), skip), std::move(accept), std::move(next)};
    say(field_->text.line());
}

// While the field is open only its keys act; the rest type (typed()).
void EditSession::fieldKey(Key key, KeyAction action) {
    switch (field_->text.key(key, action)) {
    case TextField::Outcome::typing: say(field_->text.line()); break;
    case TextField::Outcome::accepted: {
        Field done = std::move(*field_);
        field_.reset();
        done.accept(done.text.text());
        break;
    }
    case TextField::Outcome::cancelled:
        field_.reset();
        say("left unchanged");
        break;
    case TextField::Outcome::next:
        if (Field done = std::move(*field_); done.next) {
            field_.reset();
            done.next();
        } else {
            field_ = std::move(done);
        }
        break;
    }
}

namespace {

// The reader refuses an empty hint; so does the editor, before it is saved.
bool blank(const std::string& text) { return text.find_first_not_of(' ') == std::string::npos; }

} // namespace

void EditSession::addHint() {
    ask("new hint: ", "", 'h', [this](const std::string& text) {
        if (blank(text)) return say("no hint");
        edit();
        state_.level.level.hints.push_back({text, {}});
        say("hint " + std::to_string(state_.level.level.hints.size()) + " kept: " + text);
    });
}

// J: the hints in turn, loaded or typed; the pick lasts until the next key or click.
void EditSession::pickHint(std::size_t index) {
    const std::vector<Hint>& hints = state_.level.level.hints;
    if (hints.empty()) return say("J: the level has no hints yet (H adds one)", "magnet");
    index %= hints.size();
    hintPicked_ = index;
    say("hint " + std::to_string(index + 1) + " of " + std::to_string(hints.size()) + ": " + hints[index].text +
        "  (Enter changes, Delete removes, J next)");
}

void EditSession::changeHint(std::size_t index) {
    const std::string number = std::to_string(index + 1);
    ask("hint " + number + ": ", state_.level.level.hints[index].text, 0,
        [this, index, number](const std::string& text) {
            if (blank(text)) return say("a hint's text must not be empty: Delete removes it", "magnet");
            edit();
            state_.level.level.hints[index].text = text;
            say("hint " + number + " changed: " + text);
        });
}

void EditSession::removeHint(std::size_t index) {
    edit();
    std::vector<Hint>& hints = state_.level.level.hints;
    hints.erase(hints.begin() + static_cast<std::ptrdiff_t>(index));
    say("hint " + std::to_string(index + 1) + " removed; " + std::to_string(hints.size()) + " left");
}

void EditSession::typeGoalText() {
    if (!state_.level.level.goal) return say("T sets a goal first; then O types its text", "magnet");
    ask("goal text: ", state_.level.level.goal->text, 'o', [this](const std::string& text) {
        if (blank(text)) return say("the goal's text must not be empty: it is what the player is told", "magnet");
        edit();
        state_.level.level.goal->text = text;
        sayGoal();
    });
}

} // namespace rube::game
