// The catalogue of parts (game/items.md and `rube items`): the document is what the descriptors
// write today, its pictures are exactly one per kind, and each kind's one-line summary states
// numbers its bodies really have, so the docs authors learn defaults from cannot drift or lie.
#include "part_catalogue.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

using namespace rube;
using namespace rube::game;

namespace {

const std::string kGameDir = RUBE_GAME_LEVELS_DIR "/../game";

std::string readAll(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Every number written before `unit` in `text` ("0.3 m" with unit " m"), as doubles.
std::vector<double> numbersBefore(const std::string& text, const std::string& pattern) {
    std::vector<double> out;
    const std::regex re(pattern);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it)
        out.push_back(std::stod((*it)[1].str()));
    return out;
}

bool near(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)); }

} // namespace

TEST_CASE("game/items.md is what the descriptors write", "[parts][catalogue]") {
    const std::filesystem::path doc = kGameDir + "/items.md";
    const std::string generated = partCatalogueMarkdown("items");
    // RUBE_WRITE_ITEMS_DOC=1 rewrites it from the descriptors (after a kind changes).
    if (const char* write = std::getenv("RUBE_WRITE_ITEMS_DOC"); write && std::string(write) == "1") {
        std::ofstream(doc, std::ios::binary) << generated;
        return;
    }
    INFO("game/items.md differs from the descriptors: run level_tests \"[catalogue]\" with RUBE_WRITE_ITEMS_DOC=1");
    CHECK(readAll(doc) == generated);
    for (ItemKind kind : allPartKinds()) {
        std::string heading = "\n## ";
        heading.append(kind->name()).append("\n");
        CHECK(generated.find(heading) != std::string::npos);
        for (const PartKey& key : kind->keys())
            if (key.key != "kind")
                CHECK(generated.find(std::string("`").append(key.key).append("`")) != std::string::npos);
    }
}

TEST_CASE("game/items/ holds one PNG picture per kind, and nothing else", "[parts][catalogue]") {
    std::set<std::string> expected;
    for (ItemKind kind : allPartKinds()) expected.insert(partPictureName(kind));
    std::set<std::string> found;
    for (const auto& entry : std::filesystem::directory_iterator(kGameDir + "/items")) {
        const std::string name = entry.path().filename().string();
        found.insert(name);
        // A PNG starts with its eight-byte signature: a stray text file named .png is not a picture.
        CAPTURE(name);
        CHECK(readAll(entry.path()).substr(0, 8) == std::string("\x89PNG\r\n\x1a\n", 8));
    }
    INFO("regenerate with: ./build/rube items --sheet game/items");
    CHECK(found == expected);
}

TEST_CASE("each kind's summary states radii, masses, lengths and bounciness its bodies have", "[parts][catalogue]") {
    int checked = 0;
    for (ItemKind kind : allPartKinds()) {
        const std::string summary(kind->summary());
        CAPTURE(kind->name(), summary);
        const ItemBodies bodies = kind->bodies(kind->make({0.0, 0.0}));
        for (const double r : numbersBefore(summary, R"(radius ([0-9.]+) m)")) {
            CHECK(std::any_of(bodies.circles.begin(), bodies.circles.end(),
                              [&](const CircleDef& c) { return near(c.radius, r); }));
            ++checked;
        }
        for (const double m : numbersBefore(summary, R"(([0-9.]+) kg)")) {
            const bool circle = std::any_of(bodies.circles.begin(), bodies.circles.end(), [&](const CircleDef& c) {
                return c.motion == Motion::dynamic && near(c.mass, m);
            });
            const bool body = std::any_of(
                bodies.rigidBodies.begin(), bodies.rigidBodies.end(), [&](const RigidBodyDef& b) {
                    return b.motion == Motion::dynamic && std::abs(b.mass - m) <= 0.005; // summaries round to 3 figures
                });
            CHECK((circle || body));
            ++checked;
        }
        for (const double l : numbersBefore(summary, R"(([0-9.]+) m long)")) {
            CHECK(std::any_of(bodies.segments.begin(), bodies.segments.end(),
                              [&](const SegmentDef& s) { return near((s.b - s.a).length(), l); }));
            ++checked;
        }
        for (const double c : numbersBefore(summary, R"(bounciness ([0-9.]+))")) {
            const bool circle = std::any_of(bodies.circles.begin(), bodies.circles.end(),
                                            [&](const CircleDef& b) { return near(b.material.bounciness, c); });
            const bool segment = std::any_of(bodies.segments.begin(), bodies.segments.end(),
                                             [&](const SegmentDef& s) { return near(s.material.bounciness, c); });
            const bool body = std::any_of(bodies.rigidBodies.begin(), bodies.rigidBodies.end(),
                                          [&](const RigidBodyDef& b) { return near(b.material.bounciness, c); });
            CHECK((circle || segment || body));
            ++checked;
        }
    }
    CHECK(checked >= 20); // the summaries do state numbers: the patterns above match
}

TEST_CASE("the printed catalogue names every kind and key with its default", "[parts][catalogue]") {
    const std::string text = partCatalogueText();
    for (ItemKind kind : allPartKinds()) {
        CAPTURE(kind->name());
        const std::size_t at = text.find(std::string(kind->name()) + ": " + std::string(kind->summary()));
        REQUIRE(at != std::string::npos);
        CHECK(text.find("  as made: " + partDefaults(kind), at) != std::string::npos);
        for (const PartKey& key : kind->keys())
            if (key.key != "kind")
                CHECK(text.find(std::string("  ").append(key.key).append(" "), at) != std::string::npos);
    }
}

TEST_CASE("a radius or length key's written default is the size the kind's default item has", "[parts][catalogue]") {
    int checked = 0;
    for (ItemKind kind : allPartKinds()) {
        const ItemBodies bodies = kind->bodies(kind->make({0.0, 0.0}));
        for (const PartKey& key : kind->keys()) {
            CAPTURE(kind->name(), key.key, key.value);
            if (key.key != "radius" && key.key != "length") continue;
            // Every size key shows a number: "as above" sent authors to a summary, or to a refusal.
            char* end = nullptr;
            const std::string text(key.value);
            const double value = std::strtod(text.c_str(), &end);
            REQUIRE(end == text.c_str() + text.size());
            if (key.key == "radius")
                CHECK(std::any_of(bodies.circles.begin(), bodies.circles.end(),
                                  [&](const CircleDef& c) { return near(c.radius, value); }));
            else // a board's segment, or a rigid board's box (a seesaw's plank) end to end, or a
                 // capsule (a hammer's handle) between its caps' centres, or a rod that is a joint (a
                 // pendulum's: from the world's pivot to its anchor on the bob, that far from its centre)
                CHECK((std::any_of(bodies.segments.begin(), bodies.segments.end(),
                                   [&](const SegmentDef& s) { return near((s.b - s.a).length(), value); }) ||
                       std::any_of(bodies.rigidBodies.begin(), bodies.rigidBodies.end(),
                                   [&](const RigidBodyDef& b) { return near(2.0 * b.halfExtents.x, value); }) ||
                       std::any_of(bodies.joints.begin(), bodies.joints.end(), [&](const ItemJoint& j) {
                           return j.a.to == ItemJointEnd::To::world && near(j.def.localAnchorB.length(), value);
                       })));
            ++checked;
        }
    }
    CHECK(checked >= 12);
}
