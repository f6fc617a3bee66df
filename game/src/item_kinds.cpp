// Item kinds: their names, default sizes and materials, and the physics bodies each one becomes.
// Every number a kind implies lives in the one table below, so a level states only what differs.
#include "level.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rube::game {

namespace {

constexpr std::string_view kNames[] = {"heavy", "bouncy", "steel", "balloon", "plank",  "ramp",
                                       "bumper", "cannon", "bomb",  "target",  "bucket", "switch", "magnet", "fan", "rocket"};

// A kind's defaults. A pair's bounciness is the product of both (lecture 3), so a dull heavy
// ball stays dull on a lively plank and a bouncy ball stays lively on a bumper.
struct KindDefaults {
    double size;       // radius, or length for planks and ramps, or width for buckets
    double mass;       // kg, balls only
    double bounciness; // C
};

KindDefaults defaultsOf(ItemKind kind) {
    switch (kind) {
    case ItemKind::heavy: return {0.3, 8.0, 0.2};
    case ItemKind::bouncy: return {0.25, 0.5, 0.95};
    case ItemKind::steel: return {0.2, 4.0, 0.7};
    case ItemKind::balloon: return {0.35, 0.1, 0.5};
    case ItemKind::plank: return {2.0, 0.0, 0.5};
    case ItemKind::ramp: return {3.0, 0.0, 0.3};
    case ItemKind::bumper: return {0.4, 0.0, 1.0};
    case ItemKind::cannon: return {0.0, 0.0, 0.0};
    case ItemKind::bomb: return {0.25, 0.0, 0.5};
    case ItemKind::target: return {0.3, 0.0, 0.5};
    case ItemKind::bucket: return {1.2, 0.0, 0.1};
    case ItemKind::switchItem: return {0.2, 0.0, 0.5};
    case ItemKind::magnet: return {0.25, 0.0, 0.3};
    case ItemKind::fan: return {1.2, 0.0, 0.3};
    case ItemKind::rocket: return {0.25, 1.0, 0.3};
    }
    return {0.3, 1.0, 0.5};
}

// Half the thickness of planks, ramps and bucket walls: thick enough to see, thin enough to place.
constexpr double kBoardRadius = 0.05;
// A bucket's walls are this tall unless the level says otherwise.
constexpr double kBucketHeight = 0.8;
// A magnet's default pull at 1 m, N m^2: holds a 4 kg steel ball against gravity from about 1.4 m.
constexpr double kMagnetStrength = 80.0;
// A fan's air: this fast, this far, and this much drag per metre of a ball's width.
constexpr double kFanSpeed = 10.0;
constexpr double kFanReach = 5.0;
constexpr double kFanDrag = 3.0;
constexpr double kMagnetReach = 3.0;
// A rocket's thruster: 15 N on its 1 kg lifts it against gravity at about 5 m/s^2, for 2 s.
constexpr double kRocketThrust = 15.0;
constexpr double kRocketBurn = 2.0;

// A fan's housing: a board across its face, `size` wide, turned to blow along its angle.
std::pair<Vec2, Vec2> fanEnds(const ItemDesc& item) {
    const Vec2 across = Vec2::fromAngle(item.angle).perpendicular() * (0.5 * item.size);
    return {item.position - across, item.position + across};
}

// The two ends of a plank or ramp: `length` long, centred on its position, tilted by its angle.
std::pair<Vec2, Vec2> boardEnds(const ItemDesc& item) {
    const Vec2 half = Vec2::fromAngle(item.angle) * (0.5 * item.size);
    return {item.position - half, item.position + half};
}

} // namespace

std::string_view itemKindName(ItemKind kind) { return kNames[static_cast<int>(kind)]; }

int LevelDesc::find(std::string_view name) const {
    for (std::size_t i = 0; i < items.size(); ++i)
        if (!name.empty() && items[i].name == name) return static_cast<int>(i);
    return -1;
}

bool isBall(ItemKind kind) {
    return kind == ItemKind::heavy || kind == ItemKind::bouncy || kind == ItemKind::steel || kind == ItemKind::balloon;
}

bool isPlaceable(ItemKind kind) {
    return isBall(kind) || kind == ItemKind::plank || kind == ItemKind::ramp || kind == ItemKind::bumper ||
           kind == ItemKind::bomb || kind == ItemKind::magnet || kind == ItemKind::fan || kind == ItemKind::rocket;
}

ItemDesc defaultItem(ItemKind kind, Vec2 position) {
    ItemDesc item;
    item.kind = kind;
    item.position = position;
    item.size = defaultsOf(kind).size;
    item.height = kBucketHeight;
    item.speed = kind == ItemKind::fan ? kFanSpeed : 8.0;
    item.blastRadius = 2.0;
    item.strength = kind == ItemKind::magnet ? kMagnetStrength : 6.0;
    item.reach = kind == ItemKind::fan ? kFanReach : kMagnetReach;
    item.thrust = kRocketThrust;
    item.burn = kRocketBurn;
    // A placed bomb has no fuse or switch to wait for: it goes off when something hits it.
    item.trigger = Trigger::impact;
    return item;
}

ItemBodies itemBodies(const ItemDesc& item) {
    ItemBodies bodies;
    const KindDefaults defaults = defaultsOf(item.kind);
    Material material;
    material.bounciness = defaults.bounciness;
    // A ball, or the round body of a rocket: placed where the item is, sized and weighed by its kind.
    const auto roundBody = [&] {
        CircleDef ball;
        ball.position = item.position;
        ball.velocity = item.velocity;
        ball.radius = item.size;
        ball.mass = defaults.mass;
        ball.material = material;
        return ball;
    };
    if (isBall(item.kind)) {
        CircleDef ball = roundBody();
        ball.magnetic = item.kind == ItemKind::steel;
        bodies.circles.push_back(ball);
        return bodies;
    }
    switch (item.kind) {
    case ItemKind::plank:
    case ItemKind::ramp: {
        const auto [a, b] = boardEnds(item);
        bodies.segments.push_back({a, b, kBoardRadius, material, -1});
        break;
    }
    case ItemKind::bucket: {
        // Floor and two walls, the walls standing on the floor's ends.
        const double half = 0.5 * item.size;
        const Vec2 left = item.position + Vec2{-half, 0.0};
        const Vec2 right = item.position + Vec2{half, 0.0};
        const Vec2 up{0.0, item.height};
        bodies.segments.push_back({left, right, kBoardRadius, material, -1});
        bodies.segments.push_back({left, left + up, kBoardRadius, material, -1});
        bodies.segments.push_back({right, right + up, kBoardRadius, material, -1});
        break;
    }
    case ItemKind::cannon: break; // a cannon is scenery: its shots must not hit its own barrel
    case ItemKind::fan: {
        const auto [a, b] = fanEnds(item);
        bodies.segments.push_back({a, b, kBoardRadius, material, -1});
        // The air column starts at the housing's face, so a ball resting on the housing is not blown through it.
        Wind wind;
        wind.direction = Vec2::fromAngle(item.angle);
        wind.origin = item.position + wind.direction * kBoardRadius;
        wind.length = item.reach;
        wind.width = item.size;
        wind.speed = item.speed;
        wind.drag = kFanDrag;
        wind.on = item.on;
        bodies.wind = wind;
        break;
    }
    case ItemKind::rocket: {
        bodies.circles.push_back(roundBody());
        // Lit at the start it burns [0, burn); unlit, it waits (start and end at infinity) for a switch or click.
        Thruster thruster;
        thruster.force = Vec2::fromAngle(item.angle) * item.thrust;
        thruster.start = item.on ? 0.0 : std::numeric_limits<double>::infinity();
        thruster.end = item.on ? item.burn : std::numeric_limits<double>::infinity();
        bodies.thruster = thruster;
        break;
    }
    case ItemKind::magnet:
        bodies.magnet = Magnet{item.position, item.strength, item.size, item.reach, item.on};
        [[fallthrough]];
    default: {
        CircleDef part;
        part.position = item.position;
        part.radius = item.size;
        part.material = material;
        part.motion = item.path >= 0 ? Motion::kinematic : Motion::fixed;
        part.path = item.path;
        bodies.circles.push_back(part);
        break;
    }
    }
    return bodies;
}

Aabb itemExtent(const ItemDesc& item) {
    if (item.kind == ItemKind::plank || item.kind == ItemKind::ramp) {
        const auto [a, b] = boardEnds(item);
        const Vec2 pad{kBoardRadius, kBoardRadius};
        return {Vec2{std::min(a.x, b.x), std::min(a.y, b.y)} - pad, Vec2{std::max(a.x, b.x), std::max(a.y, b.y)} + pad};
    }
    if (item.kind == ItemKind::fan) {
        const auto [a, b] = fanEnds(item);
        const Vec2 pad{kBoardRadius, kBoardRadius};
        return {Vec2{std::min(a.x, b.x), std::min(a.y, b.y)} - pad, Vec2{std::max(a.x, b.x), std::max(a.y, b.y)} + pad};
    }
    if (item.kind == ItemKind::bucket) {
        const double half = 0.5 * item.size + kBoardRadius;
        return {item.position + Vec2{-half, -kBoardRadius}, item.position + Vec2{half, item.height + kBoardRadius}};
    }
    // A cannon occupies its barrel's length around its position.
    const double r = item.kind == ItemKind::cannon ? 0.6 : item.size;
    return {item.position - Vec2{r, r}, item.position + Vec2{r, r}};
}

} // namespace rube::game
