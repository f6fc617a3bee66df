// The gate (issue 22): a board on a hinge with angle limits [0, opens]. Over a range of impacts (two
// balls at 2 to 10 m/s, from either side; gates opening 90 and 45 degrees counter-clockwise and 90
// clockwise) its turn from shut never leaves the limits by more than 3 degrees (the limit is soft: an
// 8 kg ball at 10 m/s jammed under a 45-degree gate pushes it 1.99 degrees past, the worst measured;
// 0.85 degrees the worst past shut); a one-way gate lets a ball rolling from the open side through
// and stops one from the other side; a latched gate stops both until released.
#include "level_run.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

using namespace rube;
using namespace rube::game;

namespace {

struct Ball {
    const char* kind;
    double radius;
};
constexpr Ball kHeavy{"heavy", 0.3}, kSteel{"steel", 0.2};
constexpr double kLength = 1.2, kHingeY = 1.3; // the board's bottom 0.1 m above the floor

// A hanging gate at x = 0 opening `opens` degrees and a ball rolling at `speed` from `side` (-1 left, +1 right).
LevelRun gateAndBall(double opens, bool latched, const Ball& ball, double speed, int side) {
    std::ostringstream text;
    text.precision(17);
    text << "name = \"gate-test\"\n[world]\ntime_step = 0.01\nbounds = { min = [-30, -30], max = [30, 30] }\n"
         << "[[segment]]\na = [-20, 0]\nb = [20, 0]\n"
         << "[[item]]\nkind = \"gate\"\nname = \"door\"\nposition = [0, " << kHingeY << "]\nopens = " << opens
         << "\nlatched = " << (latched ? "true" : "false") << "\n"
         << "[[item]]\nkind = \"" << ball.kind << "\"\nposition = [" << side * 2.0 << ", " << ball.radius
         << "]\nvelocity = [" << -side * speed << ", 0]\n";
    const SceneLoad load = parseScene(text.str(), "gate-test.toml");
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return LevelRun(*load.scene, {});
}

// The board's turn from shut (hanging straight down), degrees.
double turn(const LevelRun& run) {
    return (run.world().body(run.states()[0].body).angle + 0.5 * std::numbers::pi) * 180.0 / std::numbers::pi;
}

} // namespace

TEST_CASE("a gate's turn stays within its limits over a range of impacts, and it lets balls through one way only",
          "[parts][gate]") {
    for (const double opens : {90.0, 45.0, -90.0}) {
        for (const Ball& ball : {kHeavy, kSteel}) {
            for (const double speed : {2.0, 5.0, 10.0}) {
                for (const int side : {-1, 1}) {
                    INFO("opens " << opens << ", " << ball.kind << " at " << speed << " m/s from the "
                                  << (side < 0 ? "left" : "right"));
                    LevelRun run = gateAndBall(opens, false, ball, speed, side);
                    double least = 0.0, most = 0.0;
                    for (int i = 0; i < 300; ++i) {
                        run.step();
                        least = std::min(least, turn(run));
                        most = std::max(most, turn(run));
                    }
                    CHECK(least >= std::min(0.0, opens) - 3.0);
                    CHECK(most <= std::max(0.0, opens) + 3.0);
                    const double x = run.world().circle(run.states()[1].circle).position.x;
                    // Through from the left when, opened as far as it goes, its bottom end (at the hinge's
                    // height less L cos opens) clears the ball's diameter: 1.3 m at 90 degrees, 0.45 m at 45,
                    // which the steel ball (0.4 m) passes under and the heavy one (0.6 m) does not.
                    // A gate opening clockwise (opens < 0) is the mirror image: through from the right.
                    const double gap = kHingeY - kLength * std::cos(opens * std::numbers::pi / 180.0);
                    const int openSide = opens > 0.0 ? -1 : 1;
                    if (side == openSide && gap > 2.0 * ball.radius) CHECK(x * side < -0.5);
                    else CHECK(x * side > 0.0); // stopped: still on its own side
                }
            }
        }
    }
}

TEST_CASE("a latched gate stops a ball from its open side until released", "[parts][gate]") {
    for (const double speed : {2.0, 5.0}) {
        INFO(speed << " m/s");
        LevelRun run = gateAndBall(90.0, true, kSteel, speed, -1);
        double most = 0.0;
        for (int i = 0; i < 200; ++i) {
            run.step();
            most = std::max(most, std::abs(turn(run)));
        }
        CHECK(most < 2.0); // held shut (the latch's motor: within 2 degrees)
        CHECK(run.world().circle(run.states()[1].circle).position.x < 0.0);
        // Released, it swings open: the stopped ball, rolled again, goes through.
        LevelRun again = gateAndBall(90.0, true, kSteel, speed, -1);
        again.toggle(0);
        for (int i = 0; i < 300; ++i) again.step();
        CHECK(again.world().circle(again.states()[1].circle).position.x > 0.5);
    }
}
