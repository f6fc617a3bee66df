// The feather level against its analytic answer: under the level's own air drag and method (auto),
// the thrown ball follows the exact solution of dv/dt = g - k v / m and sinks at the terminal speed
// v_t = m g / k, k = 2r linear (fields.hpp); and placements that would work in still air fail in it.
#include "level_run.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

using namespace rube;
using namespace rube::game;

namespace {

SceneDesc loadFeather() {
    const SceneLoad load = loadSceneFile(std::filesystem::path(RUBE_GAME_LEVELS_DIR) / "feather.toml");
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return *load.scene;
}

// A ramp placed as a script places it: centre and angle in degrees.
std::vector<Placement> ramp(Vec2 centre, double degrees) {
    return {{partKind("ramp"), centre, degrees * std::numbers::pi / 180.0, "", {}, degrees}};
}

// Plays the level for its time limit with these placements; the goal frame, if reached.
std::optional<std::int64_t> goalStep(const SceneDesc& level, const std::vector<Placement>& placements) {
    REQUIRE_FALSE(checkPlacements(level, placements));
    LevelRun run(level, placements);
    const auto steps = static_cast<std::int64_t>(*level.level.goal->timeLimit / level.world.timeStep);
    for (std::int64_t i = 0; i < steps && !run.goalStep(); ++i) run.step();
    return run.goalStep();
}

SceneDesc withoutAir(SceneDesc level) {
    level.world.airDrag = AirDrag{};
    return level;
}

} // namespace

TEST_CASE("feather: the thrown ball follows the exact solution under drag and sinks at v_t = m g / (2r linear)",
          "[level][fields][drag]") {
    const SceneDesc level = loadFeather();
    REQUIRE(level.world.method == Method::automatic); // the level's default: what a player gets
    LevelRun run(level, {});
    const Circle& ball = run.world().circle(run.states()[static_cast<std::size_t>(run.find("feather"))].circle);
    const Vec2 p0 = ball.position, v0 = ball.velocity;
    const double m = 1.0 / ball.inverseMass, g = -level.world.gravity.y;
    const double k = 2.0 * ball.radius * level.world.airDrag.linear;
    const double tau = m / k, terminal = g * tau;
    CHECK(terminal == Approx(0.5 * 9.81 / 1.5)); // the bouncy ball: 0.5 kg, r = 0.25 m, linear = 3: 3.27 m/s
    // In free flight, up to the step before it first touches the floor: x(t) = x0 + v0 tau (1 - e^{-t/tau}),
    // y(t) = y0 - v_t t + v_t tau (1 - e^{-t/tau}); v = (v0 e^{-t/tau}, -v_t (1 - e^{-t/tau})).
    double worstPosition = 0.0, worstVelocity = 0.0, t = 0.0;
    Vec2 last = p0, lastVelocity = v0;
    for (;;) {
        run.step();
        if (run.world().stats().impacts > 0 || run.world().time() > 5.0) break;
        t = run.world().time();
        last = ball.position;
        lastVelocity = ball.velocity;
        const double share = -std::expm1(-t / tau);
        const Vec2 expected{p0.x + v0.x * tau * share, p0.y - terminal * t + terminal * tau * share};
        const Vec2 expectedVelocity{v0.x * (1.0 - share), -terminal * share};
        worstPosition = std::max(worstPosition, (last - expected).length());
        worstVelocity = std::max(worstVelocity, (lastVelocity - expectedVelocity).length());
    }
    CAPTURE(t, worstPosition, worstVelocity, lastVelocity.length(), terminal);
    CHECK(run.world().stats().autoSolverSteps == 0); // auto chose exact for the whole flight
    CHECK(t > 1.5);
    CHECK(worstPosition < 1e-9);
    CHECK(worstVelocity < 1e-9);
    // Near the floor, after 5.5 time constants, it falls at its terminal speed within 1 %
    // (e^{-5.5} = 0.4 % short), and its drift has ended v0 tau from where it was thrown.
    CHECK(t > 5.0 * tau);
    CHECK(lastVelocity.length() == Approx(terminal).epsilon(0.01));
    CHECK(last.x == Approx(p0.x + v0.x * tau).margin(0.015)); // what is left of it, v0 tau e^{-t/tau}, is 9 mm
    // In still air the same throw lands 4 m further on, x0 + v0 sqrt(2 h / g).
    CHECK(p0.x + v0.x * std::sqrt(2.0 * (p0.y - ball.radius) / g) - last.x > 4.0);
}

TEST_CASE("feather: the ramp under the drift's end slides the ball into the bucket", "[level][fields][drag]") {
    const SceneDesc level = loadFeather();
    CHECK(goalStep(level, ramp({-2.6, 2.0}, -25.0)));
}

TEST_CASE("feather: what would work in still air fails in the level's air", "[level][fields][drag]") {
    const SceneDesc level = loadFeather();
    // Nothing placed: without air the throw lands in the bucket by itself; in the air it sinks 2 m short.
    CHECK(goalStep(withoutAir(level), {}));
    CHECK_FALSE(goalStep(level, {}));
    // A chute where the throw would come down in still air: the drifting ball falls behind it.
    const auto chute = ramp({-2.2, 3.4}, -40.0);
    CHECK(goalStep(withoutAir(level), chute));
    CHECK_FALSE(goalStep(level, chute));
    // The ramp tilted the other way carries the caught ball away from the bucket.
    CHECK_FALSE(goalStep(level, ramp({-2.6, 2.0}, 25.0)));
}
