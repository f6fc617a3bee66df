#pragma once
/// The catalogue of part kinds: `rube items` prints it and game/items.md holds it, both written
/// from the kinds' descriptors (part_kind.hpp), so neither can drift from the code. Besides each
/// kind's keys it states what an item of the kind is at its defaults, measured from the bodies
/// its descriptor makes: the numbers authors would otherwise learn from refusals.

#include "part_kind.hpp"

#include <string>

namespace rube::game {

/// What an item of `kind` is at its defaults, measured from its bodies and fields: one line
/// ("a ball of radius 0.3 m, 8 kg, bounciness 0.2; takes 0.6 x 0.6 m").
std::string partDefaults(ItemKind kind);
/// The file name of a kind's picture in a sheet: "<kind>.png".
std::string partPictureName(ItemKind kind);
/// The catalogue as `rube items` prints it: every kind, its keys with defaults and meanings, and
/// its defaults as made.
std::string partCatalogueText();
/// game/items.md: the catalogue in Markdown with each kind's picture from `pictureFolder`
/// (relative to the document); tests/parts/items_catalogue_test.cpp checks the file is current.
std::string partCatalogueMarkdown(const std::string& pictureFolder);

} // namespace rube::game
