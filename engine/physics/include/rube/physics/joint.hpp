#pragma once
/// Joints: the mechanisms of a machine. A joint ties two bodies (circles, boxes or capsules) or a
/// body and the world: a revolute (a hinge, with an optional motor and angle limits), a prismatic
/// (a piston: a slide along an axis, with motor and limits), a weld (rigid, or soft), a damped
/// spring, a pulley (a rope over two fixed points that pulls only when taut), and a gear that
/// couples two revolutes (or a revolute and a prismatic: rack and pinion); a belt is a gear of the
/// radii's ratio turning both wheels the same way.
///
/// Which methods carry them: the solver (substepped, soft as Box2D v3's joints, springs integrated
/// as forces by velocity Verlet); exact, a spring from a circle's centre to a fixed point where its
/// motion has a closed form (rest length 0 and undamped, or along the spring's line with gravity
/// along it), refusing every other joint (World::step throws, naming why); and auto, which gives
/// such a spring's island to exact and every other island with a jointed body to the solver (a
/// joint's ends share an island). discrete and turn-based refuse a world with joints, as they
/// refuse turning bodies. Bodies a joint joins do not collide with each other unless
/// JointDef::collideConnected. See engine/physics/ARCHITECTURE.md ("Joints").

#include "rube/physics/handles.hpp"
#include "rube/physics/vec2.hpp"

#include <cstdint>

namespace rube {

/// The kinds of joint.
enum class JointKind : std::uint8_t { revolute, prismatic, weld, spring, pulley, gear };

/// One end of a joint: a circle, a rigid body, or (both null) the world itself.
struct JointEnd {
    CircleId circle;
    BodyId body;
    bool isWorld() const { return circle.isNull() && body.isNull(); }
};

/// A motor: drives the joint's coordinate (angle, or slide along the axis) at `speed` (rad/s or
/// m/s) with at most `maxForce` (N m for a revolute, N for a prismatic). Off when maxForce is 0.
struct JointMotor {
    double speed = 0.0;
    double maxForce = 0.0;
    bool on() const { return maxForce > 0.0; }
};

/// Limits on the joint's coordinate (radians from the reference angle, or metres along the axis).
struct JointLimits {
    bool on = false;
    double lower = 0.0;
    double upper = 0.0;
};

/// Which way a spring acts.
enum class SpringSide : std::uint8_t {
    both,     ///< pushes when shorter than its rest length, pulls when longer
    pushOnly, ///< a bumper: only pushes the ends apart
    pullOnly, ///< a rubber band: only pulls them together
};

/// What a caller fills in to add a joint. Which fields a kind reads is said on each; the helpers
/// below (revoluteJoint, springJoint, ...) fill them from world points.
struct JointDef {
    JointKind kind = JointKind::revolute;
    JointEnd a, b;               ///< the two ends (every kind but gear); a may be the world
    Vec2 localAnchorA;           ///< in a's own frame (the world's for the world), m
    Vec2 localAnchorB;           ///< in b's own frame, m
    double referenceAngle = 0.0; ///< revolute, prismatic, weld: angle of b minus angle of a at rest, rad
    Vec2 localAxisA{1.0, 0.0};   ///< prismatic: the slide's direction in a's frame (unit)
    JointMotor motor;            ///< revolute, prismatic
    JointLimits limits;          ///< revolute (angle), prismatic (slide)
    /// spring: rest length (m), stiffness k (N/m) and damping c (N s/m); weld: 0 rigid, else the
    /// softness of both its point and its angle as a spring of `hertz` with `dampingRatio`.
    double restLength = 1.0;
    double stiffness = 0.0;
    double damping = 0.0;
    SpringSide springSide = SpringSide::both;
    double hertz = 0.0;        ///< weld only
    double dampingRatio = 1.0; ///< weld only
    /// pulley: the rope runs from a's anchor over fixed point groundA and from b's anchor over
    /// groundB: |pA - groundA| + ratio |pB - groundB| <= length (it only pulls).
    Vec2 groundA, groundB;
    double length = 0.0; ///< pulley: the rope's length, m
    /// gear: angleOrSlide(jointA) + ratio angleOrSlide(jointB) = constant; pulley: the rope's ratio.
    double ratio = 1.0;
    JointId jointA, jointB; ///< gear: a revolute, and a revolute or a prismatic
    /// Whether the two bodies it joins still collide with each other (Box2D's collideConnected).
    /// false, the default: a hinge's or a weld's overlapping parts, a spring's two balls pass
    /// through each other. Every kind but gear (whose joints' bodies decide).
    bool collideConnected = false;
};

/// A joint in the world: its definition and where its ends are this step.
struct Joint {
    JointDef def;
    int circleA = -1, bodyA = -1; ///< slots of a's circle or rigid body (World::circles(), bodies()), -1 for none
    int circleB = -1, bodyB = -1; ///< likewise for b
    int jointA = -1, jointB = -1; ///< gear: slots (World::joints()) of the joints it couples
    double gearConstant = 0.0;    ///< gear: coordA + ratio coordB when it was added
};

} // namespace rube
