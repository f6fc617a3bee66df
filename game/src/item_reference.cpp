// References to items by name, from a level's goal and switches or from a script's actions and
// expectations: one wording for every "unknown" and "wrong kind" message, with the same hints.
#include "level.hpp"

#include <algorithm>

namespace rube::game {

bool LevelDesc::clickable(std::string_view name) const {
    return !clicks || std::find(clicks->begin(), clicks->end(), name) != clicks->end();
}

int LevelDesc::find(std::string_view name) const {
    for (std::size_t i = 0; i < items.size(); ++i)
        if (!name.empty() && items[i].name == name) return static_cast<int>(i);
    return -1;
}

std::string itemReferenceError(const LevelDesc& level, std::string_view key, std::string_view name, PartRole role,
                               std::string_view where, const std::vector<std::string>* ropeNames) {
    const std::vector<ItemKind> kinds = partKindsPlaying(role);
    const int index = level.find(name);
    const auto fits = [&](ItemKind kind) { return std::find(kinds.begin(), kinds.end(), kind) != kinds.end(); };
    if (index >= 0 && fits(level.items[static_cast<std::size_t>(index)].kind)) return "";
    // "target", "cannon or bomb", "cannon, bomb, fan or magnet".
    // A switch may also cut a named [[rope]]: then ropes are among what would do.
    std::vector<std::string_view> words;
    for (ItemKind kind : kinds) words.push_back(itemKindName(kind));
    if (ropeNames) words.push_back("rope");
    std::string kindWords;
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (i > 0) kindWords += i + 1 == words.size() ? " or " : ", ";
        kindWords += words[i];
    }
    // Only names that would do are offered: a typo of a bomb's name is no help where a cannon is wanted.
    std::vector<std::string_view> candidates;
    for (const ItemDesc& item : level.items)
        if (fits(item.kind) && !item.name.empty()) candidates.push_back(item.name);
    if (ropeNames)
        for (const std::string& rope : *ropeNames)
            if (!rope.empty()) candidates.push_back(rope);
    const std::string none = "the level has no " + kindWords;
    if (index < 0)
        return "unknown " + kindWords + " '" + std::string(name) + "'" + std::string(where) +
               unknownNameHint(name, candidates, "the level has", none);
    // A name of the wrong kind is no typo: list what would do rather than suggest a spelling.
    return std::string(key) + " '" + std::string(name) + "' is a " +
           std::string(itemKindName(level.items[static_cast<std::size_t>(index)].kind)) + ", not a " + kindWords +
           unknownNameHint("", candidates, "the level has", none);
}

} // namespace rube::game
