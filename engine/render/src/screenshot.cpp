// Golden-frame workflow: compare, or regenerate on request, and leave evidence on failure.
#include "rube/render/screenshot.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <system_error>

namespace rube::render {
namespace {

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f %%", 100.0 * share);
    return text;
}

} // namespace

std::string goldenFileName(std::string_view scene, int step) {
    char number[16];
    std::snprintf(number, sizeof number, "_%04d.png", step);
    return std::string(scene) + number;
}

bool updatingScreenshots() {
    const char* value = std::getenv("UPDATE_SCREENSHOTS");
    return value != nullptr && std::string_view(value) == "1";
}

ScreenshotCheck checkScreenshot(const Image& actual, const std::filesystem::path& goldenPath,
                                const std::filesystem::path& failureFolder, const CompareOptions& options) {
    ScreenshotCheck check;
    std::error_code error;
    if (updatingScreenshots()) {
        std::filesystem::create_directories(goldenPath.parent_path(), error);
        writePng(goldenPath, actual);
        check.passed = true;
        check.goldenWritten = true;
        check.message = "UPDATE_SCREENSHOTS=1: wrote the golden " + goldenPath.string() +
                        "; look at it before committing";
        return check;
    }

    const std::string stem = goldenPath.stem().string();
    std::filesystem::create_directories(failureFolder, error);
    if (!std::filesystem::exists(goldenPath)) {
        check.actualPath = failureFolder / (stem + ".actual.png");
        writePng(check.actualPath, actual);
        check.message = "no golden " + goldenPath.string() + "; the frame is in " + check.actualPath.string() +
                        ": look at it, then rerun with UPDATE_SCREENSHOTS=1 to make it the golden";
        return check;
    }

    Image expected = readPng(goldenPath);
    check.comparison = compareImages(actual, expected, options);
    if (check.comparison.matches) {
        // Evidence of an earlier failure would only mislead now.
        for (const char* kind : {".actual.png", ".expected.png", ".diff.png"}) {
            std::filesystem::remove(failureFolder / (stem + kind), error);
        }
        check.passed = true;
        check.message = goldenPath.filename().string() + " matches (" +
                        std::to_string(check.comparison.differingPixels) + " pixels differ)";
        return check;
    }

    check.actualPath = failureFolder / (stem + ".actual.png");
    check.expectedPath = failureFolder / (stem + ".expected.png");
    writePng(check.actualPath, actual);
    writePng(check.expectedPath, expected);
    if (!check.comparison.sameSize) {
        check.message = "frame is " + std::to_string(actual.width) + "x" + std::to_string(actual.height) + " but " +
                        goldenPath.string() + " is " + std::to_string(expected.width) + "x" +
                        std::to_string(expected.height) + "; see " + check.actualPath.string() + " and " +
                        check.expectedPath.string();
        return check;
    }
    check.diffPath = failureFolder / (stem + ".diff.png");
    writePng(check.diffPath, diffImage(actual, expected, options));
    check.message = std::to_string(check.comparison.differingPixels) + " of " +
                    std::to_string(check.comparison.totalPixels) + " pixels (" +
                    percent(check.comparison.differingShare()) + ", allowed " + percent(options.maxDifferingShare) +
                    ") differ from " + goldenPath.string() + " by more than " +
                    std::to_string(options.channelTolerance) + "/255 within " + std::to_string(options.shift) +
                    " px; see " + check.actualPath.string() + ", " + check.expectedPath.string() + " and " +
                    check.diffPath.string() + " (differences in red)";
    return check;
}

} // namespace rube::render
