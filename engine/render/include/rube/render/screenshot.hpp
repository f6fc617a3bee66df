#pragma once
/// Golden-frame checks: compare a rendered frame with a PNG kept in the repository.

#include "rube/render/image_compare.hpp"

#include <filesystem>
#include <string>
#include <string_view>

namespace rube::render {

/// The outcome of one golden check, with a message fit for a test failure.
struct ScreenshotCheck {
    bool passed = false;
    bool goldenWritten = false; ///< UPDATE_SCREENSHOTS=1 replaced the golden
    std::string message;        ///< what happened and which files to look at
    Comparison comparison;
    std::filesystem::path actualPath;   ///< written on failure: the frame just rendered
    std::filesystem::path expectedPath; ///< written on failure when the golden exists: a copy of it
    std::filesystem::path diffPath;     ///< written on failure when the sizes agree: see diffImage
};

/// The golden file name of `scene` after `step` steps, e.g. "ramp_0266.png": goldens are named by
/// the simulation step they show (issue 23: a step is a step, a frame a written picture), so a
/// scene and its goldens are found by the same name.
std::string goldenFileName(std::string_view scene, int step);

/// Whether the environment asks for goldens to be regenerated (UPDATE_SCREENSHOTS=1).
bool updatingScreenshots();

/// Checks `actual` against the golden PNG at `goldenPath`.
/// - With UPDATE_SCREENSHOTS=1 it writes `actual` as the golden and passes.
/// - A missing golden fails, and the frame is written to `failureFolder` to be looked at (and
///   copied into place, or regenerated with UPDATE_SCREENSHOTS=1, once it looks right).
/// - A mismatch fails and writes <name>.actual.png, <name>.expected.png and <name>.diff.png
///   into `failureFolder`, returning their paths; a later pass removes them again.
ScreenshotCheck checkScreenshot(const Image& actual, const std::filesystem::path& goldenPath,
                                const std::filesystem::path& failureFolder, const CompareOptions& options = {});

} // namespace rube::render
