// Scene files: [[joint]] tables read into joints the World builds (each kind, its defaults), and
// every mistake reported at file:line:col with the kind's own keys suggested.
#include "scene_file.hpp"
#include "scene_text.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace rube;
using namespace rube::game;
using test::errorOf;
using test::sceneOf;

namespace {

// Two wheels and a box (lines 1 to 16), to join: line 17 is the first of what a case adds.
constexpr const char* kParts = "name = \"machine\"\n"
                               "[[circle]]\n"
                               "name = \"left\"\n"
                               "position = [0, 0]\n"
                               "radius = 0.5\n"
                               "[[circle]]\n"
                               "name = \"right\"\n"
                               "position = [3, 0]\n"
                               "radius = 1.0\n"
                               "[[box]]\n"
                               "name = \"crate\"\n"
                               "position = [0, -3]\n"
                               "size = [0.4, 0.4]\n"
                               "mass = 2\n"
                               "[world]\n"
                               "gravity = [0, -9.81]\n";

std::string with(std::string_view joints) { return std::string(kParts) + std::string(joints); }

constexpr const char* kAxles = "[[joint]]\nkind = \"revolute\"\nname = \"one\"\nb = \"left\"\nmotor_speed = 2\n"
                               "max_torque = 10\n"
                               "[[joint]]\nkind = \"revolute\"\nname = \"two\"\nb = \"right\"\n";

} // namespace

TEST_CASE("scene joints: every kind is read and built, and a scene with joints runs on auto", "[scene][joints]") {
    const SceneDesc scene = sceneOf(
        with(std::string(kAxles) + "[[joint]]\nkind = \"belt\"\njoint_a = \"one\"\njoint_b = \"two\"\n"
                                   "[[joint]]\nkind = \"spring\"\nanchor_a = [0, -1]\nb = \"crate\"\nstiffness = "
                                   "50\ndamping = 1\nside = \"pull\"\n"
                                   "[[joint]]\nkind = \"pulley\"\na = \"crate\"\nb = \"left\"\nground_a = [0, 5]\n"
                                   "ground_b = [0, 6]\nlength = 20\n"));
    REQUIRE(scene.joints.size() == 5);
    CHECK(scene.world.method == Method::automatic);
    CHECK(scene.joints[2].def.ratio == -1.0 / 0.5); // -r_b / r_a from the circles' radii
    CHECK(scene.joints[3].def.restLength == 2.0);   // the anchors' distance at the start
    CHECK(scene.joints[3].def.springSide == SpringSide::pullOnly);
    CHECK(scene.joints[3].a.isWorld());
    World world = buildWorld(scene);
    CHECK(world.joints().size() == 5);
    for (int s = 0; s < 60; ++s) world.step();
    // The belt turned the right wheel the same way as the driven left one, at half its angle.
    const double left = world.circles()[0].angle, right = world.circles()[1].angle;
    CHECK(left > 1.0);
    CHECK(right == Approx(left * 0.5).epsilon(1e-9));
}

TEST_CASE("scene joints: mistakes are reported where they are written", "[scene][joints]") {
    CHECK(errorOf(with("[[joint]]\nb = \"left\"\n")) == "s.toml:17:1: missing required key 'kind' in [[joint]]");
    CHECK(errorOf(with("[[joint]]\nkind = \"hinge\"\nb = \"left\"\n"))
              .starts_with("s.toml:18:8: kind must be one of revolute, prismatic, weld, spring, pulley, gear, belt"));
    CHECK(errorOf(with("[[joint]]\nkind = \"revolute\"\nb = \"lef\"\n")) ==
          "s.toml:19:5: unknown body 'lef' (did you mean 'left'?)");
    CHECK(errorOf(with("[[joint]]\nkind = \"revolute\"\nb = \"left\"\nmotor_sped = 1\n")) ==
          "s.toml:20:1: unknown key 'motor_sped' in [[joint]] of kind 'revolute' (did you mean 'motor_speed'?)");
    CHECK(errorOf(
              with("[[joint]]\nkind = \"spring\"\nb = \"left\"\nanchor_a = [0, 1]\nstiffness = 1\nmax_torque = 1\n")) ==
          "s.toml:22:1: unknown key 'max_torque' in [[joint]] of kind 'spring' (it belongs in a [[joint]] of kind "
          "'revolute')");
    CHECK(errorOf(with("[[joint]]\nkind = \"revolute\"\nb = \"left\"\nmotor_speed = 1\n")) ==
          "s.toml:20:15: a motor needs max_torque as well");
    CHECK(errorOf(with("[[joint]]\nkind = \"revolute\"\nb = \"left\"\nlower_degrees = 10\nupper_degrees = -10\n")) ==
          "s.toml:20:17: lower_degrees must not exceed upper_degrees");
    CHECK(errorOf(with("[[joint]]\nkind = \"spring\"\nb = \"left\"\nstiffness = 1\n")) ==
          "s.toml:17:1: a spring to the world needs anchor_a, the fixed point");
    CHECK(errorOf(with("[[joint]]\nkind = \"pulley\"\na = \"left\"\nb = \"right\"\nground_a = [0, 5]\n"
                       "ground_b = [3, 5]\nlength = 2\n")) ==
          "s.toml:23:10: the pulley's rope needs 10 m to reach its ends, more than its length 2");
    CHECK(errorOf(with(std::string(kAxles) + "[[joint]]\nkind = \"gear\"\njoint_a = \"one\"\njoint_b = \"tow\"\n"
                                             "ratio = 2\n")) ==
          "s.toml:30:11: unknown joint 'tow' (did you mean 'two'?)");
    CHECK(errorOf(with(std::string(kAxles) + "[[joint]]\nkind = \"gear\"\njoint_a = \"one\"\njoint_b = \"two\"\n"
                                             "ratio = 0\n")) == "s.toml:31:9: a gear's ratio must not be 0");
    CHECK(errorOf(with("[[joint]]\nkind = \"weld\"\na = \"left\"\nb = \"left\"\n")) ==
          "s.toml:20:5: a joint must join two different bodies");
}

TEST_CASE("scene joints: a method that cannot move joints is refused at its name", "[scene][joints]") {
    const std::string text =
        "name = \"m\"\n[world]\nmethod = \"exact\"\n[[circle]]\nname = \"w\"\nposition = [0, 0]\nradius = 0.5\n"
        "[[joint]]\nkind = \"revolute\"\nb = \"w\"\n";
    CHECK(errorOf(text) == "s.toml:3:10: method 'exact' cannot move joints (joint 0: the exact method follows only "
                           "springs to fixed points, not a revolute joint): use method 'auto' or 'solver'");
    CHECK(errorOf("name = \"m\"\n[world]\nmethod = \"turn-based\"\n[[circle]]\nname = \"w\"\nposition = [0, "
                  "0]\nradius = 0.5\n[[joint]]\nkind = \"revolute\"\nb = \"w\"\n") ==
          "s.toml:3:10: method 'turn-based' cannot move turning boxes, capsules, pivots or joints: use 'auto' or "
          "'solver'");
}

TEST_CASE("scene joints: exact runs a scene whose springs to fixed points have a closed form, and names why not",
          "[scene][joints][spring]") {
    // A ball hanging on a spring of rest length 1 m under its fixed point: along the line, exact's.
    const std::string hanging = "name = \"m\"\n[world]\nmethod = \"exact\"\ngravity = [0, -9.81]\n[[circle]]\n"
                                "name = \"w\"\nposition = [0, -1.5]\nradius = 0.2\n[[joint]]\nkind = \"spring\"\n"
                                "anchor_a = [0, 0]\nb = \"w\"\nstiffness = 40\nrest_length = 1\n";
    const SceneDesc scene = sceneOf(hanging);
    CHECK(scene.world.method == Method::exact);
    World world = buildWorld(scene);
    for (int n = 0; n < 120; ++n) world.step();
    CHECK(world.circles()[0].position.x == 0.0);
    // Offset from the line, the same spring swings as a pendulum: no closed form, refused at the method.
    std::string swinging = hanging;
    swinging.replace(swinging.find("position = [0, -1.5]"), 20, "position = [1, -1.5]");
    CHECK(errorOf(swinging) ==
          "s.toml:3:10: method 'exact' cannot move joints (joint 0: a spring with a rest length is linear only along "
          "its line, and its circle moves (or gravity pulls) off it): use method 'auto' or 'solver'");
}

TEST_CASE("scene joints: collide_connected is read for every kind with two ends, false by default",
          "[scene][joints][collide]") {
    const SceneDesc scene = sceneOf(with("[[joint]]\nkind = \"weld\"\na = \"left\"\nb = \"right\"\n"
                                         "[[joint]]\nkind = \"spring\"\na = \"left\"\nb = \"crate\"\nstiffness = 5\n"
                                         "collide_connected = true\n"));
    REQUIRE(scene.joints.size() == 2);
    CHECK_FALSE(scene.joints[0].def.collideConnected);
    CHECK(scene.joints[1].def.collideConnected);
    World world = buildWorld(scene);
    CHECK(world.joints()[1].def.collideConnected);
    CHECK(errorOf(with("[[joint]]\nkind = \"weld\"\na = \"left\"\nb = \"right\"\ncollide_connected = 1\n")) ==
          "s.toml:21:21: collide_connected must be true or false, got integer");
    CHECK(errorOf(with("[[joint]]\nkind = \"weld\"\na = \"left\"\nb = \"right\"\ncollide_conected = true\n")) ==
          "s.toml:21:1: unknown key 'collide_conected' in [[joint]] of kind 'weld' (did you mean "
          "'collide_connected'?)");
}
