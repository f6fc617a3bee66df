#pragma once
// A seeded generator of random *valid* scenes (issue 27): circles, segments, boxes (blocks and turning
// ones), capsules, ropes, pivots, water, fans, magnets, thrusters, explosions and kinematic bodies,
// with parameters over wide ranges (masses 1e-6..1e6 kg, time steps up to 0.05 s, speeds up to
// 40 m/s). Bodies are placed in the cells of a grid inside a walled box, so nothing starts
// overlapping; everything else is drawn freely. The same seed gives the same scene on every
// compiler: the generator uses its own integer mixing (splitmix64), not <random>'s distributions,
// whose results the standard leaves to each library.
#include "rube/physics/explosion.hpp"
#include "rube/physics/world.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace rube::test {

/// splitmix64 (Steele, Lea and Flood 2014): a full-period 64-bit generator.
class SceneRng {
public:
    explicit SceneRng(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1): the top 53 bits.
    double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    double in(double lo, double hi) { return lo + (hi - lo) * unit(); }
    /// Log-uniform in [lo, hi] (lo > 0): every decade as likely.
    double logIn(double lo, double hi) { return lo * std::pow(hi / lo, unit()); }
    int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
    bool chance(double p) { return unit() < p; }

private:
    std::uint64_t state_;
};

/// A random scene, built into a world, with what the checks need to know about it.
struct RandomScene {
    World world;
    std::vector<Explosion> explosions; ///< applied at `explosionStep[i]`
    std::vector<int> explosionStep;
    bool energySources = false; ///< fans, thrusters, magnets, water, explosions or kinematic bodies
    bool turning = false;       ///< turning bodies or pivots: only solver and auto accept it
    double floorY = 0.0;        ///< the box's floor: potential energy is measured from here
};

inline Material randomMaterial(SceneRng& rng) {
    Material m;
    m.bounciness = rng.chance(0.2) ? (rng.chance(0.5) ? 0.0 : 1.0) : rng.unit();
    m.friction = rng.chance(0.3) ? 0.0 : rng.in(0.0, 1.0);
    return m;
}

inline double randomMass(SceneRng& rng) {
    // Mostly ordinary masses; one in five at the ends of the range the scene readers accept.
    return rng.chance(0.2) ? (rng.chance(0.5) ? rng.logIn(1e-6, 1e-3) : rng.logIn(1e3, 1e6)) : rng.logIn(0.01, 100.0);
}

inline Vec2 randomVelocity(SceneRng& rng, double maxSpeed) {
    const double angle = rng.in(0.0, 6.283185307179586);
    const double speed = rng.chance(0.3) ? 0.0 : rng.in(0.0, maxSpeed);
    return {speed * std::cos(angle), speed * std::sin(angle)};
}

/// The scene of `seed`; the method is set afterwards by the caller. `afterWalls`, when given, adds
/// to the world after the box's walls and before anything else (the removal tests' far bodies).
inline RandomScene makeRandomScene(std::uint64_t seed, const std::function<void(World&, Vec2 size)>& afterWalls = {}) {
    SceneRng rng(seed * 0x2545f4914f6cdd1dULL + 1);
    WorldDef def;
    const double steps[] = {1.0 / 240, 1.0 / 120, 1.0 / 60, 1.0 / 30, 0.05};
    def.timeStep = rng.chance(0.3) ? rng.in(0.002, 0.05) : steps[rng.below(5)];
    def.gravity = rng.chance(0.1) ? Vec2{0.0, 0.0} : Vec2{rng.in(-2.0, 2.0), -rng.in(1.0, 30.0)};
    def.substeps = 1 + rng.below(12);
    if (rng.chance(0.2)) def.airDrag.linear = rng.in(0.0, 2.0);
    if (rng.chance(0.2)) def.airDrag.quadratic = rng.in(0.0, 1.0);
    const double cell = 1.2;
    const int columns = 3 + rng.below(14), rows = 3 + rng.below(9);
    const double width = columns * cell, height = rows * cell;
    def.bounds = Aabb{{-width, -height}, {2.0 * width, 2.0 * height}};
    RandomScene scene{World(def), {}, {}, false, false, 0.0};
    World& world = scene.world;
    const double maxSpeed = rng.chance(0.3) ? 40.0 : 10.0;

    // The box: floor, walls, sometimes a lid; thin or thick.
    const double wall = rng.chance(0.5) ? 0.0 : rng.in(0.01, 0.2);
    const Material wallMaterial = randomMaterial(rng);
    const auto addWall = [&](Vec2 a, Vec2 b) {
        SegmentDef s;
        s.a = a;
        s.b = b;
        s.radius = wall;
        s.material = wallMaterial;
        world.addSegment(s);
    };
    addWall({0.0, 0.0}, {width, 0.0});
    addWall({0.0, 0.0}, {0.0, height});
    addWall({width, 0.0}, {width, height});
    if (rng.chance(0.5)) addWall({0.0, height}, {width, height});
    if (afterWalls) afterWalls(world, {width, height});

    std::vector<CircleId> dynamicCircles;
    std::vector<int> cells(static_cast<std::size_t>(columns * rows));
    for (int i = 0; i < columns * rows; ++i) cells[static_cast<std::size_t>(i)] = i;
    for (int i = columns * rows - 1; i > 0; --i)
        std::swap(cells[static_cast<std::size_t>(i)], cells[static_cast<std::size_t>(rng.below(i + 1))]);
    const int filled = 1 + rng.below(std::max(1, std::min(30, columns * rows * 2 / 3)));
    for (int k = 0; k < filled; ++k) {
        const int c = cells[static_cast<std::size_t>(k)];
        const Vec2 centre{(c % columns + 0.5) * cell, (c / columns + 0.5) * cell};
        const int kind = rng.below(10);
        if (kind < 5) { // a circle: dynamic mostly, sometimes kinematic on a path
            CircleDef d;
            d.position = centre;
            d.radius = rng.chance(0.2) ? rng.logIn(0.01, 0.05) : rng.in(0.05, 0.5);
            d.mass = randomMass(rng);
            d.velocity = randomVelocity(rng, maxSpeed);
            d.material = randomMaterial(rng);
            d.angularVelocity = rng.chance(0.3) ? rng.in(-30.0, 30.0) : 0.0;
            d.magnetic = rng.chance(0.3);
            if (rng.chance(0.1)) {
                KinematicPath path;
                path.loop = rng.chance(0.5);
                double t = 0.0;
                for (int key = 0; key < 2 + rng.below(3); ++key) {
                    path.keys.push_back(PathKey{t, {rng.in(-0.5, 0.5), rng.in(-0.5, 0.5)}, 0.0});
                    t += rng.in(0.1, 2.0);
                }
                path.keys.front().offset = {};
                d.motion = Motion::kinematic;
                d.path = world.addPath(std::move(path));
                scene.energySources = true;
                world.addCircle(d);
            } else {
                dynamicCircles.push_back(world.addCircle(d));
            }
        } else if (kind < 8) { // a box (block or turning) or a capsule
            RigidBodyDef d;
            d.position = centre;
            d.shape = rng.chance(0.5) ? BodyShape::capsule : BodyShape::box;
            if (d.shape == BodyShape::capsule) d.halfExtents = {rng.in(0.02, 0.35), rng.in(0.02, 0.2)};
            else d.halfExtents = {rng.in(0.03, 0.4), rng.in(0.03, 0.4)};
            d.fixedRotation = d.shape == BodyShape::box && rng.chance(0.4);
            if (!d.fixedRotation) d.angle = rng.in(-3.14, 3.14);
            d.mass = randomMass(rng);
            d.velocity = randomVelocity(rng, maxSpeed);
            d.angularVelocity = d.fixedRotation ? 0.0 : (rng.chance(0.5) ? rng.in(-20.0, 20.0) : 0.0);
            d.material = randomMaterial(rng);
            if (rng.chance(0.1)) d.motion = Motion::fixed;
            const BodyId body = world.addBody(d);
            if (!d.fixedRotation && rng.chance(0.3)) { // a pivot somewhere on or near the body
                PivotDef p;
                p.body = body;
                p.localAnchor = {rng.in(-d.halfExtents.x, d.halfExtents.x), rng.in(-d.halfExtents.y, d.halfExtents.y)};
                const double c0 = std::cos(d.angle), s0 = std::sin(d.angle);
                p.worldAnchor = d.position + Vec2{c0 * p.localAnchor.x - s0 * p.localAnchor.y,
                                                  s0 * p.localAnchor.x + c0 * p.localAnchor.y};
                world.addPivot(p);
            }
        } else { // a segment inside the box: slanted, sometimes kinematic, sometimes a turning paddle
            SegmentDef s;
            const double angle = rng.in(0.0, 3.14159);
            const double half = rng.in(0.1, 0.55);
            s.a = centre - Vec2{std::cos(angle), std::sin(angle)} * half;
            s.b = centre + Vec2{std::cos(angle), std::sin(angle)} * half;
            s.radius = rng.chance(0.5) ? 0.0 : rng.in(0.01, 0.05);
            s.material = randomMaterial(rng);
            if (rng.chance(0.2)) s.surfaceSpeed = rng.in(-5.0, 5.0);
            if (rng.chance(0.15)) {
                KinematicPath path;
                path.loop = true;
                const bool turns = rng.chance(0.5);
                path.keys.push_back(PathKey{0.0, {}, 0.0});
                path.keys.push_back(PathKey{rng.in(0.2, 2.0),
                                            turns ? Vec2{} : Vec2{rng.in(-0.1, 0.1), rng.in(-0.1, 0.1)},
                                            turns ? rng.in(-6.0, 6.0) : 0.0});
                s.path = world.addPath(std::move(path));
                scene.energySources = true;
            }
            world.addSegment(s);
        }
    }
    scene.turning = anyTurning(world.bodies(), world.pivots());

    // Ropes: to a fixed anchor above, or between two circles, never shorter than they are apart.
    const int ropeCount = dynamicCircles.empty() ? 0 : rng.below(4);
    for (int r = 0; r < ropeCount; ++r) {
        RopeDef d;
        d.circle = dynamicCircles[static_cast<std::size_t>(rng.below(static_cast<int>(dynamicCircles.size())))];
        const Vec2 p = world.circle(d.circle).position;
        const CircleId other =
            dynamicCircles[static_cast<std::size_t>(rng.below(static_cast<int>(dynamicCircles.size())))];
        if (other != d.circle && rng.chance(0.5)) {
            d.other = other;
            d.length = (world.circle(other).position - p).length() * rng.in(1.0, 1.5);
        } else {
            d.anchor = p + Vec2{rng.in(-1.0, 1.0), rng.in(0.0, 2.0)};
            d.length = std::max(0.01, (d.anchor - p).length() * rng.in(1.0, 1.5));
        }
        world.addRope(d);
    }

    Fields& fields = world.fields();
    if (rng.chance(0.25)) { // water over the lower part of the box
        Water w;
        w.min = {0.0, 0.0};
        w.max = {width, height * rng.in(0.1, 0.6)};
        w.density = rng.logIn(1.0, 1e4);
        w.drag = rng.logIn(1.0, 1e4);
        fields.waters.push_back(w);
    }
    if (rng.chance(0.25)) {
        Wind f;
        f.origin = {rng.in(0.0, width), rng.in(0.0, height)};
        const double a = rng.in(0.0, 6.283185307179586);
        f.direction = {std::cos(a), std::sin(a)};
        f.length = rng.in(1.0, 10.0);
        f.width = rng.in(0.5, 3.0);
        f.speed = rng.in(0.0, 30.0);
        f.drag = rng.logIn(0.1, 100.0);
        fields.winds.push_back(f);
    }
    if (rng.chance(0.25)) {
        Magnet m;
        m.position = {rng.in(0.0, width), rng.in(0.0, height)};
        m.strength = rng.logIn(0.01, 1000.0);
        m.radius = rng.in(0.05, 1.0);
        fields.magnets.push_back(m);
    }
    if (!dynamicCircles.empty() && rng.chance(0.25)) {
        Thruster t;
        t.circle = dynamicCircles[static_cast<std::size_t>(rng.below(static_cast<int>(dynamicCircles.size())))];
        t.force = randomVelocity(rng, 100.0);
        t.start = rng.in(0.0, 1.0);
        t.end = t.start + rng.in(0.1, 3.0);
        fields.thrusters.push_back(t);
    }
    if (rng.chance(0.25)) {
        Explosion e;
        e.centre = {rng.in(0.0, width), rng.in(0.0, height)};
        e.radius = rng.in(0.5, 5.0);
        e.strength = rng.logIn(0.1, 100.0);
        e.falloff = static_cast<Falloff>(rng.below(3));
        scene.explosions.push_back(e);
        scene.explosionStep.push_back(rng.below(200));
    }
    scene.energySources = scene.energySources || !fields.empty() || !scene.explosions.empty();
    return scene;
}

/// True when every body's position, velocity, angle and spin are finite.
inline bool finiteState(const World& world) {
    for (const Circle& c : world.circles())
        if (!isFinite(c.position) || !isFinite(c.velocity) || !std::isfinite(c.angle) ||
            !std::isfinite(c.angularVelocity))
            return false;
    for (const RigidBody& b : world.bodies())
        if (!isFinite(b.position) || !isFinite(b.velocity) || !std::isfinite(b.angle) ||
            !std::isfinite(b.angularVelocity))
            return false;
    return true;
}

/// Kinetic plus potential energy of the dynamic bodies, the potential measured from `reference`:
/// E = sum 1/2 m v^2 + 1/2 I w^2 - m g.(p - p0).
inline double mechanicalEnergy(const World& world, Vec2 reference) {
    const Vec2 g = world.def().gravity;
    double energy = 0.0;
    const auto add = [&](double inverseMass, double inverseInertia, Vec2 p, Vec2 v, double w) {
        const double m = 1.0 / inverseMass;
        energy += 0.5 * m * v.lengthSquared() - m * g.dot(p - reference);
        if (inverseInertia > 0.0) energy += 0.5 * w * w / inverseInertia;
    };
    for (const Circle& c : world.circles())
        if (c.motion == Motion::dynamic && c.inverseMass > 0.0)
            add(c.inverseMass, c.inverseInertia, c.position, c.velocity, c.angularVelocity);
    for (const RigidBody& b : world.bodies())
        if (b.motion == Motion::dynamic && b.inverseMass > 0.0)
            add(b.inverseMass, b.inverseInertia, b.position, b.velocity, b.angularVelocity);
    return energy;
}

/// sum m |g| over the dynamic bodies: the energy of lifting every body by one metre.
inline double weight(const World& world) {
    double w = 0.0;
    for (const Circle& c : world.circles())
        if (c.motion == Motion::dynamic && c.inverseMass > 0.0) w += world.def().gravity.length() / c.inverseMass;
    for (const RigidBody& b : world.bodies())
        if (b.motion == Motion::dynamic && b.inverseMass > 0.0) w += world.def().gravity.length() / b.inverseMass;
    return w;
}

} // namespace rube::test
