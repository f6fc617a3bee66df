#pragma once
/// What the kinds' own files share: the drawing helpers, the board thickness, the reading ranges,
/// and the bases of the kinds that differ only in numbers (balls, boards). Internal to game/src/items.

#include "level_run.hpp"
#include "part_kind.hpp"
#include "scene_reading.hpp"

#include "rube/render/draw_list.hpp"
#include "rube/render/palette.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace rube::game::parts {

/// Half the thickness of planks, ramps, bucket walls and a fan's housing: thick enough to see, thin enough to place, m.
inline constexpr double kBoardRadius = 0.05;
/// A single item beyond this size is a typo for another unit, not a part of a puzzle, m.
inline constexpr double kMaxItemSize = 100.0;
/// The range of a size key: positive, at most kMaxItemSize.
inline const NumberRange kSizeRange{0.0, kMaxItemSize, true};
/// The range of an angle key, degrees.
inline const NumberRange kAngleRange{-360.0, 360.0};
/// An outline's stroke, pixels.
inline constexpr float kOutline = 1.5f;

/// Degrees as files write them to radians.
inline double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }
/// A point for the renderer.
inline render::Point pt(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }
/// A fill and an outline from the greybox palette, by role.
inline render::Style style(const char* fill, const char* outline, float width = kOutline) {
    const render::Palette& p = render::Palette::greybox();
    return {p[fill], p[outline], width};
}
/// A material of bounciness `c` (a pair's bounciness is the product of both, lecture 3).
inline Material bouncy(double c) {
    Material m;
    m.bounciness = c;
    return m;
}
/// A fixed (or, on a path, kinematic) round part of `radius` at the item's position.
inline CircleDef roundPart(const ItemDesc& item, double radius, double bounciness, int path = -1) {
    CircleDef part;
    part.position = item.position;
    part.radius = radius;
    part.material = bouncy(bounciness);
    part.motion = path >= 0 ? Motion::kinematic : Motion::fixed;
    part.path = path;
    return part;
}
/// The item's state in the run.
inline const ItemState& stateOf(const PartDrawing& d) { return d.run.states()[static_cast<std::size_t>(d.item)]; }
/// The item in the run.
inline const ItemDesc& itemOf(const PartDrawing& d) { return d.run.items()[static_cast<std::size_t>(d.item)]; }

/// True while the item's first joint's motor is on: a latch holding (a launcher's guide, a gate's
/// hinge, a hammer's pivot, each held by a motor at speed 0), a motor powered.
inline bool firstMotorOn(const PartDrawing& d) {
    const ItemState& state = stateOf(d);
    return !state.joints.empty() && !state.joints.front().isNull() &&
           d.run.world().joint(state.joints.front()).def.motor.on();
}

/// Whether the world's clock has reached time `at`: a time within 1e-9 s of the step's end counts as
/// reached, not missed by rounding (n steps of dt add up to n dt give or take a few ulps). The rule of
/// every part's timer: fuses, delays, burns, holds, runs.
inline bool timeReached(const World& world, double at) { return world.time() >= at - 1e-9; }

/// Releases a latch: turns the item's first joint's motor off, for good (a released spring, gate or
/// hammer stays free).
inline void releaseLatch(LevelRun& run, int item) {
    const ItemState& state = run.states()[static_cast<std::size_t>(item)];
    if (state.joints.empty() || state.joints.front().isNull()) return;
    run.partWorld().setJointMotor(state.joints.front(), {});
}

/// A ball's first touch of `item` (a switch, scissors): marks it hit and reports the hit event; false
/// when it was touched before, for only the first touch is news.
inline bool firstTouch(LevelRun& run, int item, Vec2 point, const std::string& by) {
    ItemState& state = run.partState(item);
    if (state.hit) return false;
    state.hit = true;
    run.report({EventKind::hit, run.steps(), run.world().time(), run.items()[static_cast<std::size_t>(item)].name,
                point, 0, by});
    return true;
}

/// A ball's parameters: every ball kind has these and nothing more.
struct BallParams {
    double radius = 0.3; ///< m
    Vec2 velocity;       ///< initial velocity, m/s
};

/// The keys of a ball whose default radius the docs write as `radius` (each ball kind lists its
/// own; tests/parts/items_catalogue_test.cpp checks the text against the radius its bodies get).
constexpr std::array<PartKey, 5> ballKeys(std::string_view radius) {
    return {kKindKey, kNameKey, kPositionKey, PartKey{"radius", radius, "m"},
            PartKey{"velocity", "[0, 0]", "initial velocity, m/s"}};
}

/// A dynamic ball: the kinds differ in radius, mass, bounciness and look only.
class BallKind : public PartKind {
public:
    bool isBall() const override { return true; }
    bool placeable() const override { return true; }
    bool plays(PartRole role) const override { return role == PartRole::goalMover; }
    ItemDesc make(Vec2 position) const override { return made(position, BallParams{radius(), {}}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        BallParams& p = item.params.as<BallParams>();
        if (const auto r = table.number("radius", kSizeRange)) p.radius = *r;
        if (const auto v = table.vec2("velocity")) p.velocity = *v;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const BallParams& p = item.params.as<BallParams>();
        CircleDef ball;
        ball.position = item.position;
        ball.velocity = p.velocity;
        ball.radius = p.radius;
        ball.mass = mass();
        ball.material = bouncy(bounciness());
        ball.magnetic = magnetic();
        ball.gravityScale = gravityScale();
        ItemBodies bodies;
        bodies.circles.push_back(ball);
        return bodies;
    }
    std::optional<CircleDef> shot(const ItemDesc& item) const override { return bodies(item).circles.front(); }
    void draw(const PartDrawing& d) const override {
        const ItemState& state = stateOf(d);
        if (state.circle.isNull()) return; // gone from the world (a balloon a needle popped)
        const Circle& c = d.run.world().circle(state.circle);
        decorateBehind(c, d.list);
        d.list.circleWithSpoke(pt(c.position), static_cast<float>(c.radius), static_cast<float>(c.velocity.angle()),
                               look());
        decorateFront(c, d.list);
    }
    void drawIcon(Vec2 centre, double size, bool available, render::DrawList& list) const override {
        render::Style ball = look();
        if (!available) ball.fill = ball.fill.withAlpha(0x60);
        list.circle(pt(centre), 0.8f * static_cast<float>(0.5 * size), ball);
    }

protected:
    /// Default radius, m.
    virtual double radius() const = 0;
    /// Mass, kg.
    virtual double mass() const = 0;
    /// Bounciness C.
    virtual double bounciness() const = 0;
    /// True when magnets pull it.
    virtual bool magnetic() const { return false; }
    /// How much of the world's gravity acts on it (World: gravity scale): 1, or -1 for a balloon that rises.
    virtual double gravityScale() const { return 1.0; }
    /// Its fill and outline.
    virtual render::Style look() const { return style("ball", "ball_outline"); }
    /// Drawn before the ball (a balloon's string).
    virtual void decorateBehind(const Circle& c, render::DrawList& list) const { (void)c, (void)list; }
    /// Drawn over the ball (a bouncy ball's ring).
    virtual void decorateFront(const Circle& c, render::DrawList& list) const { (void)c, (void)list; }
};

/// A board's parameters.
struct BoardParams {
    double length = 2.0; ///< m
};

/// The keys of a board whose default length the docs write as `length` (checked as a ball's radius).
constexpr std::array<PartKey, 5> boardKeys(std::string_view length) {
    return {kKindKey, kNameKey, kPositionKey, PartKey{"angle", "0", "tilt, degrees"},
            PartKey{"length", length, "m, between its end caps' centres"}};
}

/// A fixed straight board, centred on its position and tilted by its angle: planks and ramps.
class BoardKind : public PartKind {
public:
    bool placeable() const override { return true; }
    bool turns() const override { return true; }
    double turnPeriod() const override { return 180.0; } // its two ends are alike
    ItemDesc make(Vec2 position) const override { return made(position, BoardParams{length()}); }
    void read(TableReader& table, ItemDesc& item, SceneReading& reading) const override {
        (void)reading;
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto l = table.number("length", kSizeRange)) item.params.as<BoardParams>().length = *l;
    }
    ItemBodies bodies(const ItemDesc& item) const override {
        const Vec2 half = Vec2::fromAngle(item.angle) * (0.5 * item.params.as<BoardParams>().length);
        ItemBodies bodies;
        bodies.segments.push_back({item.position - half, item.position + half, kBoardRadius, bouncy(bounciness()), -1});
        return bodies;
    }
    void draw(const PartDrawing& d) const override { (void)d; } // drawn with the world's segments

protected:
    /// Default length, m.
    virtual double length() const = 0;
    /// Bounciness C.
    virtual double bounciness() const = 0;
};

/// A loose box's parameters (crates, dominoes): its size, mass and starting velocity.
struct LooseBoxParams {
    Vec2 size{0.5, 0.5}; ///< width and height at angle 0, m
    double mass = 1.0;   ///< kg
    Vec2 velocity;       ///< initial velocity, m/s
    Material material;   ///< bounciness and friction (a pair's mu is the product of both, as its C)
};

/// A dynamic box that turns (a rigid body, solved by `auto` or `solver`), placed and turned by the
/// player: the kinds differ in how they read their size, mass and material, and in their look.
class LooseBoxKind : public PartKind {
public:
    bool placeable() const override { return true; }
    bool turns() const override { return true; }
    double turnPeriod() const override { return 180.0; } // a box is the same after half a turn
    bool plays(PartRole role) const override { return role == PartRole::goalMover; }
    ItemDesc make(Vec2 position) const override { return made(position, defaults()); }
    ItemBodies bodies(const ItemDesc& item) const override {
        const LooseBoxParams& p = item.params.as<LooseBoxParams>();
        RigidBodyDef box;
        box.shape = BodyShape::box;
        box.position = item.position;
        box.angle = item.angle;
        box.velocity = p.velocity;
        box.halfExtents = p.size * 0.5;
        box.mass = p.mass;
        box.material = p.material;
        ItemBodies bodies;
        bodies.rigidBodies.push_back(box);
        return bodies;
    }
    /// Picked anywhere on the box as it stands now (`at`, at the item's angle), `tolerance` around it.
    bool picked(const ItemDesc& item, Vec2 at, Vec2 cursor, double tolerance) const override {
        const Vec2 half = item.params.as<LooseBoxParams>().size * 0.5;
        const Vec2 x = Vec2::fromAngle(item.angle), d = cursor - at;
        return std::abs(d.dot(x)) <= half.x + tolerance && std::abs(d.dot(x.perpendicular())) <= half.y + tolerance;
    }

protected:
    /// The parameters of an item as made.
    virtual LooseBoxParams defaults() const = 0;
    /// Reads `angle` and `velocity`, the keys every loose box has.
    static void readPose(TableReader& table, ItemDesc& item) {
        if (const auto a = table.number("angle", kAngleRange)) item.angle = radians(*a);
        if (const auto v = table.vec2("velocity")) item.params.as<LooseBoxParams>().velocity = *v;
    }
    /// The box as it is in the run (drawn by the world's bodies; kinds draw over it).
    static const RigidBody& bodyOf(const PartDrawing& d) { return d.run.world().body(stateOf(d).body); }
};

} // namespace rube::game::parts
