// The game's picture of a scene, without a GL context: the [view] key, the camera's framing,
// the draw list a world becomes (colours by motion, spokes, thin lines, HUD), the debug
// overlays' bounded memory, and the frame file names. Pixels are the screenshot tests' job.
#include "frame_recorder.hpp"
#include "scene_file.hpp"
#include "scene_framing.hpp"
#include "scene_view.hpp"

#include "rube/render/palette.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

using namespace rube;
using namespace rube::game;

namespace {

SceneDesc sceneOf(std::string_view text) {
    SceneLoad load = parseScene(text, "s.toml");
    INFO((load.errors.empty() ? std::string("no errors") : load.errors.front().format()));
    REQUIRE(load.ok());
    return std::move(*load.scene);
}

// A floor, a dynamic ball above it and a kinematic ball on a path.
constexpr const char* kScene = "name = \"view-test\"\n"
                               "[[path]]\nname = \"lift\"\nkeys = [[0, 0, 0], [1, 0, 1]]\n"
                               "[[segment]]\na = [-4, 0]\nb = [4, 0]\n"
                               "[[circle]]\nposition = [0, 3]\nradius = 0.5\n"
                               "[[circle]]\nposition = [2, 1]\nradius = 0.25\npath = \"lift\"\n";

template <class Kind>
std::vector<Kind> primitivesOf(const render::DrawList& list) {
    std::vector<Kind> found;
    for (const render::Primitive& p : list.primitives()) {
        if (const auto* kind = std::get_if<Kind>(&p)) found.push_back(*kind);
    }
    return found;
}

} // namespace

TEST_CASE("[view] sets the framed region and is checked like bounds", "[view]") {
    const SceneDesc scene = sceneOf("name = \"x\"\n[view]\nmin = [-1, -2]\nmax = [3, 4]\n");
    REQUIRE(scene.view);
    CHECK(scene.view->min == Vec2{-1, -2});
    CHECK(scene.view->max == Vec2{3, 4});
    CHECK_FALSE(sceneOf("name = \"x\"\n").view);

    const auto errors = parseScene("name = \"x\"\n[view]\nmin = [0, 0]\nmax = [1, 0]\n", "s.toml").errors;
    REQUIRE(errors.size() == 1);
    CHECK(errors.front().format() ==
          "s.toml:4:7: view max must be greater than min in both x and y, got min [0, 0] and max [1, 0]");
    const auto unknown = parseScene("name = \"x\"\n[view]\nmin = [0, 0]\nmax = [1, 1]\nzoom = 2\n", "s.toml").errors;
    REQUIRE(unknown.size() == 1);
    CHECK(unknown.front().format().starts_with("s.toml:5:1: unknown key 'zoom' in [view]"));
}

TEST_CASE("framing prefers [view], then set bounds, then the bodies with a margin", "[view]") {
    SceneDesc scene = sceneOf(kScene);
    World world = buildWorld(scene);

    // No view, default bounds: the bodies' box (x -4..4, y 0..3.5) grown by 8 % of its larger side.
    Framing bodies = frameScene(scene, world);
    CHECK(bodies.source == FrameSource::bodies);
    CHECK(bodies.region.min.x == Approx(-4.64f));
    CHECK(bodies.region.max.x == Approx(4.64f));
    CHECK(bodies.region.min.y == Approx(-0.64f));
    CHECK(bodies.region.max.y == Approx(4.14f));

    scene.world.bounds = {{-10, -1}, {10, 9}};
    Framing bounds = frameScene(scene, world);
    CHECK(bounds.source == FrameSource::bounds);
    CHECK(bounds.region.min.x == -10.0f);
    CHECK(bounds.region.max.y == 9.0f);

    scene.view = Aabb{{-1, -1}, {1, 1}};
    CHECK(frameScene(scene, world).source == FrameSource::view);

    // The frame's aspect is kept: a wide region fills the width, a tall one the height.
    const render::Camera wide = sceneCamera({{{-8, 0}, {8, 1}}, FrameSource::view}, {1280, 720});
    CHECK(wide.viewHeight == Approx(9.0f));
    const render::Camera tall = sceneCamera({{{0, 0}, {1, 20}}, FrameSource::view}, {1280, 720});
    CHECK(tall.viewHeight == Approx(20.0f));
}

TEST_CASE("a lone body is framed with room around it", "[view]") {
    const SceneDesc scene = sceneOf("name = \"x\"\n[[circle]]\nposition = [5, 5]\nradius = 0.1\n");
    World world = buildWorld(scene);
    const Framing framing = frameScene(scene, world);
    CHECK(framing.source == FrameSource::bodies);
    CHECK(framing.region.max.x - framing.region.min.x >= 1.0f);
    CHECK(framing.region.max.y - framing.region.min.y >= 1.0f);
    CHECK(0.5f * (framing.region.min.x + framing.region.max.x) == Approx(5.0f));
}

TEST_CASE("a world becomes walls, balls with spokes in the palette's colours, and a HUD line", "[view]") {
    const render::Palette& palette = render::Palette::greybox();
    const SceneDesc scene = sceneOf(kScene);
    World world = buildWorld(scene);
    const render::FrameSize size{640, 360};
    SceneView view(scene.name, world, sceneCamera(frameScene(scene, world), size), size);
    render::DrawList list;
    view.draw(world, list);

    const auto walls = primitivesOf<render::primitive::Capsule>(list);
    REQUIRE(walls.size() == 1);
    CHECK(walls[0].style.fill == palette["ground"]);
    CHECK(walls[0].style.outlineWidth >= 3.0f); // a thin line is drawn as a visible stroke

    const auto balls = primitivesOf<render::primitive::Circle>(list);
    REQUIRE(balls.size() == 2);
    CHECK(balls[0].style.fill == palette["ball"]);
    CHECK(balls[0].spoke);
    CHECK(balls[0].angle == 0.0f);
    CHECK(balls[1].style.fill == palette["kinematic"]); // kinematic, unlike static or dynamic bodies
    CHECK(balls[0].centre.y == 3.0f);

    const auto texts = primitivesOf<render::primitive::Text>(list);
    REQUIRE(texts.size() == 1);
    CHECK(list.textOf(texts[0]) == "view-test   step 0   t = 0.000 s   exact");
    // The HUD counts steps, whatever frame of a run it is drawn into: after 3 steps of 1/60 s, step 3.
    for (int i = 0; i < 3; ++i) world.step();
    view.draw(world, list);
    CHECK(list.textOf(primitivesOf<render::primitive::Text>(list)[0]) == "view-test   step 3   t = 0.050 s   exact");
    CHECK(primitivesOf<render::primitive::Polyline>(list).empty()); // overlays are off by default
    CHECK(primitivesOf<render::primitive::Arrow>(list).empty());
}

TEST_CASE("trails follow each dynamic ball through its impacts and keep bounded memory", "[view]") {
    const SceneDesc scene = sceneOf("name = \"drop\"\n[world]\ngravity = [0, -10]\n"
                                    "[[segment]]\na = [-4, 0]\nb = [4, 0]\n"
                                    "[[circle]]\nposition = [0, 1]\nradius = 0.5\nvelocity = [0, -3]\n");
    World world = buildWorld(scene);
    Trails trails(world, 0.5, 1000);
    REQUIRE(trails.pointsOf(0).size() == 1);
    bool bounced = false;
    for (int i = 0; i < 120; ++i) {
        world.step();
        bounced = bounced || !world.lastImpacts().empty();
        trails.record(world);
    }
    REQUIRE(bounced);
    // 0.5 s at 60 steps per second, plus the corner at each bounce still in the window.
    const auto points = trails.pointsOf(0);
    CHECK(points.size() >= 30);
    CHECK(points.size() <= 40);
    CHECK(points.back().y == static_cast<float>(world.circles()[0].position.y));

    Trails capped(world, 100.0, 5);
    for (int i = 0; i < 20; ++i) {
        world.step();
        capped.record(world);
    }
    CHECK(capped.pointsOf(0).size() == 5);
}

TEST_CASE("impact markers show each pair's newest impact, for a while", "[view]") {
    const SceneDesc scene = sceneOf(
        "name = \"slide\"\n[world]\ngravity = [0, -10]\n"
        "[[segment]]\na = [-40, 0]\nb = [40, 0]\n"
        "[[circle]]\nposition = [0, 0.5]\nradius = 0.5\nvelocity = [2, 0]\nbounciness = 0\n");
    World world = buildWorld(scene);
    RecentImpacts impacts(0.25, 100);
    int steps = 0;
    for (; steps < 30; ++steps) {
        world.step();
        impacts.record(world);
    }
    // Resting on the floor reports an impact every step, but only the newest is shown.
    REQUIRE(world.stats().impacts > 1);
    CHECK(impacts.shown() == 1);
    render::DrawList list;
    impacts.draw(list, world.time(), 30.0f, {200, 0, 0, 255}, {0, 0, 200, 255});
    const auto arrows = primitivesOf<render::primitive::Arrow>(list);
    REQUIRE(arrows.size() == 1);
    CHECK(arrows[0].tip.y > arrows[0].tail.y); // the normal points from the floor up into the ball
}

TEST_CASE("frames are named as ffmpeg's frame_%05d.png reads them, and only those are ours", "[frames]") {
    CHECK(frameFileName(0) == "frame_00000.png");
    CHECK(frameFileName(42) == "frame_00042.png");
    CHECK(frameFileName(123456) == "frame_123456.png");
    CHECK(isFrameFileName("frame_00000.png"));
    CHECK(isFrameFileName("frame_123456.png"));
    CHECK_FALSE(isFrameFileName("frame_0001.png"));
    CHECK_FALSE(isFrameFileName("frame_0000a.png"));
    CHECK_FALSE(isFrameFileName("frame_00000.png.tmp"));
    CHECK_FALSE(isFrameFileName("notes.txt"));

    const auto folder = std::filesystem::temp_directory_path() / ("rube-frames-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    for (const char* name : {"frame_00000.png", "frame_00001.png", "keep.png", "frame_1.png"})
        std::ofstream(folder / name) << "x";
    CHECK(removeFrames(folder) == 2);
    CHECK(std::filesystem::exists(folder / "keep.png"));
    CHECK(std::filesystem::exists(folder / "frame_1.png"));
    CHECK_FALSE(std::filesystem::exists(folder / "frame_00000.png"));
    std::filesystem::remove_all(folder);
}
