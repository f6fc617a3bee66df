// Level frames that explain themselves (issue 23), checked on the draw list LevelView makes, without
// GL: the HUD counts steps and keeps the goal's text inside the frame at any width, an explosion
// shows its whole reach on the step it happens, --labels and --zones draw what they say, and the
// heavy ball is the dark ball its part's description promises.
#include "level_view.hpp"
#include "scene_file.hpp"
#include "scene_framing.hpp"

#include "rube/render/palette.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

using namespace rube;
using namespace rube::game;

namespace {

SceneDesc parseLevel(const std::string& text) {
    const SceneLoad load = parseScene(text, "test.toml");
    INFO((load.errors.empty() ? std::string() : load.errors.front().format()));
    REQUIRE(load.ok());
    return *load.scene;
}

template <class Kind>
std::vector<Kind> primitivesOf(const render::DrawList& list) {
    std::vector<Kind> found;
    for (const render::Primitive& p : list.primitives())
        if (const auto* kind = std::get_if<Kind>(&p)) found.push_back(*kind);
    return found;
}

std::vector<std::string> textsOf(const render::DrawList& list) {
    std::vector<std::string> texts;
    for (const auto& t : primitivesOf<render::primitive::Text>(list)) texts.emplace_back(list.textOf(t));
    return texts;
}

LevelView viewOf(const LevelRun& run, render::FrameSize size, LevelViewOptions options = {}) {
    return LevelView(run.scene().name, sceneCamera(frameScene(run.scene(), run.world()), size), size, options);
}

// A level whose goal text is `goal`, with a named ball over a target, a zone and a bomb.
std::string levelText(const std::string& goal) {
    return "name = \"view\"\n[world]\ntime_step = 0.01\n[view]\nmin = [-8, -1]\nmax = [8, 8]\n"
           "[[segment]]\na = [-8, 0]\nb = [8, 0]\n"
           "[[item]]\nkind = \"heavy\"\nname = \"lead\"\nposition = [0, 3]\n"
           "[[item]]\nkind = \"steel\"\nname = \"iron\"\nposition = [3, 3]\n"
           "[[item]]\nkind = \"target\"\nname = \"flag\"\nposition = [0, 0.35]\n"
           "[[item]]\nkind = \"bomb\"\nname = \"tnt\"\nposition = [-5, 0.3]\nblast_radius = 2.5\n"
           "[inventory]\nramp = 1\n[[zone]]\nmin = [-7, 1]\nmax = [-2, 5]\n"
           "[goal]\ntext = \"" +
           goal + "\"\ncondition = \"target-hit\"\ntarget = \"flag\"\n";
}

double luma(render::Color c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

} // namespace

TEST_CASE("the HUD counts steps, and the goal's text wraps or shortens inside the frame at any width",
          "[level][view]") {
    const std::string longGoal = "knock the flag over with the heavy ball after it has rolled down the ramp, "
                                 "bounced off the wall, crossed the gap and passed under the low bridge";
    const SceneDesc level = parseLevel(levelText(longGoal));
    LevelRun run(level, {});
    for (int i = 0; i < 7; ++i) run.step();
    for (const int width : {120, 160, 320, 640, 1280, 4000}) {
        CAPTURE(width);
        const render::FrameSize size{width, width * 9 / 16};
        const LevelView view = viewOf(run, size);
        render::DrawList list;
        view.draw(run, run.steps(), list);
        const std::vector<std::string> texts = textsOf(list);
        REQUIRE(texts.size() >= 2);
        // The top line keeps the step however narrow the frame; the time and name when they fit.
        CHECK(texts[0].find("step 7") != std::string::npos);
        if (width >= 640) CHECK(texts[0] == "view   step 7   t = 0.070 s");
        // Every HUD line lies inside the frame, after the left margin.
        for (const auto& t : primitivesOf<render::primitive::Text>(list)) {
            CAPTURE(list.textOf(t));
            CHECK(t.x + render::textWidth(list.textOf(t), t.scale) <= width - t.x + 1);
        }
        // The goal's lines are its words in order: all of them, or a cut ending in "...".
        std::string shown;
        for (std::size_t i = 1; i < texts.size(); ++i) shown += (i > 1 ? " " : "") + texts[i];
        const std::string whole = "goal: " + longGoal;
        CHECK(texts.size() <= 3); // the step line and at most two goal lines
        if (shown.ends_with("...")) CHECK(whole.starts_with(shown.substr(0, shown.size() - 3)));
        else CHECK(shown == whole);
    }
    // A short goal is one line, unchanged.
    const SceneDesc shortLevel = parseLevel(levelText("hit the flag"));
    LevelRun shortRun(shortLevel, {});
    render::DrawList list;
    viewOf(shortRun, {640, 360}).draw(shortRun, 0, list);
    CHECK(textsOf(list) == std::vector<std::string>{"view   step 0   t = 0.000 s", "goal: hit the flag"});
}

TEST_CASE("wrapText breaks at spaces within the width and cuts with ... past the lines allowed", "[level][view]") {
    for (const int width : {40, 100, 300}) {
        for (const int lines : {1, 2, 3}) {
            CAPTURE(width, lines);
            const std::string text = "one two three four five six seven eight nine ten eleven twelve";
            const std::vector<std::string> wrapped = wrapText(text, width, 2, lines);
            CHECK(static_cast<int>(wrapped.size()) <= lines);
            for (const std::string& line : wrapped) CHECK(render::textWidth(line, 2) <= width);
        }
    }
    CHECK(wrapText("fits", 200, 2, 1) == std::vector<std::string>{"fits"});
    CHECK(wrapText("a b", 10000, 2, 2) == std::vector<std::string>{"a b"});
}

TEST_CASE("an explosion shows its whole reach on the step it happens", "[level][view][explosion]") {
    const SceneDesc level = parseLevel(levelText("hit the flag"));
    LevelRun run(level, {});
    const LevelView view = viewOf(run, {640, 360});
    const render::Color explosion = render::Palette::greybox()["explosion"];
    const auto blastCircles = [&](const render::DrawList& list) {
        int found = 0;
        for (const auto& c : primitivesOf<render::primitive::Circle>(list))
            if (c.radius == Approx(2.5f) && c.centre.x == Approx(-5.0f) && c.style.outline.r == explosion.r &&
                c.style.outline.a > 0)
                ++found;
        return found;
    };
    render::DrawList list;
    view.draw(run, run.steps(), list);
    CHECK(blastCircles(list) == 0);
    run.detonate(run.find("tnt")); // as a script's action does, before the frame of this step
    view.draw(run, run.steps(), list);
    CHECK(blastCircles(list) == 1);
    // A ring runs out from well inside the reach, not from a dot.
    bool ringSeen = false;
    for (const auto& r : primitivesOf<render::primitive::Ring>(list))
        if (r.radius >= 0.25f * 2.5f && r.radius <= 2.5f) ringSeen = true;
    CHECK(ringSeen);
    // It fades out: gone after half a second.
    for (int i = 0; i < 60; ++i) run.step();
    view.draw(run, run.steps(), list);
    CHECK(blastCircles(list) == 0);
}

TEST_CASE("labels write each named item's name, zones draw the placement zones (rube run's labels and zones options)",
          "[level][view]") {
    const SceneDesc level = parseLevel(levelText("hit the flag"));
    LevelRun run(level, {});
    const render::FrameSize size{640, 360};
    render::DrawList plain, labelled, zoned;
    viewOf(run, size).draw(run, 0, plain);
    viewOf(run, size, {true, false}).draw(run, 0, labelled);
    viewOf(run, size, {false, true}).draw(run, 0, zoned);
    const std::vector<std::string> texts = textsOf(labelled);
    for (const char* name : {"lead", "iron", "flag", "tnt"}) {
        CAPTURE(name);
        CHECK(std::count(texts.begin(), texts.end(), name) == 1);
        const std::vector<std::string> plainTexts = textsOf(plain);
        CHECK(std::count(plainTexts.begin(), plainTexts.end(), std::string(name)) == 0);
    }
    // A label sits beside its item: lead's is within 60 pixels of where lead is drawn.
    const render::Camera camera = sceneCamera(frameScene(level, run.world()), size);
    const render::Point lead = camera.toPixels({0.0f, 3.0f}, size);
    for (const auto& t : primitivesOf<render::primitive::Text>(labelled)) {
        if (labelled.textOf(t) != "lead") continue;
        CHECK(std::abs(static_cast<float>(t.x) - lead.x) < 60.0f);
        CHECK(std::abs(static_cast<float>(t.y) - (static_cast<float>(size.height) - lead.y)) < 60.0f);
    }
    // The zone [-7, 1] to [-2, 5] is a box centred at [-4.5, 3], half [2.5, 2], only with --zones.
    const auto zoneBoxes = [](const render::DrawList& list) {
        int n = 0;
        for (const auto& b : primitivesOf<render::primitive::Box>(list))
            if (b.centre.x == Approx(-4.5f) && b.centre.y == Approx(3.0f) && b.halfExtents.x == Approx(2.5f) &&
                b.halfExtents.y == Approx(2.0f))
                ++n;
        return n;
    };
    CHECK(zoneBoxes(plain) == 0);
    CHECK(zoneBoxes(zoned) == 1);
}

TEST_CASE("the heavy ball is drawn dark, as its description says: darker than steel and the ground", "[level][view]") {
    const SceneDesc level = parseLevel(levelText("hit the flag"));
    LevelRun run(level, {});
    render::DrawList list;
    viewOf(run, {640, 360}).draw(run, 0, list);
    std::optional<render::Color> heavy, steel;
    for (const auto& c : primitivesOf<render::primitive::Circle>(list)) {
        if (c.centre.x == Approx(0.0f) && c.centre.y == Approx(3.0f)) heavy = c.style.fill;
        if (c.centre.x == Approx(3.0f) && c.centre.y == Approx(3.0f)) steel = c.style.fill;
    }
    REQUIRE(heavy);
    REQUIRE(steel);
    const render::Palette& palette = render::Palette::greybox();
    CHECK(luma(*heavy) < luma(*steel));
    CHECK(luma(*heavy) < luma(palette["ground"]));
    CHECK(luma(*heavy) < 0.5 * luma(palette["background"]));
    CHECK(std::string(findPartKind("heavy")->summary()).starts_with("a dark"));
}
