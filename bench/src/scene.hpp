#pragma once
/// Scene: a self-describing bench scene, one per file in bench/scenes/ (the Chipmunk demos' idea):
/// its name, how long it runs, how to build it on any engine, and what it measures.

#include "sim.hpp"

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace bench {

/// What a scene's probe reports after the measurement run; NaN means "not measured here".
struct Metrics {
    double error = std::numeric_limits<double>::quiet_NaN();   ///< the scene's headline error
    double error2 = std::numeric_limits<double>::quiet_NaN();  ///< its second error, if it has one
    double overlap = std::numeric_limits<double>::quiet_NaN(); ///< largest overlap measured, m
    int tunnels = -1;                                          ///< balls that passed through a line
    double momentum =
        std::numeric_limits<double>::quiet_NaN(); ///< relative momentum error, where a scene keeps momentum
};

/// Watches one measurement run: called after every step, never inside the timed loop.
class Probe {
public:
    virtual ~Probe() = default;
    /// Called after step number `step` (1-based) when the world's time is `time` seconds.
    virtual void observe(const Sim& sim, int step, double time) = 0;
    /// The scene's errors once the run is over.
    virtual Metrics finish(const Sim& sim) = 0;
};

/// Sizes a scene is built at: the full bench, or --quick's tiny version for CI.
struct SceneSize {
    bool quick = false;
};

/// A bench scene. `build` adds the same bodies to any Sim, so rube and the peers run one scene.
struct Scene {
    std::string name;
    std::string errorName;  ///< what `error` measures and its unit, for the CSV and chart
    std::string error2Name; ///< what `error2` measures, or empty
    bool logError = true;   ///< chart the error on a log axis (false for counts)
    Vec2 gravity{0.0, -9.81};
    std::function<double(const SceneSize&)> duration;      ///< simulated seconds
    rube::Vec2 boundsMin{-1e6, -1e6}, boundsMax{1e6, 1e6}; ///< a ball whose centre leaves them escaped
    std::function<void(Sim&, const SceneSize&)> build;
    std::function<std::unique_ptr<Probe>(const SceneSize&, double timeStep)> probe;
    bool boxes = false;      ///< has boxes that turn: run only by engines with Engine::boxes, at 60 Hz (like for like)
    double runTimeLimit = 0; ///< seconds a measurement run may take, when more than RunOptions' (large pyramids)
    int scalingBodies = 0; ///< > 0: a point of the scaling sweep with this many bodies (rube's solver and the peers at
                           ///< 60 Hz, its own chart)
};

/// Every scene compiled in, in registration order (sorted by name when listed).
std::vector<Scene>& scenes();

/// Adds a scene at static-initialisation time; returns true so it can initialise a constant.
bool registerScene(Scene scene);

} // namespace bench
