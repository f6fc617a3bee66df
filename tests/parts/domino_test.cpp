// The domino (game/src/items/domino.cpp): stood on one bottom corner at an angle a from upright and let
// go, it falls back towards upright (and never leans further) when a < atan(t / h), its centre of mass
// still over its base, and falls over when a > atan(t / h), t / h = 7.5 / 48 (8.88 degrees), over
// heights and either side of that angle.
#include "level_run.hpp"
#include "scene_file.hpp"
#include "scene_number.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

using namespace rube;
using namespace rube::game;
using test::num;

namespace {

constexpr double kThicknessPerHeight = 7.5 / 48.0;

// A domino of `height` turned `degrees` counter-clockwise, its lower-left corner on a floor of
// friction 1 at the origin: its centre is that corner plus R(a) (t/2, h/2).
std::string tiltedDomino(double height, double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    const Vec2 half{0.5 * kThicknessPerHeight * height, 0.5 * height};
    const Vec2 centre{half.x * std::cos(a) - half.y * std::sin(a), half.x * std::sin(a) + half.y * std::cos(a)};
    return "name = \"tip\"\n[world]\ntime_step = 0.01\n[[segment]]\na = [-3, 0]\nb = [3, 0]\nfriction = 1\n"
           "[[item]]\nkind = \"domino\"\nposition = [" +
           num(centre.x) + ", " + num(centre.y) + "]\nangle = " + num(degrees) + "\nheight = " + num(height) + "\n";
}

} // namespace

TEST_CASE("domino: tipped past atan(t / h) it falls, short of it it stands back up", "[parts][domino]") {
    const double tipping = std::atan(kThicknessPerHeight) * 180.0 / std::numbers::pi; // 8.88 degrees
    for (const double height : {0.25, 0.5, 1.0}) {
        for (const double off : {-2.0, -0.5, 0.5, 2.0}) {
            const double degrees = tipping + off;
            CAPTURE(height, degrees);
            const SceneLoad load = parseScene(tiltedDomino(height, degrees), "tip.toml");
            REQUIRE(load.ok());
            LevelRun run(*load.scene, {});
            const BodyId id = run.states()[0].body;
            double highest = degrees; // the most it leans left, degrees
            for (int i = 0; i < 300; ++i) {
                run.step();
                highest = std::max(highest, run.world().body(id).angle * 180.0 / std::numbers::pi);
            }
            const double angle = run.world().body(id).angle * 180.0 / std::numbers::pi;
            if (off < 0.0) {
                CHECK(highest < degrees + 1e-6);  // it never leans further: it falls back towards upright
                CHECK(std::abs(angle) < tipping); // and after 3 s it rocks on its base, standing
            } else {
                CHECK(angle > 60.0); // over, to the left
            }
        }
    }
}

TEST_CASE("domino: size and mass from its height, as the descriptor says", "[parts][domino]") {
    for (const double height : {0.5, 0.2, 1.5}) {
        CAPTURE(height);
        const SceneLoad load = parseScene(
            "name = \"d\"\n[[item]]\nkind = \"domino\"\nposition = [0, 1]\nheight = " + num(height) + "\n", "d.toml");
        REQUIRE(load.ok());
        LevelRun run(*load.scene, {});
        const RigidBody& b = run.world().body(run.states()[0].body);
        CHECK(b.halfExtents.y == Approx(0.5 * height));
        CHECK(b.halfExtents.x == Approx(0.5 * height * 7.5 / 48.0));
        CHECK(1.0 / b.inverseMass == Approx(500.0 * height * (height / 2) * (7.5 * height / 48.0)));
    }
}
