#pragma once
/// Framing: which part of a scene rendered frames show, chosen once at the start of a run.

#include "scene.hpp"

#include "rube/render/camera.hpp"

namespace rube::game {

/// Where the framed region came from, for the run summary and for tests.
enum class FrameSource { view, bounds, bodies };

/// The region of the world a run's frames show, and why.
struct Framing {
    render::Rect region; ///< world metres, before the camera fits it to the frame's aspect
    FrameSource source = FrameSource::bodies;
};

/// Picks the region to show: the scene's [view] if it has one; else the world bounds if the
/// scene sets them (finite, and not the physics' huge default); else the bounding box of every
/// body and segment in `world`'s current state, with a margin so nothing touches the edge.
Framing frameScene(const SceneDesc& scene, const World& world);

/// The camera that shows `framing`'s region whole in a frame of `size`, centred; the frame's
/// aspect is kept, so one axis gets more room than the region asks for.
render::Camera sceneCamera(const Framing& framing, render::FrameSize size);

/// "view", "bounds" or "bodies".
const char* frameSourceName(FrameSource source);

} // namespace rube::game
