#pragma once
/// Renderer: draws a DrawList through a Camera into a RenderContext.

#include "rube/render/camera.hpp"
#include "rube/render/draw_list.hpp"
#include "rube/render/image.hpp"
#include "rube/render/render_context.hpp"

#include <cstddef>
#include <memory>

namespace rube::render {

/// What the last draw() did, for benchmarks and tests.
struct RenderStats {
    std::size_t instances = 0; ///< shape instances uploaded (a circle with a spoke is two)
    int drawCalls = 0;         ///< GL draw calls issued
};

/// Turns draw lists into pixels. Every shape becomes one instance of a quad whose fragment
/// shader antialiases the edge analytically, and the whole list is one instanced draw call in
/// list order, so painter's order holds and frames are the same on every run.
/// The renderer must be destroyed before its context.
class Renderer {
public:
    /// Compiles the embedded shaders in `context` (made current); throws std::runtime_error
    /// with the GL info log when they do not compile.
    explicit Renderer(RenderContext& context);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Clears the frame to list.background and draws every primitive, back to front.
    void draw(const DrawList& list, const Camera& camera);
    /// Copies the drawn frame into `into` (RGB, top row first).
    void readPixels(Image& into);
    /// draw() then readPixels() into a new image.
    Image render(const DrawList& list, const Camera& camera);

    /// The size of the frames it draws.
    FrameSize frameSize() const;
    /// Counters of the last draw().
    RenderStats lastStats() const { return stats_; }

private:
    struct Gpu; // GL object names, kept out of this header so users need no GL headers
    RenderContext& context_;
    std::unique_ptr<Gpu> gpu_;
    RenderStats stats_;
};

} // namespace rube::render
