// The failure probes. Each builds a small world through rube's public API, steps it, and after
// every step looks for the failures the issue names; a run stops at its first failing step, so a
// method that breaks early costs little (and the exact method's event cap bounds every step).

#include "failure_probes.hpp"

#include "rube/physics/collision.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace bench::failures {
namespace {

using rube::Circle;
using rube::Method;
using rube::Vec2;
using rube::World;

constexpr double kGravity = 9.81;
constexpr double kRadius = 0.1; // stack, mass-ratio and bounciness probes

World makeWorld(Method method, double gravity, double timeStep = kTimeStep) {
    rube::WorldDef def; // the rest as a level gets it: event cap 4096, resting speed 2 |g| dt + 1 mm/s, 8 substeps
    def.method = method;
    def.timeStep = timeStep;
    def.gravity = {0.0, -gravity};
    return World(def);
}

void addFloor(World& world) {
    rube::SegmentDef floor;
    floor.a = {-10.0, 0.0};
    floor.b = {10.0, 0.0};
    world.addSegment(floor);
}

void addBall(World& world, Vec2 position, Vec2 velocity, double radius, double mass, double bounciness) {
    rube::CircleDef def;
    def.position = position;
    def.velocity = velocity;
    def.radius = radius;
    def.mass = mass;
    def.material = {bounciness, 0.0};
    world.addCircle(def);
}

// Total energy: potential above the floor plus kinetic, sum m (g y + v^2 / 2). The probes have no
// friction, so no spin is ever started and rotation holds no energy.
double energy(const World& world) {
    const double g = -world.def().gravity.y;
    double e = 0.0;
    for (const Circle& c : world.circles()) e += (g * c.position.y + 0.5 * c.velocity.lengthSquared()) / c.inverseMass;
    return e;
}

// The largest overlap after a step, as a fraction of the radius: every pair (the probes hold a few
// balls) and every ball against every segment.
double deepestOverlap(const World& world) {
    double deepest = 0.0;
    const auto circles = world.circles();
    for (std::size_t i = 0; i < circles.size(); ++i) {
        const Circle& a = circles[i];
        for (std::size_t j = i + 1; j < circles.size(); ++j)
            if (const auto o = rube::circleCircleOverlap(a.position, a.radius, circles[j].position, circles[j].radius))
                deepest = std::max(deepest, o->depth / std::min(a.radius, circles[j].radius));
        for (const rube::Segment& s : world.segments())
            if (const auto o = rube::circleSegmentOverlap(a.position, a.radius, s.a, s.b, s.radius))
                deepest = std::max(deepest, o->depth / a.radius);
    }
    return deepest;
}

// Steps `world` up to `steps` times, checking after each step; `passedThrough` says whether a body
// is now where it can only be by passing through another (a tunnel or a sink, per probe).
Outcome watch(World& world, int steps, const std::function<bool(const World&)>& passedThrough, bool throughIsTunnel) {
    Outcome out;
    const double energy0 = energy(world);
    for (int step = 0; step < steps && !out.failed(); ++step) {
        world.step();
        for (const Circle& c : world.circles())
            if (!rube::isFinite(c.position) || !rube::isFinite(c.velocity)) out.nonFinite = true;
        if (out.nonFinite) break;
        if (passedThrough(world)) (throughIsTunnel ? out.tunnels : out.sinks) = true;
        out.eventCap = world.stats().capsHit > 0;
        out.deepestOverlap = std::max(out.deepestOverlap, deepestOverlap(world));
        out.overlaps = out.deepestOverlap > kOverlapTolerance;
        out.energyGain = std::max(out.energyGain, (energy(world) - energy0) / energy0);
        out.gainsEnergy = out.energyGain > kEnergyTolerance;
    }
    return out;
}

// True when the balls, added bottom to top, are no longer in that order or the lowest is below the floor.
bool columnBroken(const World& world) {
    const auto c = world.circles();
    if (c[0].position.y < 0.0) return true;
    for (std::size_t i = 1; i < c.size(); ++i)
        if (c[i].position.y < c[i - 1].position.y) return true;
    return false;
}

} // namespace

std::string Outcome::describe() const {
    std::string s;
    const auto add = [&](bool flag, const char* name) {
        if (!flag) return;
        if (!s.empty()) s += ", ";
        s += name;
    };
    add(nonFinite, "NaN");
    add(tunnels, "tunnels");
    add(sinks, "sinks");
    add(eventCap, "event cap");
    add(overlaps, "overlap > 5 % r");
    add(gainsEnergy, "gains energy");
    add(misdirected, "bounce off > 0.5 deg");
    add(refused, "refuses joints");
    add(stretches, "stretches > 1 %");
    add(missesFormula, "misses its formula > 1 %");
    add(losesEnergy, "loses energy");
    return s;
}

Outcome speedProbe(Method method, double travelPerRadius, int phases) {
    constexpr double r = 0.05;
    const double travel = travelPerRadius * r; // speed x dt
    const double speed = travel / kTimeStep;
    Outcome worst; // the deepest overlap and largest gain over the phases that held
    for (int k = 0; k < phases; ++k) {
        World world = makeWorld(method, 0.0);
        addFloor(world);
        // Three steps and a fraction of a fourth from touching: the crossing step starts at every phase.
        const double startY = r + travel * (3.0 + static_cast<double>(k) / phases);
        addBall(world, {0.0, startY}, {0.0, -speed}, r, 1.0, 1.0);
        // Below the thin line at y = 0 the ball can only be by passing through it.
        const Outcome out = watch(
            world, 8, [](const World& w) { return w.circles()[0].position.y < 0.0; }, true);
        if (out.failed()) return out;
        worst.deepestOverlap = std::max(worst.deepestOverlap, out.deepestOverlap);
        worst.energyGain = std::max(worst.energyGain, out.energyGain);
    }
    return worst;
}

Outcome stackProbe(Method method, int height, double timeStep) {
    World world = makeWorld(method, kGravity, timeStep);
    addFloor(world);
    for (int i = 0; i < height; ++i) addBall(world, {0.0, kRadius + 2.0 * kRadius * i}, {}, kRadius, 1.0, 0.0);
    return watch(world, static_cast<int>(std::lround(2.0 / timeStep)), columnBroken, false);
}

Outcome massRatioProbe(Method method, double ratio) {
    World world = makeWorld(method, kGravity);
    addFloor(world);
    addBall(world, {0.0, kRadius}, {}, kRadius, 1.0, 0.0);
    addBall(world, {0.0, 3.0 * kRadius}, {}, kRadius, ratio, 0.0);
    return watch(world, static_cast<int>(std::lround(2.0 / kTimeStep)), columnBroken, false);
}

Outcome bouncinessProbe(Method method, double bounciness) {
    constexpr double gap = 0.1;
    World world = makeWorld(method, kGravity);
    addFloor(world);
    for (int i = 0; i < 4; ++i)
        addBall(world, {0.0, kRadius + gap + (2.0 * kRadius + gap) * i}, {}, kRadius, 1.0, bounciness);
    return watch(world, static_cast<int>(std::lround(3.0 / kTimeStep)), columnBroken, false);
}

Outcome floorStackProbe(Method method, int height, double timeStep) {
    constexpr double r = 0.2;
    World world = makeWorld(method, kGravity, timeStep);
    addFloor(world);
    for (int i = 0; i < height; ++i) addBall(world, {0.0, r + 2.0 * r * i}, {}, r, 1.0, 0.0);
    Outcome out;
    for (int step = 0; step < static_cast<int>(std::lround(5.0 / timeStep)) && !out.sinks; ++step) {
        world.step();
        out.sinks = !(world.circles()[0].position.y >= 0.0); // NaN counts as through
    }
    return out;
}

Outcome inclineProbe(Method method, double degrees) {
    constexpr double r = 0.25;
    const double theta = degrees * std::acos(-1.0) / 180.0;
    World world = makeWorld(method, kGravity);
    const Vec2 down{std::cos(theta), -std::sin(theta)};
    const Vec2 normal{std::sin(theta), std::cos(theta)};
    rube::SegmentDef line;
    line.a = down * -600.0;
    line.b = down * 600.0;
    world.addSegment(line);
    const Vec2 start = down * -300.0 + normal * r;
    addBall(world, start, {}, r, 1.0, 0.0);
    const auto e = [&] {
        const Circle& c = world.circles()[0];
        return kGravity * c.position.y + 0.5 * c.velocity.lengthSquared();
    };
    const double e0 = e();
    Outcome out;
    const int steps = static_cast<int>(std::lround(10.0 / kTimeStep));
    for (int step = 0; step < steps; ++step) {
        world.step();
        out.energyGain = std::max(out.energyGain, (e() - e0) / std::abs(e0));
    }
    out.gainsEnergy = out.energyGain > 1e-9;
    const double t = world.time();
    const double slid = (world.circles()[0].position - start).dot(down);
    out.sinks = !(std::abs(slid / (0.5 * kGravity * std::sin(theta) * t * t) - 1.0) <= 0.01); // froze, or slid wrong
    return out;
}

Outcome vProbe(Method method, double halfAngleDegrees) {
    constexpr double r = 0.25, length = 5.0, bounciness = 0.3;
    const double a = halfAngleDegrees * std::acos(-1.0) / 180.0;
    World world = makeWorld(method, kGravity);
    for (const double side : {-1.0, 1.0}) {
        rube::SegmentDef line;
        line.b = {side * length * std::sin(a), length * std::cos(a)};
        line.material = {bounciness, 0.0};
        world.addSegment(line);
    }
    const double rest = r / std::sin(a), y = rest + 0.1;
    addBall(world, {0.1 * (y * std::sin(a) - r) / std::cos(a), y}, {}, r, 1.0, bounciness);
    for (int step = 0; step < static_cast<int>(std::lround(5.0 / kTimeStep)); ++step) world.step();
    const Circle& c = world.circles()[0];
    const double across = c.position.x * std::cos(a), up = c.position.y * std::sin(a);
    Outcome out;
    out.eventCap = world.stats().capsHit > 0;
    out.sinks = !(std::abs(std::abs(up + across) - r) < 1e-9 && std::abs(std::abs(up - across) - r) < 1e-9 &&
                  c.velocity.length() < 1e-9);
    return out;
}

Outcome capBounceProbe(Method method, double speed) {
    constexpr double r = 0.25;
    World world = makeWorld(method, 0.0);
    rube::SegmentDef line; // a thin line from (-5, 0) to the origin: its cap at the origin is struck
    line.a = {-5.0, 0.0};
    line.b = {0.0, 0.0};
    line.material = {1.0, 0.0};
    world.addSegment(line);
    // Coming from the right along -x with an impact parameter of r / 2 above the cap, 3.5 steps out.
    const Vec2 start{std::sqrt(0.75) * r + speed * kTimeStep * 3.5, 0.5 * r};
    addBall(world, start, {-speed, 0.0}, r, 1.0, 1.0);
    // The exact reflection: at impact the centre is at (sqrt(r^2 - (r/2)^2), r/2) from the cap, the
    // normal n from the cap to it, v' = v - 2 (v . n) n (C = 1, lecture 3).
    const Vec2 n = Vec2{std::sqrt(r * r - 0.25 * r * r), 0.5 * r}.normalized();
    const Vec2 v{-speed, 0.0};
    const Vec2 exact = v - n * (2.0 * v.dot(n));
    Outcome out;
    for (int step = 0; step < 8; ++step) world.step();
    const Vec2 after = world.circles()[0].velocity;
    const double cosine = std::clamp(after.dot(exact) / (after.length() * exact.length()), -1.0, 1.0);
    out.directionError = std::acos(cosine) * 180.0 / std::acos(-1.0);
    out.misdirected = !(out.directionError <= 0.5);
    return out;
}

} // namespace bench::failures
