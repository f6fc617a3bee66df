// The offscreen context: Mesa's OSMesa with llvmpipe, a GL 3.3 core context that renders on
// the CPU into memory. Needs no display, no GPU, and gives the same pixels on every run.
// Mesa 25.1 removed OSMesa; an EGL surfaceless context would replace this file alone.
#include "rube/render/render_context.hpp"

#include <glad/gl.h> // before osmesa.h, which would otherwise pull in the system gl.h
#include <GL/osmesa.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

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

class OffscreenContext final : public RenderContext {
public:
    explicit OffscreenContext(FrameSize size) : size_(size) {
        if (size.width <= 0 || size.height <= 0) {
            throw std::invalid_argument("offscreen context: size " + std::to_string(size.width) + "x" +
                                        std::to_string(size.height) + " is empty");
        }
        const int attributes[] = {
            OSMESA_FORMAT, OSMESA_RGBA,
            OSMESA_DEPTH_BITS, 0, // 2D in painter's order: no depth or stencil buffer to clear
            OSMESA_STENCIL_BITS, 0,
            OSMESA_ACCUM_BITS, 0,
            OSMESA_PROFILE, OSMESA_CORE_PROFILE,
            OSMESA_CONTEXT_MAJOR_VERSION, 3,
            OSMESA_CONTEXT_MINOR_VERSION, 3,
            0,
        };
        context_ = OSMesaCreateContextAttribs(attributes, nullptr);
        if (context_ == nullptr) {
            throw std::runtime_error("OSMesa could not create a GL 3.3 core context (is libosmesa6 with llvmpipe installed?)");
        }
        buffer_.resize(static_cast<std::size_t>(size.width) * size.height * 4);
        try {
            makeCurrent();
            // glad keeps one global table of function pointers; OSMesa's are the same for every context.
            if (gladLoadGL(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress)) == 0) {
                throw std::runtime_error("glad could not load the GL 3.3 core functions from OSMesa");
            }
        } catch (...) {
            OSMesaDestroyContext(context_);
            throw;
        }
    }

    ~OffscreenContext() override { OSMesaDestroyContext(context_); }

    void makeCurrent() override {
        if (OSMesaGetCurrentContext() == context_) return;
        if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, size_.width, size_.height)) {
            throw std::runtime_error("OSMesa could not make the offscreen context current");
        }
    }

    FrameSize size() const override { return size_; }

    void readPixels(Image& into) override {
        makeCurrent();
        into.resize(size_.width, size_.height);
        // GL's rows run bottom to top; reading RGBA (the buffer's own format) is a straight copy,
        // then each row is dropped to RGB into its place counted from the top.
        const std::size_t rowRgba = static_cast<std::size_t>(size_.width) * 4;
        scratch_.resize(rowRgba * size_.height);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, size_.width, size_.height, GL_RGBA, GL_UNSIGNED_BYTE, scratch_.data());
        for (int y = 0; y < size_.height; ++y) {
            dropAlpha(scratch_.data() + rowRgba * static_cast<std::size_t>(size_.height - 1 - y), into.pixel(0, y), size_.width);
        }
    }

    void present() override { glFlush(); }

private:
    FrameSize size_;
    OSMesaContext context_ = nullptr;
    std::vector<std::uint8_t> buffer_;  // OSMesa's colour buffer (RGBA, bottom row first)
    std::vector<std::uint8_t> scratch_; // glReadPixels lands here before the flip
};

} // namespace

std::unique_ptr<RenderContext> createOffscreenContext(FrameSize size) {
    return std::make_unique<OffscreenContext>(size);
}

} // namespace rube::render
