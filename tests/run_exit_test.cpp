// Issue 27: a run whose physics went non-finite exits 1 with one line, scenes and levels alike; both
// take the line from unstableStateMessage (run_command.cpp, play_command.cpp).
#include "run_command.hpp"

#include "rube/physics/world.hpp"

#include <catch2/catch.hpp>

#include <limits>

using namespace rube;

TEST_CASE("a run with a body gone non-finite has a one-line reason, a finite run has none", "[robustness][exit]") {
    WorldDef def;
    World world(def);
    CircleDef ball;
    ball.position = {0.0, 1.0};
    world.addCircle(ball);
    ball.position = {3.0, 1.0};
    const CircleId bad = world.addCircle(ball);
    for (int i = 0; i < 10; ++i) world.step();
    CHECK(game::unstableStateMessage(world).empty());
    world.setVelocity(bad, {world.circle(bad).velocity.x, std::numeric_limits<double>::quiet_NaN()});
    world.step();
    const std::string why = game::unstableStateMessage(world);
    CHECK(
        why ==
        "a body's state became NaN or infinite: 1 body frozen, the first circle 1; the run's results are not physical");
    CHECK(why.find('\n') == std::string::npos);
}
