// The trampoline (game/src/items/trampoline.cpp): its C is the bed's bounciness C_bed, and a ball of
// bounciness C_ball leaves it with C_bed x C_ball of its normal impact speed (lecture 3's product),
// keeping its speed along the bed. Tested over balls, impact speeds, beds and tilts.
#include "level_run.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

using namespace rube;
using namespace rube::game;

namespace {

// `x` written so that it reads back exactly.
std::string num(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
}

struct Ball {
    const char* kind;
    double radius, bounciness;
};

// A trampoline at the origin tilted by `degrees`, and above the bed's middle a ball of `kind` whose
// centre starts `drop` m above its point of contact (straight down, so it meets the bed's face).
std::string dropOnBed(const Ball& ball, double drop, double bed, double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    const double reach = 0.04 + ball.radius; // the bed's half thickness and the ball's radius
    // Falling straight down onto the bed's middle, the ball first touches it when its centre is `reach`
    // from the bed along the normal: reach / cos(a) above the origin.
    const double contactY = reach / std::cos(a);
    return "name = \"bed\"\n[world]\ntime_step = 0.01\n[[item]]\nkind = \"trampoline\"\nposition = [0, 0]\nangle = " +
           num(degrees) + "\nbounciness = " + num(bed) + "\n[[item]]\nkind = \"" + ball.kind + "\"\nposition = [0, " +
           num(contactY + drop) + "]\n";
}

} // namespace

TEST_CASE("trampoline: a ball leaves the bed with C_bed x C_ball of its normal impact speed", "[parts][trampoline]") {
    for (const Ball ball : {Ball{"tennis-ball", 0.0335, 0.745}, Ball{"basketball", 0.1218, 0.766},
                            Ball{"bouncy", 0.25, 0.95}, Ball{"bowling-ball", 0.1086, 0.2}}) {
        for (const double bed : {1.0, 0.9, 0.5}) {
            for (const double degrees : {0.0, 20.0, -35.0}) {
                for (const double drop : {0.2, 1.0, 3.0}) {
                    CAPTURE(ball.kind, bed, degrees, drop);
                    const SceneLoad load = parseScene(dropOnBed(ball, drop, bed, degrees), "bed.toml");
                    REQUIRE(load.ok());
                    LevelRun run(*load.scene, {});
                    const CircleId id = run.states()[1].circle;
                    const Vec2 g = run.world().def().gravity;
                    const Vec2 normal = Vec2::fromAngle(degrees * std::numbers::pi / 180.0).perpendicular();
                    const double impact = std::sqrt(2.0 * -g.y * drop); // speed at contact, straight down
                    const Vec2 before{0.0, -impact};
                    const double e = bed * ball.bounciness;
                    // v' = v - (1 + e) (v.n) n: the normal part reversed and scaled by e, the rest kept.
                    const Vec2 expected = before - normal * ((1.0 + e) * before.dot(normal));
                    bool bounced = false;
                    for (int i = 0; i < 1000 && !bounced; ++i) {
                        run.step();
                        if (run.world().lastImpacts().empty()) continue;
                        const Impact& hit = run.world().lastImpacts().front();
                        bounced = true;
                        CHECK(hit.approachSpeed == Approx(impact * std::abs(normal.y)).epsilon(1e-9));
                        // After the impact the ball flies freely for the rest of the step.
                        const double after = run.world().time() - hit.time;
                        const Circle& c = run.world().circle(id);
                        const Vec2 leaving = c.velocity - g * after;
                        CHECK(leaving.x == Approx(expected.x).margin(1e-9));
                        CHECK(leaving.y == Approx(expected.y).margin(1e-9));
                        CHECK(leaving.dot(normal) == Approx(-e * before.dot(normal)).margin(1e-9));
                    }
                    REQUIRE(bounced);
                }
            }
        }
    }
}
