// The editor's typed texts, in the bar's one-line field (edit_text_field.hpp): the level's hints
// (H adds one; J picks one, Enter changes it, Delete removes it), loaded ones as new ones; the
// goal's text (O); a part's own keys (E), read by the level reader's own code before they count.
#include "edit_session.hpp"

#include "level_writer.hpp"
#include "placement.hpp"
#include "scene_file.hpp"
#include "toml_reader.hpp"
#include "toml_writer.hpp"

#include <algorithm>
#include <utility>

namespace rube::game {

using render::Key;
using render::KeyAction;

void EditSession::ask(std::string prompt, std::string text, char skip, std::function<void(const std::string&)> accept,
                      std::function<void(const std::string&)> next) {
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
            done.next(done.text.text());
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

namespace {

// A part's own keys: its descriptor's, but for those every item has and the angle [ ] turns.
std::vector<PartKey> ownKeys(ItemKind kind) {
    std::vector<PartKey> keys;
    for (const PartKey& key : kind->keys())
        if (key.key != kKindKey.key && key.key != kNameKey.key && key.key != kPositionKey.key && key.key != "angle")
            keys.push_back(key);
    return keys;
}

std::string linePrefix(std::string_view key) { return std::string(key) + " = "; }

// The value the file gives `key` (as TOML text), or "" when it is left at its default.
std::string valueOf(const ItemDesc& item, std::string_view key) {
    for (const std::string& line : item.ownLines)
        if (line.starts_with(linePrefix(key))) return line.substr(linePrefix(key).size());
    return "";
}

// What is typed is a TOML value (12, true, 'gun'); anything else is a string, so a name or a word
// (impact) needs no quotes. The reader then says whether it is of the right type.
std::string tomlOrText(const std::string& text) {
    Diagnostics ignored("typed");
    if (const auto table = parseToml("value = " + text, "typed", ignored); table && table->size() == 1) return text;
    return tomlQuoted(text);
}

std::string trimmed(const std::string& text) {
    const auto first = text.find_first_not_of(' ');
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(' ') - first + 1);
}

// The player's parts keep their own keys as a script's [[place]] does: key and TOML value apart.
std::vector<std::string> linesOf(const Placement& p) {
    std::vector<std::string> lines;
    for (const auto& [key, value] : p.ownKeys) lines.push_back(linePrefix(key) + value);
    return lines;
}

std::vector<std::pair<std::string, std::string>> keysOf(const std::vector<std::string>& lines) {
    std::vector<std::pair<std::string, std::string>> keys;
    for (const std::string& line : lines) {
        const auto equals = line.find(" = ");
        keys.emplace_back(line.substr(0, equals), line.substr(equals + 3));
    }
    return keys;
}

} // namespace

ItemDesc EditSession::partOf(const Hit& hit) const {
    if (hit.what == Hit::What::item) return state_.level.level.items[hit.index];
    const Placement& p = state_.players[hit.index];
    ItemDesc item = placedItem(p);
    item.angleDegrees = p.angleDegrees;
    item.ownLines = linesOf(p);
    return item;
}

void EditSession::markOwnKeys(Placement& p, const ItemDesc& item) {
    p.ownKeys = keysOf(item.ownLines);
    if (p.ownKeys.empty()) p.params.reset();
    else p.params = item.params;
}

// E over a part, fixed or the player's: its own keys one at a time in the bar. Tab keeps what is
// typed and goes to the next key; Enter sets them all at once (a bomb's trigger 'timer' needs its
// fuse with it).
void EditSession::editKeysAtCursor() {
    const Hit hit = hitAtCursor();
    if (hit.what != Hit::What::item && hit.what != Hit::What::player)
        return say("E: point at a part to set its keys", "magnet");
    editKey(hit, 0, 'e', {});
}

void EditSession::editKey(Hit part, std::size_t keyIndex, char skip, KeyValues typed) {
    const ItemDesc item = partOf(part);
    const std::vector<PartKey> keys = ownKeys(item.kind);
    if (keys.empty()) return say("a " + std::string(item.kind->name()) + " has no keys of its own", "magnet");
    const PartKey key = keys[keyIndex % keys.size()];
    const auto was = std::find_if(typed.begin(), typed.end(), [&](const auto& kv) { return kv.first == key.key; });
    const std::string now = was != typed.end() ? was->second : valueOf(item, key.key);
    const std::string who = item.name.empty() ? std::string(item.kind->name()) : item.name;
    // What is typed for this key replaces what was typed before for it.
    const auto with = [key, typed](const std::string& text) {
        KeyValues all = typed;
        std::erase_if(all, [&](const auto& kv) { return kv.first == key.key; });
        all.emplace_back(key.key, text);
        return all;
    };
    ask(
        who + " " + std::string(key.key) + " (" + std::string(key.value) + "; " + std::string(key.doc) + "): ", now,
        skip, [this, part, with](const std::string& text) { setKeys(part, with(text)); },
        [this, part, keyIndex, with](const std::string& text) { editKey(part, keyIndex + 1, 0, with(text)); });
}

// Nothing typed puts a key back to its default. The changed part must read as the level reader
// reads an [[item]], among the level's other items (a player's part as one more); else the
// reader's message is shown and nothing changes.
bool EditSession::setKeys(Hit part, const KeyValues& values) {
    const ItemDesc before = partOf(part);
    ItemDesc changed = before;
    for (const auto& entry : values) {
        // Not a structured binding: clang 14 (Debian 12's, the fuzz and cross-compiler trees) cannot
        // capture one in the lambda below.
        const auto& key = entry.first;
        const std::string value = trimmed(entry.second);
        const auto line = std::find_if(changed.ownLines.begin(), changed.ownLines.end(),
                                       [&](const std::string& own) { return own.starts_with(linePrefix(key)); });
        if (value.empty() && line != changed.ownLines.end()) changed.ownLines.erase(line);
        else if (!value.empty() && line != changed.ownLines.end()) *line = linePrefix(key) + tomlOrText(value);
        else if (!value.empty()) changed.ownLines.push_back(linePrefix(key) + tomlOrText(value));
    }
    SceneDesc among = state_.level;
    std::size_t index = part.index;
    if (part.what == Hit::What::player) {
        index = among.level.items.size();
        among.level.items.push_back(before);
    }
    const ItemLoad load = readItemAgain(among, index, writeItem(changed));
    if (!load.item) {
        say("refused: " + load.errors.front().message, "magnet");
        return false;
    }
    // What the bar says: the keys whose value changed (Tab passes others by as they were).
    std::string said = (before.name.empty() ? std::string(before.kind->name()) : before.name) + ":";
    for (const auto& [key, text] : values)
        if (const std::string value = valueOf(*load.item, key); value != valueOf(before, key))
            said += (said.back() == ':' ? " " : ", ") + std::string(key) +
                    (value.empty() ? " at its default" : " = " + value);
    if (said.back() == ':') {
        say(said + " nothing changed");
        return true;
    }
    edit();
    if (part.what == Hit::What::player) {
        markOwnKeys(state_.players[part.index], *load.item);
    } else {
        ItemDesc& item = state_.level.level.items[part.index];
        const SourcePlace place = item.place;
        item = *load.item;
        item.place = place;
    }
    say(said);
    return true;
}

} // namespace rube::game
