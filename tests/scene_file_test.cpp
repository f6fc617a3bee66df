// Scene files: every physics scene loads, and every kind of mistake is reported as
// file:line:col: message at the place it was written.
#include "scene_file.hpp"
#include "scene_text.hpp"

#include <catch2/catch.hpp>

#include <numbers>

#include <algorithm>
#include <filesystem>
#include <set>

using namespace rube;
using namespace rube::game;
using test::errorOf;
using test::errorsOf;
using test::sceneOf;

namespace {

// A valid scene to break one line at a time: line 1 name, line 3 [[circle]], line 4 position, line 5 radius.
constexpr const char* kBall = "name = \"ball\"\n"
                              "\n"
                              "[[circle]]\n"
                              "position = [0, 1]\n";

std::string ballWith(std::string_view line5) { return std::string(kBall) + std::string(line5) + "\n"; }

} // namespace

TEST_CASE("every physics scene loads, builds a world and steps", "[scene]") {
    const std::set<std::string> expected = {
        "ball-stack", "blocks", "bounce",     "bullet",     "float",   "islands",       "newtons-cradle",
        "pendulum",   "pile",   "pool-break", "projectile", "rolling", "seesaw-domino", "slope-rest",
        "gears",      "belt",   "pulley",     "springs",    "piston",  "weld",          "chain"};
    std::set<std::string> found;
    for (const auto& entry : std::filesystem::directory_iterator(RUBE_LEVELS_DIR)) {
        if (entry.path().extension() != ".toml") continue;
        const std::string stem = entry.path().stem().string();
        found.insert(stem);
        SECTION(stem) {
            const SceneLoad load = loadSceneFile(entry.path());
            INFO((load.errors.empty() ? std::string("no errors") : load.errors.front().format()));
            REQUIRE(load.ok());
            const SceneDesc& scene = *load.scene;
            CHECK(scene.name == stem); // a scene is found by the same name as its file
            CHECK_FALSE(scene.description.empty());
            CHECK(scene.dynamicCircleCount() > 0);
            World world = buildWorld(scene);
            CHECK(world.circles().size() == scene.circles.size());
            CHECK(world.segments().size() == scene.segments.size());
            world.step();
            CHECK(world.stats().steps == 1);
        }
    }
    CHECK(found == expected);
}

TEST_CASE("physics scenes say what the brief asks of them", "[scene]") {
    auto load = [](const char* name) {
        SceneLoad l = loadSceneFile(std::filesystem::path(RUBE_LEVELS_DIR) / name);
        REQUIRE(l.ok());
        return std::move(*l.scene);
    };
    const SceneDesc pile = load("pile.toml");
    CHECK(pile.circles.size() == 1000);
    CHECK(pile.world.method == Method::solver);
    CHECK(std::all_of(pile.circles.begin(), pile.circles.end(), [](const CircleDef& c) { return c.radius == 0.1; }));
    const SceneDesc pool = load("pool-break.toml");
    CHECK(pool.circles.size() == 16);
    CHECK(pool.world.gravity == Vec2{0, 0});
    const SceneDesc bounce = load("bounce.toml");
    REQUIRE(bounce.circles.size() == 1);
    CHECK(bounce.circles[0].position == Vec2{0, 10});
    CHECK(bounce.circles[0].radius == 0.5);
    CHECK(bounce.circles[0].material.bounciness == 1.0);
    CHECK(bounce.world.method == Method::exact);
    CHECK(load("ball-stack.toml").world.method == Method::solver);
    CHECK(load("newtons-cradle.toml").circles.size() == 5);
    const SceneDesc bullet = load("bullet.toml");
    CHECK(bullet.circles[0].radius == 0.05);
    CHECK(bullet.circles[0].velocity.length() == 500.0);
    CHECK(bullet.segments[0].radius == 0.0);
}

TEST_CASE("a minimal scene takes the physics defaults", "[scene]") {
    const SceneDesc scene = sceneOf(ballWith("radius = 0.25"));
    CHECK(scene.name == "ball");
    CHECK(scene.world.method == WorldDef{}.method);
    CHECK(scene.world.timeStep == WorldDef{}.timeStep);
    REQUIRE(scene.circles.size() == 1);
    const CircleDef& c = scene.circles[0];
    CHECK(c.position == Vec2{0, 1});
    CHECK(c.radius == 0.25);
    CHECK(c.mass == 1.0);
    CHECK(c.motion == Motion::dynamic);
    CHECK(c.material.bounciness == 1.0);
    CHECK(scene.defaultSteps() == kDefaultSteps);
}

TEST_CASE("the [world] table sets every WorldDef field", "[scene]") {
    const SceneDesc scene = sceneOf(
        "name = \"w\"\n[world]\ngravity = [1, -2]\ntime_step = 0.1\nmethod = \"turn-based\"\n"
        "bounds = { min = [-1, -2], max = [3, 4] }\nsubsteps = 3\nworkers = 3\nmax_events_per_step = 7\n"
        "resting_speed = 0.5\nduration = 1.0\n");
    CHECK(scene.world.gravity == Vec2{1, -2});
    CHECK(scene.world.timeStep == 0.1);
    CHECK(scene.world.method == Method::turnBased);
    CHECK(scene.world.bounds.min == Vec2{-1, -2});
    CHECK(scene.world.bounds.max == Vec2{3, 4});
    CHECK(scene.world.substeps == 3);
    CHECK(scene.world.workers == 3);
    CHECK(scene.world.maxEventsPerStep == 7);
    CHECK(scene.world.restingSpeed == 0.5);
    // 1.0 / 0.1 is 9.999999999999998 in doubles: the run must still be 10 steps, not 11 or 9.
    CHECK(scene.defaultSteps() == 10);
}

TEST_CASE("a circle_grid lays circles out row by row from the bottom, staggering odd rows", "[scene]") {
    const SceneDesc scene = sceneOf("name = \"g\"\n[[circle_grid]]\norigin = [1, 2]\ncolumns = 3\nrows = 2\n"
                                    "spacing = [0.5, 0.25]\nstagger = 0.1\nradius = 0.1\nmass = 2\n");
    REQUIRE(scene.circles.size() == 6);
    CHECK(scene.circles[0].position == Vec2{1, 2});
    CHECK(scene.circles[2].position == Vec2{2, 2});
    CHECK(scene.circles[3].position == Vec2{1.1, 2.25});
    CHECK(scene.circles[5].mass == 2.0);
}

TEST_CASE("syntax errors carry toml++'s place and words", "[errors]") {
    CHECK(errorOf("name = \n") == "s.toml:1:8: syntax error in key-value pair: expected value, saw '\\n'");
    CHECK(errorOf("name = \"x\"\n[world\n").starts_with("s.toml:2:7: syntax error"));
    CHECK(errorOf("name = \"x\"\nname = \"y\"\n").starts_with("s.toml:2:"));
}

TEST_CASE("a value of the wrong type names the type it got", "[errors]") {
    CHECK(errorOf(ballWith("radius = \"big\"")) == "s.toml:5:10: radius must be a number, got string");
    CHECK(errorOf(ballWith("radius = [1]")) == "s.toml:5:10: radius must be a number, got array");
    CHECK(errorOf(ballWith("radius = 1\nvelocity = 3")) ==
          "s.toml:6:12: velocity must be an array [x, y], got integer");
    CHECK(errorOf(ballWith("radius = 1\nvelocity = [1, true]")) ==
          "s.toml:6:16: velocity's y must be a number, got boolean");
    CHECK(errorOf(ballWith("radius = 1\nvelocity = [1, 2, 3]")) ==
          "s.toml:6:12: velocity must hold 2 numbers [x, y], got 3");
    CHECK(errorOf("name = 3\n") == "s.toml:1:8: name must be a string, got integer");
    CHECK(errorOf("name = \"x\"\n[world]\nsubsteps = 2.5\n") == "s.toml:3:12: substeps must be an integer, got float");
    CHECK(errorOf("name = \"x\"\ncircle = 3\n") ==
          "s.toml:2:10: circle must be an array of tables, written [[circle]], got integer");
    CHECK(errorOf("name = \"x\"\n[path]\nname = \"p\"\n") ==
          "s.toml:2:1: path must be an array of tables, written [[path]], got table");
}

TEST_CASE("a missing required key is reported at its table's header", "[errors]") {
    CHECK(errorOf(kBall) == "s.toml:3:1: missing required key 'radius' in [[circle]]");
    CHECK(errorOf("[[circle]]\nposition = [0, 0]\nradius = 1\n") ==
          "s.toml:1:1: missing required key 'name' at the top level");
    CHECK(errorOf("name = \"x\"\n\n[[segment]]\na = [0, 0]\n") ==
          "s.toml:3:1: missing required key 'b' in [[segment]]");
    CHECK(errorOf("name = \"x\"\n[world]\nbounds = { min = [0, 0] }\n") ==
          "s.toml:3:10: missing required key 'max' in world.bounds");
}

TEST_CASE("an unknown key is an error, with the closest known key", "[errors]") {
    const auto errors = errorsOf(ballWith("raduis = 0.5"));
    REQUIRE(errors.size() == 2); // the typo, and so radius is missing
    CHECK(errors[0] == "s.toml:3:1: missing required key 'radius' in [[circle]]");
    CHECK(errors[1] == "s.toml:5:1: unknown key 'raduis' in [[circle]] (did you mean 'radius'?)");
    CHECK(errorOf(ballWith("radius = 1\n  Mass = 2")) ==
          "s.toml:6:3: unknown key 'Mass' in [[circle]] (did you mean 'mass'?)");
    CHECK(errorOf(ballWith("radius = 1\ncolour = 2")) ==
          "s.toml:6:1: unknown key 'colour' in [[circle]] (known keys: position, velocity, angular_velocity, inertia, "
          "radius, mass, bounciness, friction, motion, path)");
    CHECK(errorOf("name = \"x\"\n[world]\ntimestep = 0.1\n") ==
          "s.toml:3:1: unknown key 'timestep' in [world] (did you mean 'time_step'?)");
    CHECK(errorOf("name = \"x\"\n[[circel]]\n") ==
          "s.toml:2:3: unknown key 'circel' at the top level (did you mean 'circle'?)");
    CHECK(errorOf("name = \"x\"\ngravity = [0, -1]\n") ==
          "s.toml:2:1: unknown key 'gravity' at the top level (it belongs in [world])");
}

TEST_CASE("values out of range say the range and the value", "[errors]") {
    CHECK(errorOf(ballWith("radius = 0")) == "s.toml:5:10: radius must be between 1e-04 and 10000, got 0");
    CHECK(errorOf(ballWith("radius = -0.5")) == "s.toml:5:10: radius must be between 1e-04 and 10000, got -0.5");
    CHECK(errorOf(ballWith("radius = nan")) == "s.toml:5:10: radius must be finite, got nan");
    CHECK(errorOf(ballWith("radius = inf")) == "s.toml:5:10: radius must be finite, got inf");
    CHECK(errorOf(ballWith("radius = 1\nmass = 0")) == "s.toml:6:8: mass must be between 1e-06 and 1e+06, got 0");
    CHECK(errorOf(ballWith("radius = 1\nbounciness = 1.01")) ==
          "s.toml:6:14: bounciness must be between 0 and 1, got 1.01");
    CHECK(errorOf(ballWith("radius = 1\nbounciness = -0.1")) ==
          "s.toml:6:14: bounciness must be between 0 and 1, got -0.1");
    CHECK(errorOf(ballWith("radius = 1\nfriction = -1")) == "s.toml:6:12: friction must be at least 0, got -1");
    CHECK(errorOf(ballWith("radius = 1\nvelocity = [-inf, 0]")) ==
          "s.toml:6:13: velocity's x must be finite, got -inf");
    CHECK(errorOf("name = \"x\"\n[world]\ntime_step = 0\n") == "s.toml:3:13: time_step must be greater than 0, got 0");
    CHECK(errorOf("name = \"x\"\n[world]\nsubsteps = 0\n") ==
          "s.toml:3:12: substeps must be between 1 and 1000, got 0");
    CHECK(errorOf("name = \"x\"\n[world]\nworkers = 0\n") == "s.toml:3:11: workers must be between 1 and 64, got 0");
    CHECK(errorOf("name = \"x\"\n[world]\nworkers = 65\n") == "s.toml:3:11: workers must be between 1 and 64, got 65");
    CHECK(errorOf("name = \"x\"\n[world]\nworkers = 1.5\n") == "s.toml:3:11: workers must be an integer, got float");
    CHECK(errorOf("name = \"x\"\n[world]\nmethod = \"exat\"\n") ==
          "s.toml:3:10: method must be one of discrete, turn-based, exact, solver, auto, got 'exat' (did you mean "
          "'exact'?)");
    CHECK(errorOf("name = \"x\"\n[world]\nbounds = { min = [0, 0], max = [1, 0] }\n") ==
          "s.toml:3:32: bounds max must be greater than min in both x and y, got min [0, 0] and max [1, 0]");
    CHECK(errorOf("name = \"\"\n") == "s.toml:1:8: name must not be empty");
}

TEST_CASE("a segment of zero length is an error at its b", "[errors]") {
    CHECK(errorOf("name = \"x\"\n[[segment]]\na = [1, 2]\nb = [1, 2]\n") ==
          "s.toml:4:5: b must differ from a: the segment has zero length");
    CHECK(errorOf("name = \"x\"\n[[segment]]\na = [0, 0]\nb = [1, 0]\nradius = -0.1\n") ==
          "s.toml:5:10: radius must be between 0 and 10000, got -0.1");
}

TEST_CASE("a circle_grid must not start with its circles overlapping or be absurdly large", "[errors]") {
    const std::string grid = "name = \"x\"\n[[circle_grid]]\norigin = [0, 0]\nradius = 0.1\n";
    CHECK(errorOf(grid + "columns = 2\nrows = 1\nspacing = 0.15\n") ==
          "s.toml:7:11: spacing must be at least the diameter 0.2 so the circles do not start overlapping, got 0.15");
    CHECK(errorOf(grid + "columns = 2\nrows = 2\nspacing = [0.2, -1]\n") ==
          "s.toml:7:11: spacing's x and y must be greater than 0, got [0.2, -1]");
    CHECK(errorOf(grid + "columns = 0\nrows = 2\nspacing = 1\n") ==
          "s.toml:5:11: columns must be between 1 and 10000, got 0");
    CHECK(errorOf(grid + "columns = 1000\nrows = 1000\nspacing = 1\n") ==
          "s.toml:6:8: circle_grid makes 1000000 circles; one grid may make at most 100000");
}

TEST_CASE("paths: bodies refer to them by name, and they must exist", "[paths]") {
    const std::string path = "name = \"x\"\n[[path]]\nname = \"lift\"\nkeys = [[0, 0, 0], [2, 0, 3]]\nloop = true\n";
    SECTION("a circle with a path is kinematic and points at it") {
        const SceneDesc scene = sceneOf(path + "[[circle]]\nposition = [0, 0]\nradius = 1\npath = \"lift\"\n"
                                               "[[segment]]\na = [0, 0]\nb = [1, 0]\npath = \"lift\"\n");
        REQUIRE(scene.paths.size() == 1);
        CHECK(scene.paths[0].name == "lift");
        CHECK(scene.paths[0].path.loop);
        CHECK(scene.paths[0].path.keys[1].offset == Vec2{0, 3});
        CHECK(scene.circles[0].motion == Motion::kinematic);
        CHECK(scene.circles[0].path == 0);
        CHECK(scene.segments[0].path == 0);
        CHECK(buildWorld(scene).paths().size() == 1);
    }
    SECTION("a fourth number in a key turns a segment about its pivot, in degrees") {
        const SceneDesc scene = sceneOf(
            "name = \"x\"\n[[path]]\nname = \"paddle\"\nkeys = [[0, 0, 0, -30], [1, 0, 0, 90]]\n"
            "[[segment]]\na = [0, 0]\nb = [1, 0]\npath = \"paddle\"\npivot = 0\n");
        CHECK(scene.paths[0].path.keys[0].angle == Approx(-std::numbers::pi / 6));
        CHECK(scene.paths[0].path.keys[1].angle == Approx(std::numbers::pi / 2));
        CHECK(scene.segments[0].pivotAlong == 0.0);
        CHECK(errorOf("name = \"x\"\n[[path]]\nname = \"p\"\nkeys = [[0, 0, 0, 0, 1], [1, 0, 0]]\n") ==
              "s.toml:4:9: a path key must be [t, x, y] or [t, x, y, angle], got 5 numbers");
        CHECK(errorOf("name = \"x\"\n[[segment]]\na = [0, 0]\nb = [1, 0]\npivot = 1.5\n") ==
              "s.toml:5:9: pivot must be between 0 and 1, got 1.5");
    }
    SECTION("an unknown path suggests the closest defined one") {
        CHECK(errorOf(path + "[[circle]]\nposition = [0, 0]\nradius = 1\npath = \"lfit\"\n") ==
              "s.toml:9:8: unknown path 'lfit' (did you mean 'lift'?)");
        CHECK(errorOf(path + "[[segment]]\na = [0, 0]\nb = [1, 0]\npath = \"elevator\"\n") ==
              "s.toml:9:8: unknown path 'elevator' (defined paths: lift)");
        CHECK(errorOf(ballWith("radius = 1\npath = \"lift\"")) ==
              "s.toml:6:8: unknown path 'lift' (no [[path]] is defined)");
    }
    SECTION("motion and path must agree") {
        CHECK(errorOf(ballWith("radius = 1\nmotion = \"kinematic\"")) ==
              "s.toml:6:10: a kinematic circle needs a path = \"name\" of a [[path]] to follow");
        CHECK(errorOf(path + "[[circle]]\nposition = [0, 0]\nradius = 1\npath = \"lift\"\nmotion = \"static\"\n") ==
              "s.toml:10:10: a circle with a path must be kinematic, got motion 'static'");
        CHECK(errorOf(ballWith("radius = 1\nmotion = \"fixed\"")) ==
              "s.toml:6:10: motion must be one of dynamic, kinematic, static, got 'fixed'");
    }
    SECTION("path definitions are checked") {
        CHECK(errorOf(path + "[[path]]\nname = \"lift\"\nkeys = [[0, 0, 0], [1, 1, 1]]\n") ==
              "s.toml:7:8: a path named 'lift' is already defined");
        CHECK(errorOf("name = \"x\"\n[[path]]\nname = \"p\"\nkeys = [[0, 0, 0], [2, 0, 3], [1, 0, 0]]\n") ==
              "s.toml:4:32: path key times must increase, got 1 after 2");
        CHECK(errorOf("name = \"x\"\n[[path]]\nname = \"p\"\nkeys = [[0, 0, 0]]\n") ==
              "s.toml:4:8: keys must hold at least 2 keys [t, x, y], got 1");
        CHECK(errorOf("name = \"x\"\n[[path]]\nname = \"p\"\nkeys = [[0, 0, 0], [1, 0]]\n") ==
              "s.toml:4:20: a path key must be [t, x, y] or [t, x, y, angle], got 2 numbers");
        CHECK(errorOf("name = \"x\"\n[[path]]\nname = \"p\"\nkeys = [[-1, 0, 0], [1, 0, 0]]\n") ==
              "s.toml:4:10: path key times must be at least 0, got -1");
    }
}

TEST_CASE("every error is listed, sorted from the top of the file", "[errors]") {
    const auto errors = errorsOf(
        "name = \"x\"\n[world]\ntime_step = 0\n[[circle]]\nposition = [0, 0]\nradius = -1\nmas = 2\n");
    REQUIRE(errors.size() == 3);
    CHECK(errors[0].starts_with("s.toml:3:13: time_step"));
    CHECK(errors[1].starts_with("s.toml:6:10: radius"));
    CHECK(errors[2] == "s.toml:7:1: unknown key 'mas' in [[circle]] (did you mean 'mass'?)");
}

TEST_CASE("a file that cannot be read is one error without a place", "[errors]") {
    const SceneLoad load = loadSceneFile("no/such/scene.toml");
    REQUIRE(load.errors.size() == 1);
    CHECK(load.errors[0].format() == "no/such/scene.toml: cannot open file");
}

TEST_CASE("typo suggestions are close matches only", "[errors]") {
    constexpr std::string_view keys[] = {"radius", "mass", "position", "time_step"};
    CHECK(closestMatch("raduis", keys) == "radius");
    CHECK(closestMatch("mas", keys) == "mass");
    CHECK(closestMatch("RADIUS", keys) == "radius");
    CHECK(closestMatch("timestep", keys) == "time_step");
    CHECK_FALSE(closestMatch("colour", keys));
    CHECK_FALSE(closestMatch("x", keys));
}

TEST_CASE("[[rope]] joins a circle named or numbered to an anchor or another circle", "[scene][rope]") {
    const std::string balls =
        "name = \"x\"\n"
        "[[circle]]\nname = \"bob\"\nposition = [0, 1]\nradius = 0.2\n"                        // lines 2-5
        "[[circle]]\nposition = [0, 0]\nradius = 0.2\n"                                        // lines 6-8
        "[[circle]]\nname = \"post\"\nposition = [3, 3]\nradius = 0.2\nmotion = \"static\"\n"; // 9-13
    SECTION("an anchor, the length taken from where the ends start") {
        const SceneDesc scene = sceneOf(balls + "[[rope]]\ncircle = \"bob\"\nanchor = [0, 3]\n");
        REQUIRE(scene.ropes.size() == 1);
        CHECK(scene.ropes[0].circle == 0);
        CHECK(scene.ropes[0].other == -1);
        CHECK(scene.ropes[0].length == 2.0);
        World world = buildWorld(scene);
        CHECK(world.ropes().size() == 1);
    }
    SECTION("another circle by index, and a name to cut it by") {
        const SceneDesc scene = sceneOf(balls + "[[rope]]\nname = \"r\"\ncircle = 1\nother = \"bob\"\nlength = 1.5\n");
        REQUIRE(scene.ropes.size() == 1);
        CHECK(scene.ropes[0].other == 0);
        CHECK(scene.ropes[0].length == 1.5);
        CHECK(scene.findRope("r") == 0);
        CHECK(scene.findRope("s") == -1);
    }
    SECTION("mistakes, each at its place") {
        CHECK(errorOf(balls + "[[rope]]\ncircle = \"bbo\"\nanchor = [0, 3]\n") ==
              "s.toml:15:10: unknown circle 'bbo' (did you mean 'bob'?)");
        CHECK(errorOf(balls + "[[rope]]\ncircle = 7\nanchor = [0, 3]\n") ==
              "s.toml:15:10: circle must be a circle's index from 0 to 3 (exclusive) or its name, got 7");
        CHECK(errorOf(balls + "[[rope]]\ncircle = \"bob\"\nanchor = [0, 3]\nother = 1\n") ==
              "s.toml:16:10: a rope ends at an anchor or at another circle, not both: remove anchor or other");
        CHECK(errorOf(balls + "[[rope]]\ncircle = \"bob\"\n") ==
              "s.toml:14:1: missing required key 'anchor' in [[rope]]");
        CHECK(errorOf(balls + "[[rope]]\ncircle = \"post\"\nanchor = [0, 3]\n") ==
              "s.toml:15:10: a rope's circle must be dynamic (the rope pulls it); use other for a fixed end");
        CHECK(errorOf(balls + "[[rope]]\ncircle = \"bob\"\nanchor = [0, 3]\nlength = 1\n") ==
              "s.toml:17:10: the rope's ends start 2 m apart, more than its length 1");
        CHECK(errorOf(balls + "[[rope]]\ncircle = \"bob\"\nanchor = [0, 3]\nlength = 0\n") ==
              "s.toml:17:10: length must be greater than 0, got 0");
        CHECK(errorOf(balls + "[[rope]]\ncircle = \"bob\"\nother = \"bob\"\n") ==
              "s.toml:16:9: a rope cannot join a circle to itself");
        CHECK(errorOf(balls + "[[rope]]\ncircle = \"bob\"\nanchr = [0, 3]\nanchor = [0, 3]\n") ==
              "s.toml:16:1: unknown key 'anchr' in [[rope]] (did you mean 'anchor'?)");
    }
}

TEST_CASE("scene files: [[box]] is lecture 3's block with fixed_rotation = true, else it turns", "[scene][blocks]") {
    const SceneLoad load = parseScene(
        "name = \"b\"\n[[box]]\nposition = [1, 2]\nsize = [2, 0.5]\nmass = 3\nbounciness = 0.5\nfixed_rotation = true\n"
        "[[box]]\nposition = [0, 0]\nsize = 1\nmotion = \"static\"\n",
        "s.toml");
    REQUIRE(load.ok());
    const auto& bodies = load.scene->bodies;
    REQUIRE(bodies.size() == 2);
    CHECK(bodies[0].shape == BodyShape::box);
    CHECK(bodies[0].fixedRotation);
    CHECK(bodies[0].halfExtents == Vec2{1.0, 0.25}); // size is the full width and height
    CHECK(bodies[0].mass == 3.0);
    CHECK(bodies[0].material.bounciness == 0.5);
    CHECK(bodies[1].halfExtents == Vec2{0.5, 0.5});
    CHECK(bodies[1].motion == Motion::fixed);
    CHECK_FALSE(bodies[1].fixedRotation);
    CHECK(errorOf("name = \"b\"\n[[box]]\nposition = [0, 1]\n") ==
          "s.toml:2:1: give a box its size = [width, height] or its half_extents, one of them");
}
