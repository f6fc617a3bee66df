#pragma once
/// Image: an RGB frame in memory, and its PNG encoding, writing and reading.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace rube::render {

/// An 8-bit RGB image, rows from the top of the picture down, 3 bytes per pixel, no padding.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb; ///< width * height * 3 bytes

    /// An image of the given size filled with one colour.
    static Image filled(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b);
    /// Sets the size, keeping the memory when it is big enough (pixel values are unspecified).
    void resize(int newWidth, int newHeight);
    /// The first of the three bytes of pixel (x, y), y counted from the top.
    std::uint8_t* pixel(int x, int y) { return rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3; }
    /// The first of the three bytes of pixel (x, y), y counted from the top.
    const std::uint8_t* pixel(int x, int y) const { return rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3; }
    /// Same size and same bytes.
    friend bool operator==(const Image&, const Image&) = default;
};

/// The image as PNG bytes. Tuned for greybox frames: every row uses filter 2 ("up"), whose
/// output on flat colour is all zeros, and zlib deflates at level 1 with run-length matching;
/// a 1280x720 frame takes about 10 ms and 10-20 KB (stb's own deflate: ~100 ms).
std::vector<std::uint8_t> encodePng(const Image& image);

/// Writes the image as a PNG file, first under a temporary name in the same folder and then
/// renamed, so a reader never sees a truncated file. Throws std::runtime_error naming the
/// path and the system's reason when it cannot.
void writePng(const std::filesystem::path& path, const Image& image);

/// Writes bytes to `path` the same all-or-nothing way (temporary name, then rename).
void writeFileAtomically(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes);

/// Reads a PNG (any bit depth or colour type) as 8-bit RGB; throws std::runtime_error naming
/// the path and stb_image's reason when it cannot.
Image readPng(const std::filesystem::path& path);

} // namespace rube::render
