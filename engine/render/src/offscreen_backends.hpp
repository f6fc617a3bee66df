#pragma once
// The offscreen back ends one by one; context_offscreen.cpp chooses among those built
// (RUBE_EGL, RUBE_OSMESA) and checks the size first.

#include "rube/render/render_context.hpp"

#include <memory>

namespace rube::render {

/// Mesa's OSMesa (context_osmesa.cpp); only in builds with RUBE_OSMESA.
std::unique_ptr<RenderContext> createOsmesaContext(FrameSize size);

/// EGL without a window system, drawing into a framebuffer object (context_egl.cpp); only in
/// builds with RUBE_EGL.
std::unique_ptr<RenderContext> createEglContext(FrameSize size);

} // namespace rube::render
