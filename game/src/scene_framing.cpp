// Framing: the camera is fixed for a whole run, so a video never jitters, and it is chosen from
// what the scene's author said first ([view], then bounds) before guessing from the bodies.
#include "scene_framing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rube::game {

namespace {

// The bodies' box gets this share of its larger side as a margin on every side: enough that a
// ball resting on the edge of the box is not cut by the frame, little enough to keep them big.
constexpr double kMarginShare = 0.08;
// A lone body, or bodies in a line, would give a box with no size: show this many metres at least.
constexpr double kMinimumExtent = 1.0;

bool finite(const Aabb& box) {
    return std::isfinite(box.min.x) && std::isfinite(box.min.y) && std::isfinite(box.max.x) && std::isfinite(box.max.y);
}

bool isDefaultBounds(const Aabb& box) {
    const Aabb defaults = WorldDef{}.bounds;
    return box.min.x == defaults.min.x && box.min.y == defaults.min.y && box.max.x == defaults.max.x &&
           box.max.y == defaults.max.y;
}

render::Rect toRect(const Aabb& box) {
    return {{static_cast<float>(box.min.x), static_cast<float>(box.min.y)},
            {static_cast<float>(box.max.x), static_cast<float>(box.max.y)}};
}

// Grows `box` to hold the disc of `radius` about `centre`.
void include(Aabb& box, Vec2 centre, double radius) {
    box.min.x = std::min(box.min.x, centre.x - radius);
    box.min.y = std::min(box.min.y, centre.y - radius);
    box.max.x = std::max(box.max.x, centre.x + radius);
    box.max.y = std::max(box.max.y, centre.y + radius);
}

Aabb bodiesBox(const World& world) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    Aabb box{{inf, inf}, {-inf, -inf}};
    for (const Circle& c : world.circles()) include(box, c.position, c.radius);
    for (const Segment& s : world.segments()) {
        include(box, s.a, s.radius);
        include(box, s.b, s.radius);
    }
    if (!finite(box))
        return {{-0.5 * kMinimumExtent, -0.5 * kMinimumExtent}, {0.5 * kMinimumExtent, 0.5 * kMinimumExtent}};
    // Widen any side shorter than the minimum extent, keeping it centred on what is there.
    const auto widen = [](double& low, double& high) {
        const double missing = kMinimumExtent - (high - low);
        if (missing > 0.0) {
            low -= 0.5 * missing;
            high += 0.5 * missing;
        }
    };
    widen(box.min.x, box.max.x);
    widen(box.min.y, box.max.y);
    const double margin = kMarginShare * std::max(box.max.x - box.min.x, box.max.y - box.min.y);
    return {{box.min.x - margin, box.min.y - margin}, {box.max.x + margin, box.max.y + margin}};
}

} // namespace

Framing frameScene(const SceneDesc& scene, const World& world) {
    if (scene.view && finite(*scene.view)) return {toRect(*scene.view), FrameSource::view};
    const Aabb& bounds = scene.world.bounds;
    if (finite(bounds) && !isDefaultBounds(bounds)) return {toRect(bounds), FrameSource::bounds};
    return {toRect(bodiesBox(world)), FrameSource::bodies};
}

render::Camera sceneCamera(const Framing& framing, render::FrameSize size) {
    return render::Camera::fitting(framing.region, size);
}

const char* frameSourceName(FrameSource source) {
    switch (source) {
    case FrameSource::view: return "view";
    case FrameSource::bounds: return "bounds";
    case FrameSource::bodies: return "bodies";
    }
    return "?";
}

} // namespace rube::game
