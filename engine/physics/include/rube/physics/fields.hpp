#pragma once
/// Fields: forces beyond gravity that act on dynamic circles through the air rather than by contact
/// (air drag, wind from a fan, magnets that pull steel, thrusters). A world with none of them pays
/// nothing: `World::step` skips the whole pass when no field is set.
///
/// Every field is applied as a change of velocity at the start of the step (an impulse F dt, so
/// Delta v = F dt / m, lecture 3), before the time-step method moves the bodies. This splits the
/// field from the collision handling, so every method supports fields the same way; the price is
/// that the exact method stays exact only for gravity alone: where a field acts, its motion is
/// first-order in dt (except linear drag and a thruster, whose changes are split around the move so
/// that the body moves exactly: x(t) of dv/dt = g - k v / m, and x = F t^2 / (2m)).

#include "rube/physics/handles.hpp"
#include "rube/physics/vec2.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace rube {

/// Drag of still air on every dynamic circle, in proportion to its width 2r (the 2-D cross-section):
/// F = -2r (linear v + quadratic |v| v). Heavier balls of the same size are slowed less, as in air.
struct AirDrag {
    double linear = 0.0; ///< N s/m per metre of width: viscous (slow, small bodies); terminal speed m g / (2r linear)
    double quadratic = 0.0; ///< N s^2/m^2 per metre of width: pressure drag (1/2 rho C_d; about 0.28 for a ball in air)
    /// True when either coefficient is set.
    bool active() const { return linear > 0.0 || quadratic > 0.0; }
    /// k of a ball of `radius` and 1/m `inverseMass` in dv/dt = -k v: 2r linear / m, 1/s.
    double linearRate(double radius, double inverseMass) const { return 2.0 * radius * linear * inverseMass; }
    /// k of the same ball in dv/dt = -k |v| v: 2r quadratic / m, 1/m.
    double quadraticRate(double radius, double inverseMass) const { return 2.0 * radius * quadratic * inverseMass; }
};

/// A fan: a column of air blowing from `origin` along `direction`, `length` long and `width` wide.
/// A circle whose centre is inside feels linear drag relative to the moving air,
/// F = 2r drag (u - v) with u = speed direction, so it is carried towards the air's speed.
struct Wind {
    Vec2 origin;              ///< the middle of the fan's face, m
    Vec2 direction{1.0, 0.0}; ///< unit vector: the way the air blows
    double length = 5.0;      ///< how far the column reaches from the face, m
    double width = 1.0;       ///< the column's width across the direction, m
    double speed = 5.0;       ///< air speed, m/s
    double drag = 1.0;        ///< N s/m per metre of width
    bool on = true;           ///< a switch may turn a fan on or off
    /// True when `p` lies in the air column.
    bool contains(Vec2 p) const {
        const Vec2 local = p - origin;
        const double along = local.dot(direction);
        return along >= 0.0 && along <= length && std::abs(direction.cross(local)) <= 0.5 * width;
    }
    /// u: the velocity of the moving air.
    Vec2 airVelocity() const { return direction * speed; }
};

/// A magnet: pulls every magnetic circle (steel) towards its centre with F = strength / d^2.
/// Inside `radius` the pull is held at its value at the radius, so it stays finite at the centre.
struct Magnet {
    Vec2 position;                                          ///< m
    double strength = 1.0;                                  ///< N m^2: the pull at 1 m
    double radius = 0.1;                                    ///< m: the pull does not grow closer than this
    double reach = std::numeric_limits<double>::infinity(); ///< m: no pull at or past this distance
    bool on = true;                                         ///< a switch may turn a magnet on or off
};

/// A thruster (or rocket) fixed to one circle: a constant force from `start` until `end`.
struct Thruster {
    CircleId circle;                                      ///< the dynamic circle it pushes (none while it is disabled)
    Vec2 force;                                           ///< N, in world axes
    double start = 0.0;                                   ///< s, world time it lights
    double end = std::numeric_limits<double>::infinity(); ///< s, world time it burns out
};

/// Water: a rectangular pool whose surface is its top edge. A circle in it is pushed up by the
/// weight of the water it displaces (Archimedes), F = rho A |g| with A the exactly submerged area
/// (a circular segment), and slowed by drag in proportion to how much of it is under water.
/// In 2-D a density is a mass per area: kg/m^2.
struct Water {
    Vec2 min;                ///< lower-left corner of the pool, m
    Vec2 max;                ///< upper-right corner; max.y is the surface, m
    double density = 1000.0; ///< rho, kg/m^2: a ball of half this density floats half under
    double drag = 1000.0;    ///< N s/m per metre of width, fully submerged: damps a floating 1 m ball in seconds
};

/// The area of a circle of radius `r` whose centre is `height` above a flat surface that lies
/// below the surface: A = r^2 acos(h/r) - h sqrt(r^2 - h^2), 0 above, pi r^2 fully under.
double submergedArea(double r, double height);

/// Every field of a world except its air drag (which is part of WorldDef).
struct Fields {
    std::vector<Wind> winds;
    std::vector<Magnet> magnets;
    std::vector<Thruster> thrusters;
    std::vector<Water> waters;
    /// True when no wind, magnet, thruster or water is set.
    bool empty() const { return winds.empty() && magnets.empty() && thrusters.empty() && waters.empty(); }
};

/// The magnet's pull on a magnetic circle at `position`, N (zero past its reach or when switched off).
Vec2 magnetForce(const Magnet& magnet, Vec2 position);

} // namespace rube
