#pragma once
/// The pyramid scene type: Box2D's benchmark pyramids of unit boxes (half-size 0.5 m, density 1,
/// friction 0.6) on a static ground box, built resting, so an engine that holds them still is right.
/// Shared by pyramid-40, large-pyramid and many-pyramids.

#include "scene.hpp"

#include <memory>

namespace bench {

/// Pyramids side by side on one ground.
struct PyramidLayout {
    int base = 40;     ///< boxes in the bottom row; base (base + 1) / 2 boxes a pyramid
    int pyramids = 1;  ///< how many, side by side
    double gap = 1.0;  ///< m between neighbouring pyramids' bottom rows
};

/// The boxes' half-size, m.
inline constexpr double kPyramidHalf = 0.5;

/// Adds the ground (box 0) and the pyramids' boxes, row by row, each box touching those below.
void buildPyramids(Sim& sim, const PyramidLayout& layout);

/// Error: the largest distance any box moved from where it was built, over the run (m). Second error:
/// how far the top box of the first pyramid sank by the end (m).
std::unique_ptr<Probe> pyramidProbe(const PyramidLayout& layout);

} // namespace bench
