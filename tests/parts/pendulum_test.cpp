// The pendulum (game/src/items/pendulum.cpp): a round bob of radius r on a light rod of length L.
// Released from theta0 it reaches the bottom at v = sqrt(2 g L (1 - cos theta0)) x L / sqrt(L^2 + r^2 / 2)
// (energy, the bob a disc turning with its rod; the point-mass law within 0.4 % for r <= L / 8), over
// lengths, start angles and masses; small swings (theta0 <= 10 degrees) take the period
// T = 2 pi sqrt((L^2 + r^2 / 2) / (g L)) (1 + theta0^2 / 16), the simple pendulum's 2 pi sqrt(L / g)
// with the exact period series' first term; its energy does not grow over ten swings; latched, it
// holds until released. And its messages for bad keys and values.
#include "level_run.hpp"
#include "part_text.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

using namespace rube;
using namespace rube::game;
using rube::test::firstError;
using rube::test::num;

namespace {

constexpr double kG = 9.81;

double radiansOf(double degrees) { return degrees * std::numbers::pi / 180.0; }

LevelRun pendulum(double degrees, double length, double mass, double radius, bool latched) {
    const std::string text = "name = \"pendulum-test\"\n[world]\ntime_step = 0.01\nbounds = { min = [-30, -30], max = "
                             "[30, 30] }\n[[item]]\nkind = \"pendulum\"\nname = \"bob\"\nposition = [0, 0]\nangle = " +
                             num(degrees) + "\nlength = " + num(length) + "\nmass = " + num(mass) +
                             "\nradius = " + num(radius) + "\nlatched = " + (latched ? "true" : "false") + "\n";
    const SceneLoad load = parseScene(text, "pendulum-test.toml");
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return LevelRun(*load.scene, {});
}

const Circle& bobOf(const LevelRun& run) { return run.world().circle(run.states()[0].circle); }

// The bob's energy with the pivot at height 0: (1/2) m v^2 + (1/2) I_c omega^2 + m g y.
double energy(const Circle& bob, double mass, double radius) {
    return 0.5 * mass * bob.velocity.dot(bob.velocity) +
           0.25 * mass * radius * radius * bob.angularVelocity * bob.angularVelocity + mass * kG * bob.position.y;
}

// (1/2) I omega^2 = m g L (1 - cos theta0), I = m (L^2 + r^2 / 2) about the pivot, v = omega L.
double speedAtBottom(double degrees, double length, double radius) {
    return std::sqrt(2.0 * kG * length * (1.0 - std::cos(radiansOf(degrees)))) * length /
           std::sqrt(length * length + 0.5 * radius * radius);
}

} // namespace

TEST_CASE("a released pendulum's bob reaches the bottom at v = sqrt(2 g L (1 - cos theta0)), for a disc's inertia",
          "[parts][pendulum]") {
    for (const double length : {0.8, 2.0, 5.0}) {
        for (const double degrees : {15.0, 45.0, 90.0, -60.0, 135.0}) {
            for (const double mass : {1.0, 10.0, 80.0}) {
                const double radius = 0.1 * length; // r <= L / 8: the point-mass law within 0.4 %
                INFO("L " << length << " m, theta0 " << degrees << " degrees, " << mass << " kg");
                LevelRun run = pendulum(degrees, length, mass, radius, false);
                const double expected = speedAtBottom(degrees, length, radius);
                // The point-mass law, which the disc's factor L / sqrt(L^2 + r^2 / 2) corrects by under 0.4 %.
                CHECK(expected ==
                      Approx(std::sqrt(2.0 * kG * length * (1.0 - std::cos(radiansOf(degrees))))).epsilon(0.004));
                // Fastest at the bottom of the arc, which a quarter of a period reaches (at most 0.6 s x
                // sqrt(L) for theta0 <= 135 degrees); the bob stays on its rod, L from the pivot.
                const double quarter = 0.25 * 2.0 * std::numbers::pi * std::sqrt(length / kG) * 2.0;
                double fastest = 0.0, lowest = 0.0, offRod = 0.0;
                for (int i = 0; i * 0.01 < quarter; ++i) {
                    run.step();
                    const Circle& bob = bobOf(run);
                    fastest = std::max(fastest, std::sqrt(bob.velocity.dot(bob.velocity)));
                    lowest = std::min(lowest, bob.position.y);
                    offRod = std::max(offRod, std::abs(bob.position.length() - length));
                }
                CHECK(fastest == Approx(expected).epsilon(0.005));
                CHECK(lowest == Approx(-length).epsilon(1e-3));
                CHECK(offRod < 2e-3);
            }
        }
    }
}

TEST_CASE("a pendulum's small swings take T = 2 pi sqrt(L / g) (1 + theta0^2 / 16), for a disc's inertia",
          "[parts][pendulum]") {
    for (const double length : {0.5, 1.0, 2.0, 4.0}) {
        for (const double degrees : {5.0, 10.0}) {
            const double radius = 0.1 * length;
            INFO("L " << length << " m, theta0 " << degrees << " degrees");
            LevelRun run = pendulum(degrees, length, 10.0, radius, false);
            const double theta0 = radiansOf(degrees);
            const double expected = 2.0 * std::numbers::pi *
                                    std::sqrt((length * length + 0.5 * radius * radius) / (kG * length)) *
                                    (1.0 + theta0 * theta0 / 16.0);
            // The times the bob crosses the bottom moving left (x from + to -), interpolated in the step:
            // one period apart.
            std::vector<double> crossings;
            double x = bobOf(run).position.x;
            for (int i = 0; crossings.size() < 4 && i < 10000; ++i) {
                run.step();
                const double now = bobOf(run).position.x;
                if (x > 0.0 && now <= 0.0) crossings.push_back(run.world().time() - 0.01 * now / (now - x));
                x = now;
            }
            REQUIRE(crossings.size() == 4);
            const double period = (crossings[3] - crossings[0]) / 3.0;
            CHECK(period == Approx(expected).epsilon(0.003));
            // The simple pendulum's 2 pi sqrt(L / g), which the disc and the amplitude lengthen by under 1 %.
            CHECK(period == Approx(2.0 * std::numbers::pi * std::sqrt(length / kG)).epsilon(0.01));
        }
    }
}

TEST_CASE("a pendulum's energy does not grow over ten swings", "[parts][pendulum]") {
    for (const double length : {1.0, 3.0}) {
        for (const double degrees : {30.0, 90.0, 150.0}) {
            for (const double mass : {1.0, 50.0}) {
                const double radius = 0.3;
                INFO("L " << length << " m, theta0 " << degrees << " degrees, " << mass << " kg");
                LevelRun run = pendulum(degrees, length, mass, radius, false);
                const double start = energy(bobOf(run), mass, radius), scale = mass * kG * length;
                const double swing = 2.0 * std::numbers::pi * std::sqrt(length / kG);
                // At each end of a swing (the bob at rest for an instant, the rod's tension least) the
                // energy is all m g y: it must never rise above the last end's. Between the ends the
                // soft rod stretches under its tension and the sum wavers (within 0.5 % of m g L); from end to end
                // it wavers by under 1e-5 m g L (measured), which the 1e-4 allows.
                std::vector<double> ends;
                double most = start, previousSpeed = 0.0;
                bool rising = false;
                for (int i = 0; i * 0.01 < 10.0 * swing; ++i) {
                    run.step();
                    const Circle& bob = bobOf(run);
                    const double speed = std::sqrt(bob.velocity.dot(bob.velocity));
                    if (rising && speed > previousSpeed) ends.push_back(energy(bob, mass, radius));
                    rising = speed < previousSpeed;
                    previousSpeed = speed;
                    most = std::max(most, energy(bob, mass, radius));
                }
                REQUIRE(ends.size() >= 10); // ten swings at least (fewer, slower, from high up)
                for (std::size_t k = 1; k < ends.size(); ++k) CHECK(ends[k] - ends[k - 1] < 1e-4 * scale);
                CHECK(ends.back() <= start);
                CHECK(most - start < 5e-3 * scale);
            }
        }
    }
}

TEST_CASE("a latched pendulum holds its bob aside until released", "[parts][pendulum]") {
    for (const double length : {1.0, 10.0}) {
        for (const double degrees : {90.0, -45.0, 165.0}) {
            for (const double mass : {1.0, 100.0}) {
                INFO("L " << length << " m, theta0 " << degrees << " degrees, " << mass << " kg");
                LevelRun run = pendulum(degrees, length, mass, 0.3, true);
                const Vec2 start = bobOf(run).position;
                // The latch (a motor at speed 0) and the rod are soft as every joint: over 5 s the bob
                // gives a little, under 0.5 mm per metre of rod (0.29 mm measured).
                for (int i = 0; i < 500; ++i) run.step();
                CHECK(bobOf(run).position.distance(start) < 5e-4 * length);
                run.toggle(0);
                for (int i = 0; i < 50; ++i) run.step();
                CHECK(bobOf(run).position.distance(start) > 0.05);
            }
        }
    }
}

TEST_CASE("pendulum: read like every [[item]], with its own keys only", "[parts][pendulum]") {
    const std::string item = "name = \"t\"\n[[item]]\nkind = \"pendulum\"\nposition = [0, 3]\n";
    CHECK(firstError(item) == "no error");
    CHECK(firstError(item + "lenght = 2\n") ==
          "t.toml:5:1: unknown key 'lenght' in [[item]] of kind 'pendulum' (did you mean 'length'?)");
    CHECK(firstError(item + "length = 0.2\n") ==
          "t.toml:5:10: length 0.2 m must be longer than the bob's radius, 0.3 m");
    CHECK(firstError(item + "mass = 0\n").starts_with("t.toml:5:8: mass must be"));
    CHECK(firstError(item + "mass = 500\n").starts_with("t.toml:5:8: mass must be"));
    CHECK(firstError(item + "latched = 1\n").starts_with("t.toml:5:11: latched must be"));
}
