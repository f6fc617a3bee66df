// The catalogue of part kinds, written from their descriptors: the keys as each kind lists them,
// and the defaults measured from the bodies of an item made at its defaults (PartKind::make and
// PartKind::bodies), so "a ramp is 3 m long" is what the physics gets, not a remembered number.
#include "part_catalogue.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <vector>

namespace rube::game {

namespace {

// A number as the docs write it: up to four significant digits, no trailing zeros.
std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

std::string traits(ItemKind kind) {
    std::string out;
    const auto add = [&](const char* trait) { out += (out.empty() ? "" : ", ") + std::string(trait); };
    if (kind->placeable()) add("placeable");
    if (kind->turns()) add("turns");
    if (kind->needsName() && kind->summary().find("needs a name") == std::string_view::npos) add("needs a name");
    if (kind->isBall()) add("a cannon may shoot it");
    return out;
}

// A circle of the default item: a dynamic one is a ball with a mass, a fixed one a round part.
std::string circleText(const CircleDef& c) {
    std::string out = c.motion == Motion::dynamic
                          ? "a ball of radius " + number(c.radius) + " m, " + number(c.mass) + " kg"
                          : "a fixed circle of radius " + number(c.radius) + " m";
    out += ", bounciness " + number(c.material.bounciness);
    if (c.motion == Motion::dynamic && c.magnetic) out += ", magnetic";
    if (c.motion == Motion::dynamic && c.gravityScale != 1.0) out += ", gravity scale " + number(c.gravityScale);
    return out;
}

// A board's length between its end caps' centres, and end to end (a capsule of radius r is 2r longer).
std::string segmentText(const SegmentDef& s) {
    const double length = (s.b - s.a).length();
    return "a fixed board " + number(length) + " m long (" + number(length + 2.0 * s.radius) +
           " m end to end), bounciness " + number(s.material.bounciness);
}

// A rigid body of the default item: a box or capsule, its size, mass (when it moves) and material.
std::string rigidBodyText(const RigidBodyDef& b) {
    const Vec2 size = b.halfExtents * 2.0;
    std::string out = b.shape == BodyShape::box
                          ? "a box " + number(size.x) + " x " + number(size.y) + " m"
                          : "a capsule " + number(size.x) + " m long, radius " + number(b.halfExtents.y) + " m";
    if (b.motion == Motion::dynamic) out += ", " + number(b.mass) + " kg";
    out += ", bounciness " + number(b.material.bounciness);
    if (b.material.friction > 0.0) out += ", friction " + number(b.material.friction);
    return out;
}

std::string keyDefault(ItemKind kind, const PartKey& key) {
    const bool required = key.value == "required" || (key.key == kNameKey.key && kind->needsName());
    return required ? "required" : std::string(key.value);
}

} // namespace

std::string partDefaults(ItemKind kind) {
    const ItemDesc item = kind->make({0.0, 0.0});
    const ItemBodies bodies = kind->bodies(item);
    std::vector<std::string> parts;
    for (const CircleDef& c : bodies.circles) parts.push_back(circleText(c));
    for (const SegmentDef& s : bodies.segments) parts.push_back(segmentText(s));
    for (const RigidBodyDef& b : bodies.rigidBodies) parts.push_back(rigidBodyText(b));
    if (bodies.magnet)
        parts.push_back("a pull of " + number(bodies.magnet->strength) + " N m^2 at 1 m, none from " +
                        number(bodies.magnet->reach) + " m");
    if (bodies.wind)
        parts.push_back("air at " + number(bodies.wind->speed) + " m/s in a column " + number(bodies.wind->width) +
                        " m wide, " + number(bodies.wind->length) + " m long");
    if (bodies.thruster)
        parts.push_back("a thrust of " + number(bodies.thruster->force.length()) + " N for " +
                        number(bodies.thruster->end - bodies.thruster->start) + " s");
    if (const auto shot = kind->shot(item); shot && !kind->isBall())
        parts.push_back("shoots " + circleText(*shot) + " at " + number(kind->muzzleSpeed(item)) + " m/s");
    if (parts.empty()) parts.push_back("no body");
    // Equal bodies once, counted (a bucket's two walls).
    std::string out;
    for (std::size_t i = 0; i < parts.size();) {
        std::size_t same = i + 1;
        while (same < parts.size() && parts[same] == parts[i]) ++same;
        out += (out.empty() ? "" : "; ") + parts[i] + (same - i > 1 ? " (x" + std::to_string(same - i) + ")" : "");
        i = same;
    }
    const Aabb box = kind->extent(item);
    return out + "; takes " + number(box.max.x - box.min.x) + " x " + number(box.max.y - box.min.y) + " m";
}

std::string partPictureName(ItemKind kind) { return std::string(kind->name()) + ".png"; }

std::string partCatalogueText() {
    std::string out;
    for (ItemKind kind : allPartKinds()) {
        out += std::string(kind->name()) + ": " + std::string(kind->summary());
        const std::string t = traits(kind);
        out += t.empty() ? "\n" : " (" + t + ")\n";
        out += "  as made: " + partDefaults(kind) + "\n";
        for (const PartKey& key : kind->keys()) {
            if (key.key == kKindKey.key) continue;
            char line[256];
            std::snprintf(line, sizeof line, "  %-13s %-9s %s\n", std::string(key.key).c_str(),
                          keyDefault(kind, key).c_str(), std::string(key.doc).c_str());
            out += line;
        }
    }
    return out;
}

std::string partCatalogueMarkdown(const std::string& pictureFolder) {
    std::string out =
        "# The parts\n\n"
        "<!-- Generated from the kinds' descriptors (game/src/items/*.cpp) by partCatalogueMarkdown; do not edit.\n"
        "     tests/parts/items_catalogue_test.cpp checks it is current: after changing a kind, run\n"
        "     RUBE_WRITE_ITEMS_DOC=1 ./build/tests/level_tests \"[catalogue]\" and, for the pictures,\n"
        "     ./build/rube items --sheet game/items -->\n\n"
        "Every kind of part a level or a script may use, in the order messages list them: what it is, what an item of "
        "it\n"
        "is at its defaults (measured from the bodies the game makes for it), and its `[[item]]` keys. `rube items`\n"
        "prints the same; `rube items --sheet DIR` draws the pictures. A part placed with the mouse in `rube play` "
        "takes\n"
        "its position, and its angle when it turns; every other key keeps the default below. A script's `[[place]]` "
        "may\n"
        "also give the kind's own keys (a plank's `length`, a bomb's `trigger` and `fuse`). Keys and their syntax:\n"
        "[scene-format.md](scene-format.md).\n";
    for (ItemKind kind : allPartKinds()) {
        const std::string name(kind->name());
        out += "\n## " + name + "\n\n![" + name + "](" + pictureFolder + "/" + partPictureName(kind) + ")\n\n";
        std::string summary(kind->summary());
        summary[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(summary[0])));
        out += summary + ".";
        const std::string t = traits(kind);
        if (!t.empty()) {
            std::string sentence = t;
            sentence[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(sentence[0])));
            out += " " + sentence + ".";
        }
        out += "\n\nAs made: " + partDefaults(kind) + ".\n\n| key | default | meaning |\n|---|---|---|\n";
        for (const PartKey& key : kind->keys()) {
            if (key.key == kKindKey.key) continue;
            out += "| `" + std::string(key.key) + "` | " + markdownCell(keyDefault(kind, key)) + " | " +
                   markdownCell(key.doc) + " |\n";
        }
    }
    return out;
}

} // namespace rube::game
