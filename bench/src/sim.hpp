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
};

/// A ball's state as read back after a step (outside the timed loop).
struct BallState {
    Vec2 position{};
    Vec2 velocity{};
    double angularVelocity = 0.0; ///< omega, rad/s, counter-clockwise (every engine here turns circles)
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
