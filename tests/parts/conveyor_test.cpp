// The conveyor (game/src/items/conveyor.cpp): a crate set at rest on a running belt slips against it,
// and kinetic friction accelerates it along the belt at a = g (mu cos theta - sin theta), theta the
// rise in the way the belt carries (mu g on a level belt), until it moves with the belt: after
// t = v / a and s = v^2 / (2 a), then it rides at the belt's speed. Over belt speeds, the pair's
// frictions and four tilts (level, 15 degrees either way, 30), each carried up and down. Switched off
// it holds the crate (mu cos theta >= sin theta), a switch starts and stops it, a frictionless ball is
// not carried; and its messages.
#include "level_run.hpp"
#include "part_text.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

using namespace rube;
using namespace rube::game;
using rube::test::firstError;
using rube::test::num;

namespace {

constexpr double kBand = 0.1;       // the belt's half thickness, m
constexpr double kHalfCrate = 0.25; // a crate's half side, m
constexpr double kLength = 24.0;    // long enough for every run below, m

// A conveyor at the origin tilted by `degrees`, running at `speed` (or still: `on`), with a crate of
// friction `mu` at rest on its top `along` m from its centre, square to it.
std::string crateOnBelt(double degrees, double speed, double mu, double along, bool on = true) {
    const double t = degrees * std::numbers::pi / 180.0;
    const Vec2 x{std::cos(t), std::sin(t)}, n = x.perpendicular();
    const Vec2 crate = x * along + n * (kBand + kHalfCrate);
    return "name = \"t\"\n[world]\ntime_step = 0.01\nbounds = { min = [-40, -40], max = [40, 40] }\n"
           "[[item]]\nkind = \"conveyor\"\nname = \"belt\"\nposition = [0, 0]\nangle = " +
           num(degrees) + "\nlength = " + num(kLength) + "\nspeed = " + num(speed) +
           "\non = " + (on ? "true" : "false") + "\n[[item]]\nkind = \"crate\"\nname = \"box\"\nposition = [" +
           num(crate.x) + ", " + num(crate.y) + "]\nangle = " + num(degrees) + "\nfriction = " + num(mu) + "\n";
}

// The crate's velocity and travel along the belt's direction `x` from where it started.
struct Along {
    double velocity, travel;
};
Along along(const LevelRun& run, Vec2 start, Vec2 x) {
    const RigidBody& crate = run.world().body(run.states()[1].body);
    return {crate.velocity.dot(x), (crate.position - start).dot(x)};
}

} // namespace

TEST_CASE("conveyor: a crate at rest on it reaches the belt's speed after v / a and v^2 / (2 a), "
          "a = g (mu cos theta - sin theta), then rides at it",
          "[parts][conveyor]") {
    struct Tilt {
        double degrees;
        // Pairs that carry it up and hold it riding down, mu > tan theta, and that slide it rather than tip
        // it over backwards: a square crate's contact force passes outside its base when mu > 1.
        std::initializer_list<double> mus;
    };
    for (const Tilt tilt :
         {Tilt{0.0, {0.2, 0.4, 0.8}}, Tilt{15.0, {0.4, 0.8}}, Tilt{-15.0, {0.4, 0.8}}, Tilt{30.0, {0.7, 0.8}}}) {
        for (const double mu : tilt.mus) {
            for (const double speed : {0.5, 1.5, 3.0, -1.5}) {
                CAPTURE(tilt.degrees, mu, speed);
                // The crate starts on the end the belt carries away from, so all its run is on the belt.
                const double start = speed > 0.0 ? -0.4 * kLength : 0.4 * kLength;
                const SceneLoad load = parseScene(crateOnBelt(tilt.degrees, speed, mu, start), "t.toml");
                REQUIRE(load.ok());
                LevelRun run(*load.scene, {});
                const double g = -run.world().def().gravity.y, dt = run.world().def().timeStep;
                const double theta = tilt.degrees * std::numbers::pi / 180.0;
                // Along the way the belt carries: x; the rise that way is theta when carried towards b.
                const Vec2 x = Vec2::fromAngle(theta) * (speed > 0.0 ? 1.0 : -1.0);
                const double rise = speed > 0.0 ? theta : -theta;
                const double v = std::abs(speed);
                const double a = g * (mu * std::cos(rise) - std::sin(rise)); // kinetic friction less gravity's pull
                REQUIRE(a > 0.0);
                const Vec2 from = run.world().body(run.states()[1].body).position;
                // Step until it moves with the belt; its speed grows as a t all the way.
                std::optional<double> caughtUp;
                double travelled = 0.0;
                for (int i = 0; i < 2000 && !caughtUp; ++i) {
                    run.step();
                    const Along now = along(run, from, x);
                    const double time = run.world().time();
                    // Caught up when within 1 mm/s: the solver's friction impulse closes the last of the slip
                    // over a few iterations, not exactly in one.
                    if (now.velocity < v - 1e-3) {
                        CHECK(now.velocity == Approx(std::min(a * time, v)).margin(1e-3 + 0.01 * a * time));
                        continue;
                    }
                    caughtUp = time, travelled = now.travel;
                }
                REQUIRE(caughtUp);
                // Caught up within the step in which a t passes v: t = v / a, s = v^2 / (2 a) (+ v dt at most).
                CHECK(*caughtUp >= v / a - 1e-9);
                CHECK(*caughtUp < v / a + dt + 1e-9);
                CHECK(travelled == Approx(v * v / (2.0 * a)).margin(v * dt + 1e-3));
                // Then it rides with the belt: one second on, it has gone v x 1 s further at v.
                for (int i = 0; i < 100; ++i) run.step();
                const Along later = along(run, from, x);
                CHECK(later.velocity == Approx(v).margin(1e-4)); // within 0.1 mm/s: the solver's residual slip
                CHECK(later.travel - travelled == Approx(v * 1.0).margin(1e-3));
                const RigidBody& crate = run.world().body(run.states()[1].body);
                CHECK(std::abs(crate.angle - theta) < 1e-3); // it slid and rode square; it did not tip
            }
        }
    }
}

TEST_CASE("conveyor: switched off it holds a crate (mu cos theta >= sin theta), and a switch starts and stops it",
          "[parts][conveyor]") {
    for (const double degrees : {0.0, 15.0}) {
        CAPTURE(degrees);
        const SceneLoad load = parseScene(crateOnBelt(degrees, 1.5, 0.4, 0.0, false), "t.toml");
        REQUIRE(load.ok());
        LevelRun run(*load.scene, {});
        const double g = -run.world().def().gravity.y, theta = degrees * std::numbers::pi / 180.0;
        const double a = g * (0.4 * std::cos(theta) - std::sin(theta));
        const Vec2 x = Vec2::fromAngle(theta);
        const Vec2 from = run.world().body(run.states()[1].body).position;
        for (int i = 0; i < 200; ++i) run.step(); // two seconds still: it settles and holds
        CHECK(std::abs(along(run, from, x).velocity) < 1e-6);
        CHECK(std::abs(along(run, from, x).travel) < 1e-3);
        run.toggle(0); // started: it catches the belt's 1.5 m/s in 1.5 / a s
        const double startedAt = run.world().time();
        std::optional<double> caughtUp;
        for (int i = 0; i < 200 && !caughtUp; ++i) {
            run.step();
            if (along(run, from, x).velocity >= 1.5 - 1e-3) caughtUp = run.world().time() - startedAt;
        }
        REQUIRE(caughtUp);
        CHECK(*caughtUp == Approx(1.5 / a).margin(0.011));
        run.toggle(0); // stopped: now the crate slips forward over the still belt; friction stops it in 1.5 / a'
        const double a2 = g * (0.4 * std::cos(theta) + std::sin(theta)); // friction and gravity both hold it back
        const double stoppedAt = run.world().time();
        std::optional<double> stopped;
        for (int i = 0; i < 200 && !stopped; ++i) {
            run.step();
            if (along(run, from, x).velocity <= 1e-3) stopped = run.world().time() - stoppedAt;
        }
        REQUIRE(stopped);
        CHECK(*stopped == Approx(1.5 / a2).margin(0.011));
        for (int i = 0; i < 100; ++i) run.step();
        CHECK(std::abs(along(run, from, x).velocity) < 1e-6); // and stays: the belt is still
    }
}

TEST_CASE("conveyor: a frictionless ball on the running belt is not carried", "[parts][conveyor]") {
    const SceneLoad load = parseScene("name = \"t\"\n[world]\ntime_step = 0.01\n[[item]]\nkind = \"conveyor\"\n"
                                      "position = [0, 0]\nspeed = 3\n[[item]]\nkind = \"heavy\"\nposition = [0, " +
                                          num(kBand + 0.3) + "]\n",
                                      "t.toml");
    REQUIRE(load.ok());
    LevelRun run(*load.scene, {});
    for (int i = 0; i < 100; ++i) run.step();
    const Circle& ball = run.world().circle(run.states()[1].circle);
    CHECK(std::abs(ball.velocity.x) < 1e-12);
    CHECK(std::abs(ball.position.x) < 1e-12);
}

TEST_CASE("conveyor: read like every [[item]], with its own keys only", "[parts][conveyor]") {
    const std::string floor = "name = \"t\"\n[[segment]]\na = [-5, 0]\nb = [5, 0]\n";
    const std::string item = floor + "[[item]]\nkind = \"conveyor\"\nposition = [0, 1]\n";
    CHECK(firstError(item + "sped = 2\n") ==
          "t.toml:8:1: unknown key 'sped' in [[item]] of kind 'conveyor' (did you mean 'speed'?)");
    CHECK(firstError(floor + "[[item]]\nkind = \"convayor\"\nposition = [0, 1]\n")
              .ends_with("got 'convayor' (did you mean 'conveyor'?)"));
    CHECK(firstError(item + "speed = -2\nangle = 15\nlength = 3\nfriction = 0.5\non = false\n") == "no error");
    CHECK(firstError(item + "length = 0\n").starts_with("t.toml:8:10: length must be"));
    CHECK(firstError(item + "speed = \"fast\"\n").starts_with("t.toml:8:9: speed must be"));
    CHECK(firstError(item + "friction = -1\n").starts_with("t.toml:8:12: friction must be"));
    CHECK(firstError(item + "on = 1\n").starts_with("t.toml:8:6: on must be"));
}
