// Camera: world metres to frame pixels and back. Both axes point the same way (y up) in the
// world and in GL's window coordinates, so the map is a uniform scale plus a shift.
#include "rube/render/camera.hpp"

#include <algorithm>

namespace rube::render {

Camera Camera::fitting(Rect world, FrameSize frame, float margin) {
    float width = world.max.x - world.min.x + 2.0f * margin;
    float height = world.max.y - world.min.y + 2.0f * margin;
    float aspect = frame.height > 0 ? static_cast<float>(frame.width) / static_cast<float>(frame.height) : 1.0f;
    Camera camera;
    camera.centre = {0.5f * (world.min.x + world.max.x), 0.5f * (world.min.y + world.max.y)};
    // The view must be tall enough for the rect's height and, at this aspect, wide enough for its width.
    camera.viewHeight = std::max({height, width / aspect, 1e-6f});
    return camera;
}

float Camera::pixelsPerMetre(FrameSize frame) const { return static_cast<float>(frame.height) / viewHeight; }

Point Camera::toPixels(Point world, FrameSize frame) const {
    float scale = pixelsPerMetre(frame);
    return {(world.x - centre.x) * scale + 0.5f * static_cast<float>(frame.width),
            (world.y - centre.y) * scale + 0.5f * static_cast<float>(frame.height)};
}

Point Camera::toWorld(Point pixels, FrameSize frame) const {
    float scale = pixelsPerMetre(frame);
    return {(pixels.x - 0.5f * static_cast<float>(frame.width)) / scale + centre.x,
            (pixels.y - 0.5f * static_cast<float>(frame.height)) / scale + centre.y};
}

} // namespace rube::render
