#pragma once
/// Image comparison with tolerances, for screenshot tests that must survive small driver changes.

#include "rube/render/image.hpp"

#include <cstdint>

namespace rube::render {

/// How close two frames must be to count as the same. The defaults:
/// - a channel may differ by 16/255: antialiased edges move by a level or two between Mesa
///   versions and CPUs (llvmpipe with AVX2 or SSE rounds differently), while a wrong colour in
///   the palette moves a channel by far more than 16;
/// - a pixel may match any pixel within one pixel of it (as VTK's image test does), in both
///   directions, so an edge rasterised one pixel over passes but a missing one-pixel line fails;
/// - at most 0.1 % of pixels may still differ: a handful of stray pixels, far fewer than one
///   shape moved by a few pixels changes (in the render-basics test, a ball of radius 30 px
///   moved by 3 px leaves ~600 of 129,600 pixels differing, where 130 are allowed).
struct CompareOptions {
    int channelTolerance = 16;        ///< largest per-channel difference that still matches, 0-255
    int shift = 1;                    ///< pixels a match may be away, in x and y
    double maxDifferingShare = 0.001; ///< share of pixels allowed to differ, 0-1
};

/// What a comparison found.
struct Comparison {
    bool sameSize = false;
    std::int64_t totalPixels = 0;
    std::int64_t differingPixels = 0; ///< pixels with no match within the shift, either way
    int largestDifference = 0;        ///< largest channel difference at the same position, 0-255
    bool matches = false;             ///< same size and differingPixels within the allowed share

    /// differingPixels / totalPixels (1 when the sizes differ).
    double differingShare() const;
};

/// Compares `actual` with `expected` under `options`.
Comparison compareImages(const Image& actual, const Image& expected, const CompareOptions& options = {});

/// Where the images differ: `expected` faded to a light grey, with differing pixels in red.
/// Both images must have the same size (throws std::invalid_argument otherwise).
Image diffImage(const Image& actual, const Image& expected, const CompareOptions& options = {});

} // namespace rube::render
