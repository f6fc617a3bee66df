#pragma once
// Reading an offscreen colour buffer back as the renderer's RGB image: both offscreen contexts
// (OSMesa, EGL) render RGBA, bottom row first, and hand out RGB, top row first.

#include "rube/render/image.hpp"

#include <cstdint>
#include <vector>

namespace rube::render {

/// Reads the bound framebuffer (RGBA, `width` x `height`) with glReadPixels into `scratch` and
/// converts it into `into` as RGB rows from the top. The current context's GL must be loaded.
void readRgbaFramebuffer(int width, int height, std::vector<std::uint8_t>& scratch, Image& into);

} // namespace rube::render
