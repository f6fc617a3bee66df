// The OSMesa offscreen context: Mesa's OSMesa with llvmpipe, a GL 3.3 core context that renders
// on the CPU into memory. Needs no display, no GPU, and gives the same pixels on every run.
// Mesa 25.1 removed OSMesa; context_egl.cpp is the path that outlives it (RUBE_OSMESA=OFF builds
// without this file).
#include "offscreen_backends.hpp"
#include "rgba_rows.hpp"

#include <glad/gl.h> // before osmesa.h, which would otherwise pull in the system gl.h
#include <GL/osmesa.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace rube::render {
namespace {

class OsmesaContext final : public RenderContext {
public:
    explicit OsmesaContext(FrameSize size) : size_(size) {
        const int attributes[] = {
            OSMESA_FORMAT,
            OSMESA_RGBA,
            OSMESA_DEPTH_BITS,
            0, // 2D in painter's order: no depth or stencil buffer to clear
            OSMESA_STENCIL_BITS,
            0,
            OSMESA_ACCUM_BITS,
            0,
            OSMESA_PROFILE,
            OSMESA_CORE_PROFILE,
            OSMESA_CONTEXT_MAJOR_VERSION,
            3,
            OSMESA_CONTEXT_MINOR_VERSION,
            3,
            0,
        };
        context_ = OSMesaCreateContextAttribs(attributes, nullptr);
        if (context_ == nullptr) {
            throw std::runtime_error(
                "OSMesa could not create a GL 3.3 core context (install libosmesa6, Mesa's llvmpipe)");
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

    ~OsmesaContext() override { OSMesaDestroyContext(context_); }

    void makeCurrent() override {
        if (OSMesaGetCurrentContext() == context_) return;
        if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, size_.width, size_.height)) {
            throw std::runtime_error("OSMesa could not make the offscreen context current");
        }
    }

    FrameSize size() const override { return size_; }

    void readPixels(Image& into) override {
        makeCurrent();
        readRgbaFramebuffer(size_.width, size_.height, scratch_, into);
    }

    void present() override { glFlush(); }

    std::string_view backendName() const override { return "osmesa"; }

private:
    FrameSize size_;
    OSMesaContext context_ = nullptr;
    std::vector<std::uint8_t> buffer_;  // OSMesa's colour buffer (RGBA, bottom row first)
    std::vector<std::uint8_t> scratch_; // glReadPixels lands here before the flip
};

} // namespace

std::unique_ptr<RenderContext> createOsmesaContext(FrameSize size) { return std::make_unique<OsmesaContext>(size); }

} // namespace rube::render
