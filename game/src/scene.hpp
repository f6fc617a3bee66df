#pragma once
/// Scene: what a scene file describes, held game-side, and how it becomes a physics World.

#include "level.hpp"

#include "rube/physics/world.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rube::game {

/// A scripted path with the name scene files refer to it by.
struct NamedPath {
    std::string name;   ///< unique within the scene
    KinematicPath path; ///< offsets from where each body following it was placed
};

/// A [[rope]] as the file names it: circles by their index in SceneDesc::circles.
struct SceneRope {
    int circle = -1;     ///< the circle at one end
    int other = -1;      ///< the circle at the other end, or -1 for `anchor`
    Vec2 anchor;         ///< the fixed end, m
    double length = 1.0; ///< m
};

/// A [[pivot]] as the file names it: the body by its index in SceneDesc::bodies.
struct ScenePivot {
    int body = -1;    ///< the rigid body
    Vec2 localAnchor; ///< in the body's frame, m
    Vec2 worldAnchor; ///< in the world, m
};

/// One end of a [[joint]]: a circle or a rigid body by its index in SceneDesc, or the world (both -1).
struct SceneJointEnd {
    int circle = -1;
    int body = -1;
    bool isWorld() const { return circle < 0 && body < 0; }
};

/// A [[joint]] as the file gives it: ends by index, anchors as world points at the start, the
/// coupled joints of a gear by their index in SceneDesc::joints; `def` holds the kind and its
/// parameters (its ends, anchors and coupled joints are filled in when the World is built).
struct SceneJoint {
    JointDef def;
    SceneJointEnd a, b;
    Vec2 anchorA, anchorB; ///< world points at the start, m
    int jointA = -1, jointB = -1;
};

/// Everything a scene file says, validated; the physics definitions are ready to hand to a World.
/// Circles and segments refer to paths by index into `paths`, which is also the World's index.
struct SceneDesc {
    std::string name;                 ///< shown in the run summary; by convention the file's stem
    std::string description;          ///< one sentence: what the scene demonstrates
    WorldDef world;                   ///< gravity, time step, method, bounds: the physics defaults unless set
    std::optional<double> duration;   ///< seconds `rube run` simulates when no --steps is given
    std::optional<Aabb> view;         ///< [view]: the region rendered frames show, else chosen from bounds or bodies
    std::vector<NamedPath> paths;     ///< in file order: index i is the World's path i
    std::vector<CircleDef> circles;   ///< in file order, [[circle_grid]] circles row by row from the bottom
    std::vector<SegmentDef> segments; ///< in file order
    std::vector<std::string> circleNames;  ///< the `name` of each circle, "" when unnamed
    std::vector<std::string> segmentNames; ///< the `name` of each segment, "" when unnamed
    std::vector<Water> waters;             ///< [[water]] pools, in file order
    std::vector<SceneRope> ropes;          ///< [[rope]] in file order: index i is the World's rope i
    std::vector<std::string> ropeNames;    ///< the `name` of each rope, "" when unnamed
    std::vector<RigidBodyDef> bodies;      ///< every [[box]], then every [[capsule]]: index i is the World's body i
    std::vector<std::string> bodyNames;    ///< the `name` of each box or capsule, "" when unnamed
    std::vector<ScenePivot> pivots;        ///< [[pivot]] in file order
    std::vector<SceneJoint> joints;        ///< [[joint]] in file order: index i is the World's joint i
    std::vector<std::string> jointNames;   ///< the `name` of each joint, "" when unnamed
    LevelDesc level;                       ///< items, inventory, zones and goal: empty for a physics scene
    std::string physicsToml;               ///< the file's physics tables ([world], [[segment]], ...) as TOML, as read:
                                           ///< the level writer writes them back unchanged

    /// Steps a run takes when the caller names none: the duration rounded up to whole steps, else 600.
    std::int64_t defaultSteps() const;
    /// How many circles move under gravity and impacts (the bodies a trace records).
    std::size_t dynamicCircleCount() const;
    /// The index of the rope called `name`, or -1.
    int findRope(std::string_view name) const;
};

/// Every time-step method, in the order help and error messages list them.
inline constexpr Method kAllMethods[] = {Method::discrete, Method::turnBased, Method::exact, Method::solver,
                                         Method::automatic};

/// The number of steps a run takes when the scene has no duration (10 s at 60 steps per second).
inline constexpr std::int64_t kDefaultSteps = 600;

/// Builds the World: paths first, so that body path indices are valid, then circles, segments and ropes.
World buildWorld(const SceneDesc& scene);

} // namespace rube::game
