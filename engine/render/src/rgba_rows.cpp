// glReadPixels of an RGBA buffer, flipped and dropped to RGB: the offscreen contexts' readback.
#include "rgba_rows.hpp"

#include <glad/gl.h>

#include <bit>
#include <cstring>

namespace rube::render {
namespace {

// RGBA to RGB for one row. Four pixels at a time as 32-bit words (16 bytes in, 12 out) is
// several times faster than byte by byte, and the frame has a million pixels.
void dropAlpha(const std::uint8_t* rgba, std::uint8_t* rgb, int width) {
    int x = 0;
    for (; x + 4 <= width; x += 4, rgba += 16, rgb += 12) {
        std::uint32_t p[4];
        std::memcpy(p, rgba, 16);
        std::uint32_t out[3];
        if constexpr (std::endian::native == std::endian::little) {
            out[0] = (p[0] & 0xffffffu) | (p[1] << 24);
            out[1] = ((p[1] >> 8) & 0xffffu) | (p[2] << 16);
            out[2] = ((p[2] >> 16) & 0xffu) | (p[3] << 8);
        } else {
            out[0] = (p[0] & 0xffffff00u) | (p[1] >> 24);
            out[1] = ((p[1] << 8) & 0xffff0000u) | (p[2] >> 16);
            out[2] = ((p[2] << 16) & 0xff000000u) | (p[3] >> 8);
        }
        std::memcpy(rgb, out, 12);
    }
    for (; x < width; ++x, rgba += 4, rgb += 3) {
        rgb[0] = rgba[0];
        rgb[1] = rgba[1];
        rgb[2] = rgba[2];
    }
}

} // namespace

void readRgbaFramebuffer(int width, int height, std::vector<std::uint8_t>& scratch, Image& into) {
    into.resize(width, height);
    // GL's rows run bottom to top; reading RGBA (the buffer's own format) is a straight copy,
    // then each row is dropped to RGB into its place counted from the top.
    const std::size_t rowRgba = static_cast<std::size_t>(width) * 4;
    scratch.resize(rowRgba * static_cast<std::size_t>(height));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, scratch.data());
    for (int y = 0; y < height; ++y) {
        dropAlpha(scratch.data() + rowRgba * static_cast<std::size_t>(height - 1 - y), into.pixel(0, y), width);
    }
}

} // namespace rube::render
