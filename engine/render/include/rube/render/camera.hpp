#pragma once
/// Camera: which part of the world (metres, y up) a frame of pixels shows.

namespace rube::render {

/// A point or vector in the plane; world points are in metres with y up.
struct Point {
    float x = 0.0f;
    float y = 0.0f;
};

/// An axis-aligned rectangle in world units, min the lower-left corner.
struct Rect {
    Point min;
    Point max;
};

/// The size of a frame in pixels.
struct FrameSize {
    int width = 0;
    int height = 0;
};

/// A view of the world: a centre and how many metres fit between the bottom and top of the
/// frame. Pixels are square, so the visible width follows from the frame's aspect ratio.
struct Camera {
    Point centre;
    float viewHeight = 10.0f; ///< metres from the bottom to the top of the frame

    /// The camera that shows all of `world`, centred, with `margin` metres around it; the
    /// rect's longer side relative to the frame's aspect fills the frame (letterboxing the other).
    static Camera fitting(Rect world, FrameSize frame, float margin = 0.0f);

    /// Pixels per metre in a frame of this size.
    float pixelsPerMetre(FrameSize frame) const;
    /// Where a world point lands, in pixels from the frame's bottom-left corner, y up.
    Point toPixels(Point world, FrameSize frame) const;
    /// The world point under a pixel position given from the bottom-left corner, y up.
    Point toWorld(Point pixels, FrameSize frame) const;
};

} // namespace rube::render
