// The part kinds' descriptors (game/src/items): the registry holds each kind once, in its order;
// every kind's defaults make an item of that kind whose bodies lie inside its extent; and the docs
// in game/scene-format.md list each kind's keys exactly as the descriptors do.
#include "level.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

using namespace rube;
using namespace rube::game;

namespace {

const std::string kDocs = RUBE_GAME_LEVELS_DIR "/../game/scene-format.md";
const std::string kBegin = "<!-- parts: generated from the kinds' descriptors (partKindsMarkdown); "
                           "tests/parts/part_kinds_test.cpp checks it -->\n";
const std::string kEnd = "<!-- parts: end -->";

std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace

TEST_CASE("the registry holds every kind once, in order, each findable by its name", "[parts]") {
    const auto kinds = allPartKinds();
    REQUIRE(kinds.size() >= 15);
    std::set<std::string_view> names;
    for (std::size_t i = 0; i < kinds.size(); ++i) {
        CHECK(names.insert(kinds[i]->name()).second);
        CHECK(findPartKind(kinds[i]->name()) == kinds[i]);
        if (i > 0) CHECK(kinds[i - 1]->order() < kinds[i]->order());
        // Every [[item]] starts with kind, name and position, so messages list them alike.
        REQUIRE(kinds[i]->keys().size() >= 3);
        CHECK(kinds[i]->keys()[0].key == "kind");
        CHECK(kinds[i]->keys()[1].key == "name");
        CHECK(kinds[i]->keys()[2].key == "position");
    }
    CHECK(findPartKind("no such kind") == nullptr);
}

TEST_CASE("each kind's default item is of that kind, and its bodies and room lie inside its extent", "[parts]") {
    for (ItemKind kind : allPartKinds()) {
        for (const double degrees : {0.0, 30.0, 90.0, -135.0}) {
            CAPTURE(kind->name(), degrees);
            ItemDesc item = kind->make({1.5, -2.0});
            item.angle = degrees * 3.141592653589793 / 180.0;
            CHECK(item.kind == kind);
            const Aabb box = kind->extent(item);
            const auto inside = [&](Vec2 p, double r) {
                return p.x - r >= box.min.x - 1e-12 && p.y - r >= box.min.y - 1e-12 && p.x + r <= box.max.x + 1e-12 &&
                       p.y + r <= box.max.y + 1e-12;
            };
            for (const ItemBodies& shapes : {kind->bodies(item), kind->room(item)}) {
                for (const CircleDef& c : shapes.circles) CHECK(inside(c.position, c.radius));
                for (const SegmentDef& s : shapes.segments) CHECK((inside(s.a, s.radius) && inside(s.b, s.radius)));
            }
            // A kind picked by a click is picked at its own position: one with a circle or a segment,
            // or with a rigid body over it (a glove; a gate's board from its hinge; a launcher's
            // plunger starts pulled back from it).
            const ItemBodies room = kind->room(item);
            const bool bodyThere = std::any_of(
                room.rigidBodies.begin(), room.rigidBodies.end(), [&](const RigidBodyDef& b) {
                    const Vec2 x = Vec2::fromAngle(b.angle), d = item.position - b.position;
                    const double pad = b.shape == BodyShape::capsule ? b.halfExtents.y : 0.0;
                    return std::abs(d.dot(x)) <= b.halfExtents.x + pad + 1e-12 &&
                           std::abs(d.dot(x.perpendicular())) <= b.halfExtents.y + 1e-12;
                });
            CHECK(kind->picked(item, item.position, item.position, 0.0) ==
                  (room.circles.size() + room.segments.size() > 0 || bodyThere));
        }
    }
}

TEST_CASE("the docs list every kind's keys as its descriptor does", "[parts]") {
    const std::string docs = readAll(kDocs);
    const std::size_t begin = docs.find(kBegin);
    const std::size_t end = docs.find(kEnd);
    REQUIRE(begin != std::string::npos);
    REQUIRE(end != std::string::npos);
    const std::string generated = partKindsMarkdown();
    // RUBE_WRITE_PART_DOCS=1 rewrites the section from the descriptors (after a kind changes).
    if (const char* write = std::getenv("RUBE_WRITE_PART_DOCS"); write && std::string(write) == "1") {
        std::ofstream(kDocs, std::ios::binary)
            << docs.substr(0, begin + kBegin.size()) << generated << docs.substr(end);
        return;
    }
    const std::string written = docs.substr(begin + kBegin.size(), end - begin - kBegin.size());
    INFO("game/scene-format.md differs from the descriptors: run level_tests \"[parts]\" with RUBE_WRITE_PART_DOCS=1");
    CHECK(written == generated);
    for (ItemKind kind : allPartKinds())
        CHECK(written.find("| **" + std::string(kind->name()) + "** |") != std::string::npos);
}
