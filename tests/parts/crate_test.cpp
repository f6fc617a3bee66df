// The crate (game/src/items/crate.cpp): a box sliding on a floor stops after s = v^2 / (2 mu g), mu the
// pair's friction (the crate's times the floor's, here 1), over speeds and frictions, within 1 %.
#include "level_run.hpp"
#include "scene_file.hpp"
#include "scene_number.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace rube;
using namespace rube::game;
using test::num;

namespace {

// A default crate resting on a floor of friction 1, sliding right at `speed`, its own friction `mu`.
std::string slidingCrate(double speed, double mu) {
    return "name = \"slide\"\n[world]\ntime_step = 0.01\n[[segment]]\na = [-2, 0]\nb = [40, 0]\nfriction = 1\n"
           "[[item]]\nkind = \"crate\"\nposition = [0, 0.25]\nvelocity = [" +
           num(speed) + ", 0]\nfriction = " + num(mu) + "\n";
}

} // namespace

TEST_CASE("crate: sliding at v on a floor it stops after v^2 / (2 mu g), within 1 %", "[parts][crate]") {
    for (const double mu : {0.2, 0.4, 0.8}) {
        for (const double speed : {1.0, 2.5, 5.0}) {
            CAPTURE(mu, speed);
            const SceneLoad load = parseScene(slidingCrate(speed, mu), "slide.toml");
            REQUIRE(load.ok());
            LevelRun run(*load.scene, {});
            const BodyId id = run.states()[0].body;
            const double g = -run.world().def().gravity.y;
            const double expected = speed * speed / (2.0 * mu * g);
            bool stopped = false;
            for (int i = 0; i < 2000 && !stopped; ++i) {
                run.step();
                stopped = std::abs(run.world().body(id).velocity.x) < 1e-6;
            }
            REQUIRE(stopped);
            const RigidBody& crate = run.world().body(id);
            CHECK(crate.position.x == Approx(expected).epsilon(0.01));
            CHECK(std::abs(crate.angle) < 1e-3); // it slid; it did not tip
            CHECK(crate.position.y == Approx(0.25).margin(0.01));
        }
    }
}

TEST_CASE("crate: its size, mass and friction as the descriptor says", "[parts][crate]") {
    const SceneLoad load = parseScene("name = \"c\"\n[[item]]\nkind = \"crate\"\nposition = [0, 1]\n[[item]]\nkind = "
                                      "\"crate\"\nposition = [2, 1]\nsize = [1, 0.4]\nmass = 3\nangle = 90\n",
                                      "c.toml");
    REQUIRE(load.ok());
    LevelRun run(*load.scene, {});
    const RigidBody& made = run.world().body(run.states()[0].body);
    CHECK(made.halfExtents == Vec2{0.25, 0.25});
    CHECK(1.0 / made.inverseMass == Approx(10.0));
    CHECK(made.material.friction == 0.4);
    CHECK(made.material.bounciness == 0.2);
    const RigidBody& set = run.world().body(run.states()[1].body);
    CHECK(set.halfExtents == Vec2{0.5, 0.2});
    CHECK(1.0 / set.inverseMass == Approx(3.0));
    CHECK(set.angle == Approx(std::acos(-1.0) / 2));
}
