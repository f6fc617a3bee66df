// The docs of the part kinds, written from their descriptors: game/scene-format.md holds this text
// between its "parts" markers, and tests/parts/part_kinds_test.cpp fails when the two differ, so the
// docs cannot drift from the code.
#include "part_kind.hpp"

namespace rube::game {

std::string markdownCell(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (c == '|') out += '\\';
        out += c;
    }
    return out;
}

std::string partKindsMarkdown() {
    std::string out = "| kind | key | default | meaning |\n|---|---|---|---|\n";
    for (ItemKind kind : allPartKinds()) {
        std::string traits;
        if (kind->placeable()) traits += "; placeable";
        if (kind->turns()) traits += ", turns";
        out += "| **" + std::string(kind->name()) + "** | | | " + markdownCell(kind->summary()) + traits + " |\n";
        for (const PartKey& key : kind->keys()) {
            if (key.key == kKindKey.key) continue; // every item has it: it names the row above
            const bool required = key.value == "required" || (key.key == kNameKey.key && kind->needsName());
            out += "| | `" + std::string(key.key) + "` | " +
                   (required ? std::string("required") : markdownCell(key.value)) + " | " + markdownCell(key.doc) +
                   " |\n";
        }
    }
    return out;
}

} // namespace rube::game
