#pragma once
/// `rube items`: the catalogue of part kinds as text, and with --sheet one labelled picture per
/// kind, drawn by the kind itself through the renderer `rube run --out` uses.

#include "exit_codes.hpp"

#include "rube/render/camera.hpp"

#include <ostream>
#include <string>

namespace rube::game {

/// What `rube items` was asked for.
struct ItemsOptions {
    std::string sheet;                ///< folder for the pictures; empty: print the catalogue
    render::FrameSize size{320, 240}; ///< each picture's size, pixels
    bool progress = false;            ///< show a progress line on `err` (when it is a terminal)
};

/// Prints the catalogue to `out`, or writes the sheet into options.sheet: one PNG per kind,
/// named partPictureName(kind), and a line on `out` saying how many. A folder that cannot be
/// written is one line on `err` and badInput, before any picture is drawn; no GL context is failed.
ExitCode listItems(const ItemsOptions& options, std::ostream& out, std::ostream& err);

} // namespace rube::game
