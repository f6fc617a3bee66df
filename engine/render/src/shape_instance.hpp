#pragma once
// Internal: the per-instance record the shape shaders read (assets/shaders/shape.*), and the
// conversion of a DrawList into such records. No GL here, so tests can check it without a context.

#include "rube/render/camera.hpp"
#include "rube/render/draw_list.hpp"

#include <cstdint>
#include <vector>

namespace rube::render {

/// What the fragment shader knows how to shade; each has an exact signed distance.
enum class ShapeKind : std::uint32_t {
    disc = 0,     ///< geomA = (centre.x, centre.y, radius, -)
    capsule = 1,  ///< geomA = (a.x, a.y, b.x, b.y), geomB = (radius, startJointAngle, endJointAngle, -);
                  ///< bits 8/9 of kindAndFlags: clipped at the start/end joint (see strokeChain)
    box = 2,      ///< geomA = (centre.x, centre.y, halfWidth, halfHeight), geomB = (cos, sin, cornerRadius, -)
    triangle = 3, ///< geomA = (p0.x, p0.y, p1.x, p1.y), geomB.xy = p2; bits 8-10 of kindAndFlags: boundary edges
};

/// One quad's worth of shape, everything in pixels from the frame's bottom-left corner, y up,
/// so the shaders need no camera and distances come out in pixels directly.
struct ShapeInstance {
    float geomA[4] = {0, 0, 0, 0};
    float geomB[4] = {0, 0, 0, 0};
    float outlineWidth = 0.0f; ///< pixels inside the edge drawn in the outline colour
    std::uint32_t kindAndFlags = 0;
    Color fill;
    Color outline;

    /// The kind, without the flags.
    ShapeKind kind() const { return static_cast<ShapeKind>(kindAndFlags & 0xffu); }
};
static_assert(sizeof(ShapeInstance) == 48, "the vertex attribute layout in renderer.cpp assumes 48 bytes");

/// Replaces `out` with the instances that draw `list` through `camera` into a frame of `frame`
/// pixels, in list order (painter's order).
void buildInstances(const DrawList& list, const Camera& camera, FrameSize frame, std::vector<ShapeInstance>& out);

/// Appends one box instance per stroke of the stb_easy_font glyphs of `text`, its top-left
/// corner at (x, y) pixels from the frame's top-left, each font unit `scale` pixels.
void appendTextInstances(std::string_view text, int x, int y, int scale, Color color, FrameSize frame,
                         std::vector<ShapeInstance>& out);

} // namespace rube::render
