#pragma once
/// TextField: the editor's one-line text entry on the bar (a hint, the goal's text, a part's key).
/// Characters come from the window's char callback (InputListener::typed), so the keyboard's layout
/// is the system's; keys edit the line. Internal to the editor's files (edit_*.cpp).

#include "rube/render/window_input.hpp"

#include <string>

namespace rube::game {

class TextField {
public:
    /// What a key did to the field.
    enum class Outcome { typing, accepted, cancelled, next };

    /// A field showing `prompt` before `text` (what is being changed, its value now). `skip` is the
    /// character the key that opened it types too (H types an 'h' after its key event): not taken.
    TextField(std::string prompt, std::string text, char skip)
        : prompt_(std::move(prompt)), text_(std::move(text)), skip_(skip) {}

    /// A typed character: printable ASCII only, what the HUD's font draws.
    void typed(char32_t codePoint) {
        const char32_t skip = skip_;
        skip_ = 0;
        if (skip != 0 && (codePoint == skip || codePoint == skip - U'a' + U'A')) return;
        if (codePoint < 32 || codePoint > 126) return;
        text_ += static_cast<char>(codePoint);
    }
    /// Enter accepts, Esc cancels, Tab asks for the next thing to edit, Backspace takes a character
    /// back; any other key is typing (its character comes through typed()).
    Outcome key(render::Key key, render::KeyAction action) {
        if (action == render::KeyAction::release) return Outcome::typing;
        skip_ = 0; // the opening key's character comes before any other key
        if (action == render::KeyAction::press) {
            if (key == render::Key::enter) return Outcome::accepted;
            if (key == render::Key::escape) return Outcome::cancelled;
            if (key == render::Key::tab) return Outcome::next;
        }
        if (key == render::Key::backspace && !text_.empty()) text_.pop_back();
        return Outcome::typing;
    }

    const std::string& text() const { return text_; }
    /// The bar's line: the prompt, the text and a cursor.
    std::string line() const { return prompt_ + text_ + "_"; }

private:
    std::string prompt_;
    std::string text_;
    char32_t skip_;
};

} // namespace rube::game
