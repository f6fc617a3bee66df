#pragma once
/// The level writer, beside the reader (level_file.cpp): a SceneDesc as a level file that reads
/// back to the same level. The physics tables are written as they were read (SceneDesc::physicsToml);
/// the name, description, view, items, inventory, zones, goal and hints from the SceneDesc, so what
/// an editor changes there is what the file says.

#include "scene.hpp"

#include <string>

namespace rube::game {

/// `scene` as TOML, under `header` (comment lines, each starting with '#', or empty).
std::string writeLevel(const SceneDesc& scene, const std::string& header = "");
/// One item as its [[item]] table: kind, name, position, angle, then its own keys as read.
std::string writeItem(const ItemDesc& item);

} // namespace rube::game
