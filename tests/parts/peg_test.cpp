// The peg (game/src/items/peg.cpp): a small fixed pin whose bounce is the product of bounciness
// (lecture 3), read with the same messages as every [[item]].
#include "level_run.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace rube;
using namespace rube::game;

namespace {

constexpr double kPegRadius = 0.12;    // the peg's default radius, m
constexpr double kPegBounciness = 0.8; // its bounciness

// A ball of `kind` (radius r, bounciness c) resting `gap` m above the top of a peg at the origin.
std::string dropOnPeg(const std::string& kind, double gap, double r) {
    return "name = \"peg\"\n[world]\ntime_step = 0.01\n[[item]]\nkind = \"peg\"\nposition = [0, 0]\n[[item]]\nkind = "
           "\"" +
           kind + "\"\nposition = [0, " + std::to_string(kPegRadius + r + gap) + "]\n";
}

std::string firstError(const std::string& text) {
    const SceneLoad load = parseScene(text, "t.toml");
    return load.errors.empty() ? std::string("no error") : load.errors.front().format();
}

} // namespace

TEST_CASE("peg: a ball dropped on its top leaves with (C_ball x C_peg) of its speed, and the peg stays put",
          "[parts][peg]") {
    struct Ball {
        const char* kind;
        double radius, bounciness;
    };
    for (const Ball ball : {Ball{"heavy", 0.3, 0.2}, Ball{"bouncy", 0.25, 0.95}, Ball{"steel", 0.2, 0.7}}) {
        for (const double gap : {0.5, 1.0, 2.0, 4.0}) {
            CAPTURE(ball.kind, gap);
            const SceneLoad load = parseScene(dropOnPeg(ball.kind, gap, ball.radius), "peg.toml");
            REQUIRE(load.ok());
            LevelRun run(*load.scene, {});
            const CircleId peg = run.states()[0].circle, moving = run.states()[1].circle;
            const double start = run.world().circle(moving).position.y;
            const double contact = start - gap; // the ball's centre when it touches the peg's top
            const double g = -run.world().def().gravity.y;
            // Find the first step after the bounce: in free flight v^2 + 2 g (y - contact) is the rebound
            // speed squared, (C_ball C_peg)^2 x 2 g gap, whenever in the step after the impact it is measured.
            bool bounced = false;
            for (int i = 0; i < 1000 && !bounced; ++i) {
                run.step();
                const Circle& c = run.world().circle(moving);
                if (c.velocity.y <= 0.0) continue;
                bounced = true;
                const double e = ball.bounciness * kPegBounciness;
                const double rebound = c.velocity.y * c.velocity.y + 2.0 * g * (c.position.y - contact);
                CHECK(rebound == Approx(e * e * 2.0 * g * gap).epsilon(1e-9));
                CHECK(std::abs(c.velocity.x) < 1e-12); // straight down on its top: no kick aside
            }
            REQUIRE(bounced);
            const Circle& pin = run.world().circle(peg);
            CHECK(pin.motion == Motion::fixed);
            CHECK(pin.position == Vec2{0.0, 0.0});
            CHECK(pin.radius == kPegRadius);
        }
    }
}

TEST_CASE("peg: read like every [[item]], with its own keys only", "[parts][peg]") {
    const std::string floor = "name = \"t\"\n[[segment]]\na = [-5, 0]\nb = [5, 0]\n";
    CHECK(firstError(floor + "[[item]]\nkind = \"peg\"\nposition = [0, 1]\nraduis = 0.2\n") ==
          "t.toml:8:1: unknown key 'raduis' in [[item]] of kind 'peg' (did you mean 'radius'?)");
    CHECK(firstError(floor + "[[item]]\nkind = \"pge\"\nposition = [0, 1]\n")
              .ends_with("got 'pge' (did you mean 'peg'?)"));
    CHECK(firstError(floor + "[[item]]\nkind = \"peg\"\nposition = [0, 1]\nradius = 0.3\n") == "no error");
    CHECK(firstError(floor + "[[item]]\nkind = \"peg\"\nposition = [0, 1]\nradius = 0\n")
              .starts_with("t.toml:8:10: radius must be"));
}
