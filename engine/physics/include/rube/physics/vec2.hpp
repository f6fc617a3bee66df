#pragma once
/// Vec2: the two-dimensional vector every quantity in the physics is made of.
///
/// A value type of two doubles. Everything is inline and constexpr where the
/// standard library allows, so the compiler sees through it in hot loops.

#include <cmath>

namespace rube {

/// A 2-D vector in world units (metres, metres per second, ...); y points up.
struct Vec2 {
    double x = 0.0;
    double y = 0.0;

    constexpr Vec2() = default;
    constexpr Vec2(double x_, double y_) : x(x_), y(y_) {}

    /// The unit vector at `radians` from the +x axis, counter-clockwise.
    static Vec2 fromAngle(double radians) { return {std::cos(radians), std::sin(radians)}; }

    constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
    constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
    constexpr Vec2 operator-() const { return {-x, -y}; }
    constexpr Vec2 operator*(double s) const { return {x * s, y * s}; }
    constexpr Vec2 operator/(double s) const { return {x / s, y / s}; }
    constexpr Vec2& operator+=(Vec2 o) {
        x += o.x;
        y += o.y;
        return *this;
    }
    constexpr Vec2& operator-=(Vec2 o) {
        x -= o.x;
        y -= o.y;
        return *this;
    }
    constexpr Vec2& operator*=(double s) {
        x *= s;
        y *= s;
        return *this;
    }
    constexpr Vec2& operator/=(double s) {
        x /= s;
        y /= s;
        return *this;
    }
    /// Exact, bitwise-meaningful equality; use approxEqual for computed values.
    constexpr bool operator==(const Vec2&) const = default;

    /// a . b = |a| |b| cos(alpha) (lecture 5, dot product recap).
    constexpr double dot(Vec2 o) const { return x * o.x + y * o.y; }
    /// The 2-D cross product a x b = ax by - ay bx: the z of the 3-D cross, |a||b| sin(alpha).
    constexpr double cross(Vec2 o) const { return x * o.y - y * o.x; }
    constexpr double lengthSquared() const { return dot(*this); }
    /// |v|, computed with hypot so that huge and tiny components neither overflow nor underflow.
    double length() const { return std::hypot(x, y); }

    /// v / |v|, or the zero vector when |v| is zero (a direction that does not exist stays zero).
    Vec2 normalized() const {
        const double len = length();
        return len > 0.0 ? Vec2{x / len, y / len} : Vec2{};
    }
    /// v rotated a quarter turn counter-clockwise, same length: (-y, x).
    constexpr Vec2 perpendicular() const { return {-y, x}; }
    /// The unit normal of a line along v: the left-hand perpendicular, normalized (zero for zero v).
    Vec2 normal() const { return perpendicular().normalized(); }

    /// v rotated counter-clockwise by `radians`.
    Vec2 rotated(double radians) const {
        const double c = std::cos(radians), s = std::sin(radians);
        return {x * c - y * s, x * s + y * c};
    }
    /// v rotated counter-clockwise by `radians` around `pivot`.
    Vec2 rotatedAround(Vec2 pivot, double radians) const { return pivot + (*this - pivot).rotated(radians); }
    /// The angle of v from the +x axis in (-pi, pi]; 0 for the zero vector.
    double angle() const { return std::atan2(y, x); }

    /// The scalar projection of v onto `onto`: v . onto / |onto| (0 when onto is zero).
    double scalarProjection(Vec2 onto) const {
        const double len = onto.length();
        return len > 0.0 ? dot(onto) / len : 0.0;
    }
    /// The vector projection of v onto `onto` (zero when onto is zero).
    Vec2 projectedOnto(Vec2 onto) const {
        const double l2 = onto.lengthSquared();
        return l2 > 0.0 ? onto * (dot(onto) / l2) : Vec2{};
    }

    /// Reflection off a surface with unit normal n and bounciness C:
    /// v' = v - (1 + C)(v . n) n, so the normal part becomes -C times itself
    /// and the tangential part is kept (lecture 3: newVelocity = -C * oldVelocity along the normal).
    constexpr Vec2 reflected(Vec2 unitNormal, double bounciness = 1.0) const {
        return *this - unitNormal * ((1.0 + bounciness) * dot(unitNormal));
    }

    /// Distance between two points.
    double distance(Vec2 o) const { return (*this - o).length(); }
};

constexpr Vec2 operator*(double s, Vec2 v) { return v * s; }

/// a + (b - a) t: t = 0 gives a, t = 1 gives b.
constexpr Vec2 lerp(Vec2 a, Vec2 b, double t) { return a + (b - a) * t; }

/// True when a and b differ by at most `tolerance` in each component,
/// measured relative to their size when they are large (|a - b| <= tol * max(1, |a|, |b|)).
inline bool approxEqual(Vec2 a, Vec2 b, double tolerance = 1e-9) {
    const double scale = std::fmax(
        1.0, std::fmax(std::fmax(std::fabs(a.x), std::fabs(a.y)), std::fmax(std::fabs(b.x), std::fabs(b.y))));
    return std::fabs(a.x - b.x) <= tolerance * scale && std::fabs(a.y - b.y) <= tolerance * scale;
}

/// True when neither component is NaN or infinite.
inline bool isFinite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

} // namespace rube
