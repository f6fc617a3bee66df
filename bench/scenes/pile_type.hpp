#pragma once
/// The pile scene type: balls of radius 0.1 m poured into an open box, shared by the pile scene
/// and the scaling sweep, so that the sweep's 1000-ball point is the pile itself.

#include "scene.hpp"

#include <array>
#include <memory>

namespace bench {

/// How many balls, in how many columns, into how big a box.
struct PileLayout {
    int balls = 1000;
    int columns = 20;
    double width = 5.0;   ///< m, the floor's length
    double height = 20.0; ///< m, the walls' height
};

/// The pile's radius, m.
inline constexpr double kPileRadius = 0.1;

/// The floor and the two walls of the layout's box, centred on x = 0.
std::array<LineSpec, 3> pileBox(const PileLayout& layout);

/// Adds the box and the balls: rows of `columns` 0.24 m apart from y = 0.5 m, every other row shifted
/// 6 cm (as levels/physics/pile.toml), the last row only partly filled when balls / columns is not whole.
void buildPile(Sim& sim, const PileLayout& layout);

/// The largest overlap in the last simulated second of a run `duration` seconds long.
std::unique_ptr<Probe> pileProbe(const PileLayout& layout, double duration, double timeStep);

} // namespace bench
