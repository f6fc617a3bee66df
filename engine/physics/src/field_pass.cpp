// The fields' pass (field_pass.hpp): air drag, wind, magnets and thrusters as velocity changes around the
// method's step; also the public helpers of rube/physics/fields.hpp it uses (submergedArea, magnetForce).
#include "field_pass.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rube {

namespace {

// Linear drag on top of gravity, dv/dt = g - k v, has the exact solution (v_t = g / k, a = e^{-k dt})
//   v(dt) = v_t + (v - v_t) a,   x(dt) - x = v_t dt + (v - v_t) (1 - a) / k.
// The method moves a body at its velocity u plus gravity, x += u dt + g dt^2 / 2, and adds g dt. As for
// a thruster the change is split around that move: before it, u = v_t + phi (v - v_t) - g dt / 2 with
// phi = (1 - a) / (k dt), so the move lands exactly on x(dt); after it (linearDragAfterMove) the
// velocity w = u + g dt is mapped onto v(dt). Both position and velocity are then exact at every step,
// and the terminal speed is g / k to round-off. (1 - a) is -expm1(-k dt), exact for small k dt.
//
// phi = (1 - e^{-k dt}) / (k dt): the share of v - v_t the move carries.
double linearDragShare(double k, double dt) { return -std::expm1(-k * dt) / (k * dt); }

// e^{-k dt} / phi: how the velocity after the move is scaled onto v(dt). Only the second half of the
// step needs e^{-k dt} itself, so the first half computes no exponential it would throw away.
double linearDragAfterScale(double k, double dt) { return std::exp(-k * dt) / linearDragShare(k, dt); }

Vec2 linearDragKick(Vec2 v, Vec2 gravity, double k, double dt) {
    const Vec2 terminal = gravity / k;
    const double phi = linearDragShare(k, dt);
    return terminal + (v - terminal) * phi - gravity * (0.5 * dt) - v;
}

// Quadratic drag has no closed form with gravity in 2-D; v <- v / (1 + k |v| dt) is the
// implicit Euler step of dv/dt = -k |v| v, stable at any speed (it never reverses v).
Vec2 quadraticDragKick(Vec2 v, double k, double dt) { return v / (1.0 + k * v.length() * dt) - v; }

// Wind: linear drag relative to the moving air, dv/dt = k (u - v), exact: v(dt) = u + (v - u) e^{-k dt}.
Vec2 windKick(Vec2 v, Vec2 air, double k, double dt) { return (v - air) * std::expm1(-k * dt); }

// The part of [start, end) that lies within [t0, t1): how long a thruster burns during the step.
double overlap(double start, double end, double t0, double t1) {
    return std::max(0.0, std::min(end, t1) - std::max(start, t0));
}

} // namespace

Vec2 implicitFloatKick(Vec2 velocity, Vec2 up, double kick, double stiffness, double k, double dt, double ownGravity) {
    const double rise = velocity.dot(up);
    const double after = (rise + kick) / (1.0 + stiffness);
    const Vec2 end = (velocity + up * (after - rise)) * std::exp(-k * dt);
    return end - velocity + up * ownGravity;
}

namespace {

// Buoyancy and water drag on one circle in one pool, as a change of velocity over dt.
Vec2 waterKick(const Circle& c, const Water& water, Vec2 gravity, double dt) {
    if (c.position.x < water.min.x || c.position.x > water.max.x || c.position.y - c.radius > water.max.y ||
        c.position.y + c.radius < water.min.y)
        return {};
    const double height = c.position.y - water.max.y; // the centre above the surface
    const double area = submergedArea(c.radius, height);
    if (area <= 0.0) return {};
    const double fullArea = std::numbers::pi * c.radius * c.radius;
    // Drag, exact as for the wind: dv/dt = -k v with k = 2r drag (A / pi r^2) / m.
    const double k = 2.0 * c.radius * water.drag * (area / fullArea) * c.inverseMass;
    // Buoyancy is a spring along the vertical: rising by dy uncovers a chord of width w at the surface,
    // dA = -w dy, so its stiffness per unit mass is kappa = |g| rho w / m and its period 2 pi / sqrt(kappa).
    // Kicked at the step's start and then moved (semi-implicit Euler), a spring stiffer than the step
    // can follow, dt^2 kappa > 4, gains energy every step: a 10 g ball of radius 0.1 m set on water of
    // 1000 kg/m^2 rose 6.7 km in 20 s. Past dt^2 kappa = 1 the spring is taken implicitly instead, the
    // upward speed after the step being v1 = (v0 + (b - |g|) dt) / (1 + dt^2 kappa) with b the buoyant
    // acceleration now (implicit Euler on the linearised spring: stable at any stiffness), and the drag
    // then slows that velocity, not the one the step began with (summed, the two would both undo v0).
    // Below it, as in every shipped scene and level, the kicks are as before.
    const double g = gravity.length();
    if (g > 0.0 && std::abs(height) < c.radius) {
        // Along up = -g / |g|, the surface (y = const) is crossed at up.y of the speed.
        const Vec2 up = gravity * (-1.0 / g);
        const double chord = 2.0 * std::sqrt(c.radius * c.radius - height * height);
        const double stiffness = dt * dt * g * water.density * chord * std::abs(up.y) * c.inverseMass;
        if (stiffness > 1.0) {
            const double lift = g * water.density * area * c.inverseMass;
            return implicitFloatKick(c.velocity, up, (lift - g) * dt, stiffness, k, dt, g * dt);
        }
    }
    // Archimedes: the displaced water's weight, rho A g, pushes against gravity; its line of action
    // passes through the centre of a circle, so it turns nothing.
    const Vec2 buoyancy = gravity * (-water.density * area * c.inverseMass * dt);
    return buoyancy + c.velocity * std::expm1(-k * dt);
}

} // namespace

double submergedArea(double r, double height) {
    if (height >= r) return 0.0;
    if (height <= -r) return std::numbers::pi * r * r;
    // The circular segment cut off below a chord at signed distance h from the centre (h > 0: the
    // centre is above the surface): A = r^2 acos(h/r) - h sqrt(r^2 - h^2), pi r^2 / 2 at h = 0.
    return r * r * std::acos(height / r) - height * std::sqrt(r * r - height * height);
}

Vec2 magnetForce(const Magnet& magnet, Vec2 position) {
    const Vec2 d = magnet.position - position;
    const double distance = d.length();
    if (!magnet.on || distance >= magnet.reach || distance == 0.0) return {};
    // F = strength / d^2 towards the magnet, held at its value at the radius inside it.
    const double clamped = std::max(distance, magnet.radius);
    return d * (magnet.strength / (clamped * clamped * distance));
}

Vec2 magnetKick(std::span<const Magnet> magnets, const Circle& c, double dt) {
    Vec2 kick;
    if (!c.magnetic || c.motion != Motion::dynamic) return kick;
    for (const Magnet& magnet : magnets) kick += magnetForce(magnet, c.position) * (c.inverseMass * dt);
    return kick;
}

void applyFields(std::span<Circle> circles, const Fields& fields, std::span<const int> thrusterSlots,
                 const AirDrag& airDrag, Vec2 gravity, double time, double dt) {
    for (Circle& c : circles) {
        if (c.motion != Motion::dynamic || c.inverseMass == 0.0) continue;
        const double width = 2.0 * c.radius;
        Vec2 kick;
        // Linear drag's split carries gravity's share (see linearDragKick): a sleeper, held against
        // gravity and at rest, gets none, or the kick would wake it every step.
        if (airDrag.linear > 0.0 && !c.sleep.asleep)
            kick += linearDragKick(c.velocity, gravity, airDrag.linearRate(c.radius, c.inverseMass), dt);
        if (airDrag.quadratic > 0.0)
            kick += quadraticDragKick(c.velocity, airDrag.quadraticRate(c.radius, c.inverseMass), dt);
        for (const Wind& wind : fields.winds)
            if (wind.on && wind.contains(c.position))
                kick += windKick(c.velocity, wind.airVelocity(), width * wind.drag * c.inverseMass, dt);
        if (c.magnetic) kick += magnetKick(fields.magnets, c, dt);
        for (const Water& water : fields.waters) kick += waterKick(c, water, gravity, dt);
        c.velocity += kick;
    }
    kickThrusters(circles, fields.thrusters, thrusterSlots, time, dt, BurnShare::beforeMove);
}

void linearDragAfterMove(std::span<Circle> circles, const AirDrag& airDrag, Vec2 gravity, double dt) {
    for (Circle& c : circles) {
        if (c.motion != Motion::dynamic || c.inverseMass == 0.0 || c.sleep.asleep) continue;
        const double k = airDrag.linearRate(c.radius, c.inverseMass);
        const Vec2 terminal = gravity / k;
        // v(dt) = v_t + (w - v_t - g dt / 2) e^{-k dt} / phi: undoes the share the move carried (see linearDragKick).
        c.velocity = terminal + (c.velocity - terminal - gravity * (0.5 * dt)) * linearDragAfterScale(k, dt);
    }
}

void kickThrusters(std::span<Circle> circles, const std::vector<Thruster>& thrusters, std::span<const int> slots,
                   double time, double dt, BurnShare share) {
    const double t1 = time + dt;
    for (std::size_t k = 0; k < thrusters.size() && k < slots.size(); ++k) {
        const Thruster& thruster = thrusters[k];
        const int slot = slots[k];
        if (slot < 0 || static_cast<std::size_t>(slot) >= circles.size()) continue;
        const double burning = overlap(thruster.start, thruster.end, time, t1);
        if (burning <= 0.0) continue;
        Circle& c = circles[static_cast<std::size_t>(slot)];
        // A constant force a = F / m burning over [s, e] within the step moves a body by a tau (t1 - c) and
        // changes its velocity by a tau (tau = e - s, c = (s + e) / 2, lecture 3: impulse = change of
        // momentum). Kicking a tau (t1 - c) / dt before the method moves it at constant velocity and the
        // rest after makes both exact: x = F t^2 / (2 m) with no error of order dt (velocity Verlet's
        // half kicks for a whole step, where c = t0 + dt / 2).
        const double s = std::max(thruster.start, time), centre = s + 0.5 * burning;
        const double before = burning * (t1 - centre) / dt;
        const double seconds = share == BurnShare::beforeMove ? before : burning - before;
        c.velocity += thruster.force * (c.inverseMass * seconds);
    }
}

} // namespace rube
