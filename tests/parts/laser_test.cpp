// The laser, mirror and detector (game/src/items/laser.cpp, mirror.cpp, detector.cpp): a beam routed
// through three mirrors at random angles reaches its detector within 1e-9 m of the point the reflect
// formula r = d - 2 (d.n) n gives, computed here on its own (each mirror's face line, its radius off
// the centre line; the detector's circle); a ball in the way stops it; a laser switched on by a
// trigger shines from then, and the detector switches what it names once.
#include "level_run.hpp"
#include "part_text.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <random>
#include <string>

using namespace rube;
using namespace rube::game;
using rube::test::num;

namespace {

constexpr double kMirrorRadius = 0.05; // a board's half thickness (part_common.hpp)
constexpr double kMirrorLength = 1.5;  // the test's mirrors, m
constexpr double kDetectorRadius = 0.5;
constexpr double kLaserRadius = 0.25;

struct Route {
    Vec2 mirrors[3];
    double mirrorDegrees[3];
    Vec2 detector;
};

// A route right, up, right and up again through three mirrors: leg directions are drawn at random,
// each mirror turned so its normal bisects the beam's turn there (the reflect formula's mirror).
Route randomRoute(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto deg = [](double d) { return d * std::numbers::pi / 180.0; };
    const double legs[4] = {0.0, deg(60.0 + 75.0 * unit(rng)), deg(30.0 * unit(rng)), deg(60.0 + 60.0 * unit(rng))};
    Route route;
    Vec2 at{0.0, 0.0};
    for (int i = 0; i < 4; ++i) {
        at = at + Vec2::fromAngle(legs[i]) * (3.0 + 2.0 * unit(rng));
        if (i == 3) {
            route.detector = at;
            break;
        }
        route.mirrors[i] = at;
        const Vec2 normal = (Vec2::fromAngle(legs[i + 1]) - Vec2::fromAngle(legs[i])).normalized();
        const Vec2 axis = normal.perpendicular();
        route.mirrorDegrees[i] = std::atan2(axis.y, axis.x) * 180.0 / std::numbers::pi;
    }
    return route;
}

std::string routeLevel(const Route& route, const std::string& extra = "", bool on = true) {
    std::string text = "name = \"t\"\n[world]\ntime_step = 0.01\ngravity = [0, 0]\n"
                       "[[item]]\nkind = \"laser\"\nname = \"beam\"\nposition = [0, 0]\non = " +
                       std::string(on ? "true" : "false") + "\n";
    for (int i = 0; i < 3; ++i)
        text += "[[item]]\nkind = \"mirror\"\nposition = [" + num(route.mirrors[i].x) + ", " + num(route.mirrors[i].y) +
                "]\nangle = " + num(route.mirrorDegrees[i]) + "\nlength = " + num(kMirrorLength) + "\n";
    text += "[[item]]\nkind = \"detector\"\nname = \"eye\"\nposition = [" + num(route.detector.x) + ", " +
            num(route.detector.y) + "]\nradius = " + num(kDetectorRadius) + "\ntriggers = \"tnt\"\n" +
            "[[item]]\nkind = \"bomb\"\nname = \"tnt\"\nposition = [-30, -30]\ntrigger = \"switch\"\n" + extra;
    return text;
}

// Where the reflect formula takes the beam: from the laser's muzzle, off each mirror's face (the
// line `radius` off its centre line on the side the beam comes from), into the detector's circle.
// None when the beam would miss a mirror's face or the detector.
std::optional<Vec2> reflectFormulaEnd(const Route& route) {
    Vec2 d{1.0, 0.0};
    Vec2 o = d * kLaserRadius;
    for (int i = 0; i < 3; ++i) {
        const double a = route.mirrorDegrees[i] * std::numbers::pi / 180.0;
        const Vec2 axis{std::cos(a), std::sin(a)};
        Vec2 n{-axis.y, axis.x};
        if (d.x * n.x + d.y * n.y > 0.0) n = Vec2{-n.x, -n.y};
        const Vec2 face = route.mirrors[i] + n * kMirrorRadius;
        const double t = ((face.x - o.x) * n.x + (face.y - o.y) * n.y) / (d.x * n.x + d.y * n.y);
        const Vec2 q = o + d * t;
        if (std::abs((q - route.mirrors[i]).dot(axis)) > 0.5 * kMirrorLength) return std::nullopt;
        const double dn = d.x * n.x + d.y * n.y;
        d = Vec2{d.x - 2.0 * dn * n.x, d.y - 2.0 * dn * n.y}; // r = d - 2 (d.n) n
        o = q;
    }
    // The detector: |o + t d - c|^2 = R^2, the smaller root.
    const Vec2 m = o - route.detector;
    const double b = m.x * d.x + m.y * d.y, c = m.x * m.x + m.y * m.y - kDetectorRadius * kDetectorRadius;
    if (b * b - c < 0.0) return std::nullopt;
    const double t = -b - std::sqrt(b * b - c);
    return o + d * t;
}

std::optional<GameEvent> detectorHit(const LevelRun& run) {
    for (const GameEvent& e : run.events())
        if (e.kind == EventKind::hit && e.item == "eye") return e;
    return std::nullopt;
}

int explosions(const LevelRun& run) {
    int n = 0;
    for (const GameEvent& e : run.events()) n += e.kind == EventKind::explosion ? 1 : 0;
    return n;
}

} // namespace

TEST_CASE("laser: a beam through three mirrors at random angles reaches its detector within 1e-9 m of the reflect "
          "formula",
          "[parts][laser]") {
    std::mt19937_64 rng(2026);
    int checked = 0;
    for (int sample = 0; sample < 200; ++sample) {
        const Route route = randomRoute(rng);
        const auto expected = reflectFormulaEnd(route);
        if (!expected) continue; // the mirrors' thickness moved the beam off a face: not this route
        CAPTURE(sample, route.mirrorDegrees[0], route.mirrorDegrees[1], route.mirrorDegrees[2]);
        const SceneLoad load = parseScene(routeLevel(route), "t.toml");
        REQUIRE(load.ok());
        LevelRun run(*load.scene, {});
        run.step();
        const auto hit = detectorHit(run);
        REQUIRE(hit);
        CHECK(hit->by == "beam");
        CHECK(hit->step == 1);
        CHECK(hit->position.distance(*expected) < 1e-9);
        CHECK(explosions(run) == 1); // the detector switched its bomb
        for (int i = 0; i < 10; ++i) run.step();
        CHECK(explosions(run) == 1); // once
        ++checked;
    }
    CHECK(checked > 150);
}

TEST_CASE("laser: a ball in the beam's way stops it short of the detector", "[parts][laser]") {
    std::mt19937_64 rng(7);
    int checked = 0;
    for (int sample = 0; sample < 50; ++sample) {
        const Route route = randomRoute(rng);
        if (!reflectFormulaEnd(route)) continue;
        // A still ball (no gravity) across the middle of the second leg, between mirrors 1 and 2.
        const Vec2 middle = (route.mirrors[0] + route.mirrors[1]) * 0.5;
        const SceneLoad load = parseScene(routeLevel(route, "[[item]]\nkind = \"steel\"\nposition = [" + num(middle.x) +
                                                                ", " + num(middle.y) + "]\n"),
                                          "t.toml");
        REQUIRE(load.ok());
        LevelRun run(*load.scene, {});
        for (int i = 0; i < 20; ++i) run.step();
        CHECK_FALSE(detectorHit(run));
        CHECK(explosions(run) == 0);
        ++checked;
    }
    CHECK(checked > 30);
}

TEST_CASE("laser: one that starts off shines from the step it is switched on, and off again when switched",
          "[parts][laser]") {
    std::mt19937_64 rng(3);
    Route route = randomRoute(rng);
    while (!reflectFormulaEnd(route)) route = randomRoute(rng);
    for (const int switchAt : {0, 5, 30}) {
        const SceneLoad load = parseScene(routeLevel(route, "", false), "t.toml");
        REQUIRE(load.ok());
        LevelRun run(*load.scene, {});
        for (int i = 0; i < 40; ++i) {
            if (i == switchAt) run.toggle(0);
            run.step();
        }
        const auto hit = detectorHit(run);
        REQUIRE(hit);
        CHECK(hit->step == switchAt + 1);
    }
    // Switched on and off before a step: dark.
    const SceneLoad load = parseScene(routeLevel(route, "", false), "t.toml");
    REQUIRE(load.ok());
    LevelRun run(*load.scene, {});
    run.toggle(0);
    run.toggle(0);
    for (int i = 0; i < 10; ++i) run.step();
    CHECK_FALSE(detectorHit(run));
}
