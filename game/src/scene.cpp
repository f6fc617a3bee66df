// Scene: turning a validated description into a physics World.
#include "scene.hpp"

#include <algorithm>
#include <cmath>

namespace rube::game {

std::int64_t SceneDesc::defaultSteps() const {
    if (!duration) return kDefaultSteps;
    // Forgive rounding in duration / time_step (10 / 0.1 is 100.00000000000001), then round up
    // so the run covers at least the whole duration.
    const double steps = *duration / world.timeStep;
    return static_cast<std::int64_t>(std::ceil(steps - 1e-9 * std::max(1.0, steps)));
}

std::size_t SceneDesc::dynamicCircleCount() const {
    return static_cast<std::size_t>(
        std::count_if(circles.begin(), circles.end(), [](const CircleDef& c) { return c.motion == Motion::dynamic; }));
}

int SceneDesc::findRope(std::string_view name) const {
    for (std::size_t i = 0; i < ropeNames.size(); ++i)
        if (!name.empty() && ropeNames[i] == name) return static_cast<int>(i);
    return -1;
}

World buildWorld(const SceneDesc& scene) {
    World world(scene.world);
    for (const NamedPath& path : scene.paths) world.addPath(path.path);
    std::vector<CircleId> circles;
    for (const CircleDef& circle : scene.circles) circles.push_back(world.addCircle(circle));
    for (const SegmentDef& segment : scene.segments) world.addSegment(segment);
    for (const SceneRope& rope : scene.ropes)
        world.addRope({circles[static_cast<std::size_t>(rope.circle)],
                       rope.other >= 0 ? circles[static_cast<std::size_t>(rope.other)] : CircleId{}, rope.anchor,
                       rope.length});
    std::vector<BodyId> bodies;
    for (const RigidBodyDef& body : scene.bodies) bodies.push_back(world.addBody(body));
    for (const ScenePivot& pivot : scene.pivots)
        world.addPivot({bodies[static_cast<std::size_t>(pivot.body)], pivot.localAnchor, pivot.worldAnchor});
    std::vector<JointId> joints;
    const auto endOf = [&](const SceneJointEnd& e) {
        if (e.circle >= 0) return JointEnd{circles[static_cast<std::size_t>(e.circle)], {}};
        if (e.body >= 0) return JointEnd{{}, bodies[static_cast<std::size_t>(e.body)]};
        return JointEnd{};
    };
    for (const SceneJoint& joint : scene.joints) {
        JointDef def = joint.def;
        if (def.kind == JointKind::gear) {
            def.jointA = joints[static_cast<std::size_t>(joint.jointA)];
            def.jointB = joints[static_cast<std::size_t>(joint.jointB)];
        } else {
            def.a = endOf(joint.a);
            def.b = endOf(joint.b);
            def.localAnchorA = world.localPoint(def.a, joint.anchorA);
            def.localAnchorB = world.localPoint(def.b, joint.anchorB);
            def.referenceAngle = world.angleOf(def.b) - world.angleOf(def.a);
        }
        joints.push_back(world.addJoint(def));
    }
    world.fields().waters = scene.waters;
    return world;
}

} // namespace rube::game
