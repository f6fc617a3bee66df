// Tolerant image comparison (thresholds and their reasons in image_compare.hpp).
#include "rube/render/image_compare.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace rube::render {
namespace {

int channelDifference(const std::uint8_t* a, const std::uint8_t* b) {
    return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

// Whether pixel (x, y) of `from` has a pixel within `shift` of (x, y) in `in` that matches it.
bool hasMatchNear(const Image& from, const Image& in, int x, int y, const CompareOptions& options) {
    const std::uint8_t* p = from.pixel(x, y);
    if (channelDifference(p, in.pixel(x, y)) <= options.channelTolerance) return true;
    for (int dy = -options.shift; dy <= options.shift; ++dy) {
        int ny = y + dy;
        if (ny < 0 || ny >= in.height) continue;
        for (int dx = -options.shift; dx <= options.shift; ++dx) {
            int nx = x + dx;
            if (nx < 0 || nx >= in.width) continue;
            if (channelDifference(p, in.pixel(nx, ny)) <= options.channelTolerance) return true;
        }
    }
    return false;
}

// One byte per pixel, 1 where the images differ. Both directions are checked: looking only
// from actual to expected would forgive a thin line that is missing from the actual frame.
std::vector<std::uint8_t> differingMask(const Image& actual, const Image& expected, const CompareOptions& options,
                                        int* largestDifference) {
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(actual.width) * actual.height, 0);
    int largest = 0;
    for (int y = 0; y < actual.height; ++y) {
        for (int x = 0; x < actual.width; ++x) {
            int same = channelDifference(actual.pixel(x, y), expected.pixel(x, y));
            largest = std::max(largest, same);
            if (same <= options.channelTolerance) continue;
            bool differs = !hasMatchNear(actual, expected, x, y, options) ||
                           !hasMatchNear(expected, actual, x, y, options);
            mask[static_cast<std::size_t>(y) * actual.width + x] = differs ? 1 : 0;
        }
    }
    if (largestDifference != nullptr) *largestDifference = largest;
    return mask;
}

bool sameSize(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           a.rgb.size() == static_cast<std::size_t>(a.width) * a.height * 3 &&
           b.rgb.size() == static_cast<std::size_t>(b.width) * b.height * 3;
}

} // namespace

double Comparison::differingShare() const {
    if (!sameSize || totalPixels == 0) return 1.0;
    return static_cast<double>(differingPixels) / static_cast<double>(totalPixels);
}

Comparison compareImages(const Image& actual, const Image& expected, const CompareOptions& options) {
    Comparison result;
    result.sameSize = sameSize(actual, expected);
    if (!result.sameSize) return result;
    result.totalPixels = static_cast<std::int64_t>(actual.width) * actual.height;
    std::vector<std::uint8_t> mask = differingMask(actual, expected, options, &result.largestDifference);
    result.differingPixels = std::count(mask.begin(), mask.end(), std::uint8_t{1});
    result.matches = static_cast<double>(result.differingPixels) <=
                     options.maxDifferingShare * static_cast<double>(result.totalPixels);
    return result;
}

Image diffImage(const Image& actual, const Image& expected, const CompareOptions& options) {
    if (!sameSize(actual, expected)) {
        throw std::invalid_argument("diffImage: the images differ in size");
    }
    std::vector<std::uint8_t> mask = differingMask(actual, expected, options, nullptr);
    Image diff;
    diff.resize(expected.width, expected.height);
    for (std::size_t i = 0; i < mask.size(); ++i) {
        std::uint8_t* out = diff.rgb.data() + 3 * i;
        if (mask[i] != 0) {
            out[0] = 255;
            out[1] = 0;
            out[2] = 0;
            continue;
        }
        // Rec. 601 luma squeezed into 170-255: the scene stays readable, and no grey is
        // mistaken for the red of a difference.
        const std::uint8_t* in = expected.rgb.data() + 3 * i;
        int luma = (299 * in[0] + 587 * in[1] + 114 * in[2]) / 1000;
        auto grey = static_cast<std::uint8_t>(170 + luma / 3);
        out[0] = out[1] = out[2] = grey;
    }
    return diff;
}

} // namespace rube::render
