// Placement: the three rules a placed item must pass, checked with exact shapes (capsules), not
// boxes, so a ball may sit right beside a sloped ramp whose bounding box it overlaps.
#include "placement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rube::game {

namespace {

// Everything here is a capsule: a segment a-b thickened by radius (a circle has a == b).
struct Capsule {
    Vec2 a, b;
    double radius = 0.0;
    std::string what;  // how a message names it: "the fixed segment 2 ([0, 0] to [8, 0])", "placement 1 (plank)"
    std::string brief; // and the bar: "the fixed segment 2", "your plank 1"
};

double pointSegmentDistance(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 ab = b - a;
    const double l2 = ab.lengthSquared();
    const double t = l2 > 0.0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    return p.distance(a + ab * t);
}

// Two segments are 0 apart when they cross; otherwise the closest pair includes an endpoint.
double segmentDistance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
    const double d1 = (b - a).cross(c - a), d2 = (b - a).cross(d - a);
    const double d3 = (d - c).cross(a - c), d4 = (d - c).cross(b - c);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 0.0;
    return std::min({pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d), pointSegmentDistance(c, a, b),
                     pointSegmentDistance(d, a, b)});
}

bool overlaps(const Capsule& p, const Capsule& q) { return segmentDistance(p.a, p.b, q.a, q.b) < p.radius + q.radius; }

// A rigid body's room as one capsule that holds it whole: a capsule as it is; a box as the capsule
// from end to end of its longer axis with its shorter half-extent as radius, which is the box along
// its long sides and covers its corners with the caps (a placement is refused a little early at
// the ends rather than let the box overlap).
Capsule roomOf(const RigidBodyDef& b, const std::string& what, const std::string& brief) {
    const bool wide = b.shape == BodyShape::capsule || b.halfExtents.x >= b.halfExtents.y;
    const double half = wide ? b.halfExtents.x : b.halfExtents.y;
    const double radius = wide ? b.halfExtents.y : b.halfExtents.x;
    const double axisAngle = wide ? b.angle : b.angle + 0.5 * std::numbers::pi;
    const Vec2 axis{std::cos(axisAngle), std::sin(axisAngle)};
    return {b.position - axis * half, b.position + axis * half, radius, what, brief};
}

void addBodies(const ItemBodies& bodies, const std::string& what, const std::string& brief, std::vector<Capsule>& out) {
    for (const CircleDef& c : bodies.circles) out.push_back({c.position, c.position, c.radius, what, brief});
    for (const SegmentDef& s : bodies.segments) out.push_back({s.a, s.b, s.radius, what, brief});
    for (const RigidBodyDef& b : bodies.rigidBodies) out.push_back(roomOf(b, what, brief));
}

// A pair rounded to centimetres, for the bar: [0.65, 3.45], not [0.650961894323342, 3.45].
std::string roundedPair(Vec2 v) {
    return formatPair(std::round(v.x * 100.0) / 100.0 + 0.0, std::round(v.y * 100.0) / 100.0 + 0.0);
}

std::string itemWords(const ItemDesc& item) {
    std::string words = "the fixed " + std::string(itemKindName(item.kind));
    if (!item.name.empty()) words += " '" + item.name + "'";
    return words;
}

// Every fixed part: the scene's circles and segments, and each fixed item's room (its bodies; a
// cannon, having none, still takes the room of its barrel).
std::vector<Capsule> fixedParts(const SceneDesc& scene) {
    std::vector<Capsule> parts;
    for (std::size_t i = 0; i < scene.circles.size(); ++i)
        parts.push_back({scene.circles[i].position, scene.circles[i].position, scene.circles[i].radius,
                         "the fixed circle " + std::to_string(i), "the fixed circle " + std::to_string(i)});
    for (std::size_t i = 0; i < scene.segments.size(); ++i)
        parts.push_back({scene.segments[i].a, scene.segments[i].b, scene.segments[i].radius,
                         "the fixed segment " + std::to_string(i) + " (" +
                             formatPair(scene.segments[i].a.x, scene.segments[i].a.y) + " to " +
                             formatPair(scene.segments[i].b.x, scene.segments[i].b.y) + ")",
                         "the fixed segment " + std::to_string(i)});
    for (const ItemDesc& item : scene.level.items)
        addBodies(item.kind->room(item), itemWords(item), itemWords(item), parts);
    return parts;
}

// "1 ramp", "0 ramps", "2 heavy balls": a kind's name counted in English. A ball kind's name is an
// adjective (heavy, steel, bouncy), so it takes the noun, unless the name says ball itself (balloon).
std::string kindCount(ItemKind kind, int count) {
    std::string words(itemKindName(kind));
    if (kind->isBall() && !words.starts_with("ball")) words += " ball";
    return words + (count == 1 ? "" : "s");
}

bool inside(const Aabb& outer, const Aabb& inner) {
    return inner.min.x >= outer.min.x && inner.min.y >= outer.min.y && inner.max.x <= outer.max.x &&
           inner.max.y <= outer.max.y;
}

} // namespace

ItemDesc placedItem(const Placement& placement) {
    ItemDesc item = defaultItem(placement.kind, placement.position);
    item.angle = placement.angle;
    if (placement.params) item.params = *placement.params;
    item.name = placement.name;
    item.place = placement.place;
    return item;
}

std::optional<PlacementRefusal> checkPlacements(const SceneDesc& scene, const std::vector<Placement>& placements) {
    std::vector<PlacementRefusal> all = placementRefusals(scene, placements);
    if (all.empty()) return std::nullopt;
    return std::move(all.front());
}

std::vector<std::pair<std::size_t, std::size_t>> overlappingItems(const SceneDesc& scene) {
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    std::vector<std::vector<Capsule>> shapes;
    for (const ItemDesc& item : scene.level.items) {
        shapes.emplace_back();
        addBodies(item.kind->room(item), itemWords(item), itemWords(item), shapes.back());
    }
    for (std::size_t i = 0; i < shapes.size(); ++i)
        for (std::size_t j = i + 1; j < shapes.size(); ++j)
            if (std::any_of(shapes[i].begin(), shapes[i].end(), [&](const Capsule& p) {
                    return std::any_of(shapes[j].begin(), shapes[j].end(),
                                       [&](const Capsule& q) { return overlaps(p, q); });
                }))
                pairs.emplace_back(i, j);
    return pairs;
}

std::vector<PlacementRefusal> placementRefusals(const SceneDesc& scene, const std::vector<Placement>& placements) {
    std::vector<PlacementRefusal> refusals;
    std::vector<Capsule> taken = fixedParts(scene);
    std::map<std::string, int, std::less<>> used;
    for (std::size_t i = 0; i < placements.size(); ++i) {
        const Placement& p = placements[i];
        const ItemDesc item = placedItem(p);
        const std::string kind(itemKindName(p.kind));
        const std::string head = "placement refused: " + kind + " at " + formatPair(p.position.x, p.position.y) + " ";
        const auto refuse = [&](std::string why, std::string brief) {
            refusals.push_back(PlacementRefusal{i, head + why, kind + " at " + roundedPair(p.position) + ": " + brief});
        };
        const auto stock = scene.level.inventory.find(kind);
        const int have = stock == scene.level.inventory.end() ? 0 : stock->second;
        if (used[kind] + 1 > have) {
            refuse("exceeds the inventory: the level gives " + std::to_string(have) + " " + kindCount(p.kind, have) +
                       " and this is number " + std::to_string(used[kind] + 1),
                   "none left (the level gives " + std::to_string(have) + ")");
            continue;
        }
        const Aabb extent = itemExtent(item);
        const bool inZone = std::any_of(scene.level.zones.begin(), scene.level.zones.end(),
                                        [&](const Zone& z) { return inside(z.box, extent); });
        if (!inZone) {
            refuse(scene.level.zones.empty()
                       ? std::string("is outside every placement zone (the level has none)")
                       : "is not wholly inside a placement zone (it spans " + formatPair(extent.min.x, extent.min.y) +
                             " to " + formatPair(extent.max.x, extent.max.y) + ")",
                   scene.level.zones.empty() ? std::string("the level has no placement zone")
                                             : "not inside a zone (it spans " + roundedPair(extent.min) + " to " +
                                                   roundedPair(extent.max) + ")");
            continue;
        }
        std::vector<Capsule> mine;
        addBodies(itemBodies(item), "placement " + std::to_string(i + 1) + " (" + kind + ")",
                  "your " + kind + " (placement " + std::to_string(i + 1) + ")", mine);
        const Capsule* hit = nullptr;
        for (const Capsule& shape : mine)
            for (const Capsule& other : taken)
                if (!hit && overlaps(shape, other)) hit = &other;
        if (hit) {
            refuse("overlaps " + hit->what, "overlaps " + hit->brief);
            continue;
        }
        taken.insert(taken.end(), mine.begin(), mine.end());
        ++used[kind]; // only what was placed uses the inventory up
    }
    return refusals;
}

} // namespace rube::game
