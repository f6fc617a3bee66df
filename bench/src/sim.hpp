#pragma once
/// Sim: one engine-neutral interface over rube's methods and the peer engines, so every scene is
/// described once and every engine runs the very same bodies.

#include "rube/physics/vec2.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace bench {

using rube::Vec2;

/// A dynamic ball as a scene asks for it.
struct BallSpec {
    Vec2 position{};
    Vec2 velocity{};
    double radius = 0.5;
    double mass = 1.0;
    double bounciness = 1.0; ///< C; a pair's C is the product of both (rube's and Chipmunk's rule)
    double friction = 0.0;
    bool fast = false; ///< ask the engine for continuous detection (Box2D's bullet flag)
};

/// A static line, or a kinematic one when `velocity` is non-zero; two-sided, `radius` thick.
struct LineSpec {
    Vec2 a{};
    Vec2 b{1.0, 0.0};
    double radius = 0.0;
    double bounciness = 1.0; ///< 1 leaves the ball's own C under the product rule
    double friction = 0.0;
    Vec2 velocity{}; ///< constant velocity of a kinematic line, m/s
};

/// A joint between balls (or a ball and the world), as the joints scenes ask for it. Engines that
/// do not have the kind refuse it (Sim::addJoint returns false) and the scene is not run on them.
struct JointSpec {
    enum class Kind : std::uint8_t {
        pin,    ///< ball `a` pinned at its centre to the world, free to turn; a motor when maxTorque > 0
        gear,   ///< the pins of balls `a` and `b`: angle_a + ratio angle_b stays constant
        pulley, ///< a rope from ball a over groundA and from ball b over groundB: |pa - gA| + ratio |pb - gB| = length
        spring, ///< ball `a` on a damped spring to the fixed point `anchor`
    };
    Kind kind = Kind::pin;
    int a = 0, b = -1;
    double motorSpeed = 0.0, maxTorque = 0.0;                ///< pin: rad/s, N m
    double ratio = 1.0;                                      ///< gear, pulley
    Vec2 groundA{}, groundB{};                               ///< pulley
    double length = 0.0;                                     ///< pulley, m
    Vec2 anchor{};                                           ///< spring's fixed end
    double stiffness = 0.0, damping = 0.0, restLength = 0.0; ///< spring: N/m, N s/m, m
};

/// A box as a scene asks for it: dynamic unless `fixed`, its mass from a density (kg/m^2).
struct BoxSpec {
    Vec2 position{};
    double angle = 0.0; ///< radians, counter-clockwise
    Vec2 halfExtents{0.5, 0.5};
    double density = 1.0;
    double friction = 0.6;
    double bounciness = 0.0;
    bool fixed = false; ///< static: the ground of a pyramid, the walls of a bin
};

/// The world settings every engine is given.
struct WorldSpec {
    Vec2 gravity{0.0, -9.81};
    double timeStep = 1.0 / 60;
    bool rubeSleep = true;      ///< rube's sleeping islands, on by default as in a level (--rube-no-sleep: off)
    bool chipmunkSleep = false; ///< Chipmunk's sleeping, off by default in Chipmunk (--chipmunk-sleep: 0.5 s)
    int rubeWorkers = 1;        ///< rube's WorldDef::workers (--rube-workers)
};

/// A ball's state as read back after a step (outside the timed loop).
struct BallState {
    Vec2 position{};
    Vec2 velocity{};
    double angularVelocity = 0.0; ///< omega, rad/s, counter-clockwise (every engine here turns circles)
    double angle = 0.0;           ///< radians turned, counter-clockwise
};

/// A box's state as read back after a step (outside the timed loop).
struct BoxState {
    Vec2 position{};
    double angle = 0.0;
    Vec2 velocity{};
    double angularVelocity = 0.0;
};

/// One engine instance running one scene. Implementations own their world.
class Sim {
public:
    virtual ~Sim() = default;
    /// Adds a dynamic ball and returns its index (0, 1, 2, ... in the order added).
    virtual int addBall(const BallSpec& spec) = 0;
    /// Adds a static or kinematic line.
    virtual void addLine(const LineSpec& spec) = 0;
    /// Adds a box and returns its index among the boxes (0, 1, 2, ... in the order added); only
    /// engines whose Engine::boxes is true are given scenes with boxes.
    virtual int addBox(const BoxSpec& spec) {
        (void)spec;
        return -1;
    }
    /// Advances by one time step: the only call inside the timed loop.
    virtual void step() = 0;
    /// The number of balls added.
    virtual int ballCount() const = 0;
    /// Ball i's position and velocity now.
    virtual BallState ball(int i) const = 0;
    /// The number of boxes added.
    virtual int boxCount() const { return 0; }
    /// Box i's pose and velocity now.
    virtual BoxState box(int i) const {
        (void)i;
        return {};
    }
    /// Steps that hit the engine's own per-step cap (rube's event cap); 0 where there is none.
    virtual std::int64_t capsHit() const { return 0; }
    /// Adds a joint; false (and nothing added) when the engine or method does not have its kind.
    virtual bool addJoint(const JointSpec&) {
        lacksJoint_ = true;
        return false;
    }
    /// True once a scene asked for a joint this engine does not have: the scene is not run on it.
    bool lacksJoint() const { return lacksJoint_; }

protected:
    bool lacksJoint_ = false;
};

/// How an engine is run: one of rube's methods over the time-step sweep, or a peer at its usual step.
enum class EngineKind : std::uint8_t { rubeMethod, peer };

/// An engine the bench can run: a name for the CSV and a factory.
struct Engine {
    std::string name; ///< "rube-solver", "box2d-2.4.1", "chipmunk-7.0.3", ...
    EngineKind kind = EngineKind::rubeMethod;
    int order = 0; ///< position in the output (rube's methods first, then the peers)
    std::function<std::unique_ptr<Sim>(const WorldSpec&)> make;
    bool boxes = true; ///< runs scenes with boxes that turn (rube's solver and auto, and the peers)
};

/// Every engine linked into this build (adapters register themselves, see registerEngine).
std::vector<Engine>& engines();

/// Adds an engine at static-initialisation time; returns true so it can initialise a constant.
bool registerEngine(Engine engine);

} // namespace bench
