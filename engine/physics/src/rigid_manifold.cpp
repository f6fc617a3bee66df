// Narrowphase for rigid bodies: contact manifolds between rounded polygons (boxes, capsules,
// circles, segments with rounded line caps).
#include "rigid_manifold.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rube {

namespace {

/// Cores closer than this count as touching: the faces are clipped rather than the corners rounded.
constexpr double kTouchingCores = 0.0005;
/// A face within this much of the best separation is preferred on shape A, so the reference face does
/// not flip between steps when two faces separate almost equally (Box2D's relative tolerance).
constexpr double kReferenceTolerance = 0.0005;
/// cos of 8 degrees: a closest-points direction further off the best face than this is a corner or a
/// cap touching first, and gets one point along that direction instead of a clipped face.
constexpr double kFaceAlignment = 0.99;
/// Cores crossing by more than this (m) overlap; less is rounding on two segments lying along one line.
constexpr double kCoreOverlap = 1e-9;
/// The id of the one point of two rounded ends (corner or cap) touching first: no face is involved.
constexpr std::uint32_t kRoundedId = 0xffffu;

/// Outward normal of an edge running d along a counter-clockwise polygon: d turned clockwise.
Vec2 outwardNormal(Vec2 d) { return Vec2{d.y, -d.x}.normalized(); }

RoundedPolygon twoVertex(Vec2 a, Vec2 b, double radius) {
    RoundedPolygon p;
    p.radius = radius;
    if ((b - a).lengthSquared() == 0.0) {
        p.vertices[0] = a;
        p.count = 1;
        return p;
    }
    p.vertices[0] = a;
    p.vertices[1] = b;
    p.normals[0] = outwardNormal(b - a);
    p.normals[1] = -p.normals[0];
    p.count = 2;
    return p;
}

Vec2 closestOnSegment(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 d = b - a;
    const double dd = d.lengthSquared();
    if (dd == 0.0) return a;
    return a + d * std::clamp((p - a).dot(d) / dd, 0.0, 1.0);
}

/// The deepest-separating face of `p1` against `p2`: max over faces i of min over vertices j of
/// n_i . (v2_j - v1_i) (the separating axis test; > 0 means the cores are apart along n_i).
double maxSeparation(const RoundedPolygon& p1, const RoundedPolygon& p2, int& edge) {
    double best = -std::numeric_limits<double>::infinity();
    edge = -1;
    for (int i = 0; i < p1.count; ++i) {
        double s = std::numeric_limits<double>::infinity();
        for (int j = 0; j < p2.count; ++j) s = std::min(s, p1.normals[i].dot(p2.vertices[j] - p1.vertices[i]));
        if (s > best) {
            best = s;
            edge = i;
        }
    }
    return best;
}

int edgeCount(const RoundedPolygon& p) { return p.count == 1 ? 1 : p.count == 2 ? 1 : p.count; }

/// The closest points of two disjoint cores: for disjoint convex polygons the nearest pair always has
/// a vertex of one of them, so vertex against edge both ways covers it.
double closestPoints(const RoundedPolygon& a, const RoundedPolygon& b, Vec2& pa, Vec2& pb) {
    double best = std::numeric_limits<double>::infinity();
    const auto scan = [&best](const RoundedPolygon& p, const RoundedPolygon& q, Vec2& onP, Vec2& onQ) {
        for (int i = 0; i < p.count; ++i)
            for (int e = 0; e < edgeCount(q); ++e) {
                const Vec2 q1 = q.vertices[e];
                const Vec2 q2 = q.vertices[q.count == 1 ? 0 : (e + 1) % q.count];
                const Vec2 c = closestOnSegment(p.vertices[i], q1, q2);
                const double d = (c - p.vertices[i]).lengthSquared();
                if (d < best) {
                    best = d;
                    onP = p.vertices[i];
                    onQ = c;
                }
            }
    };
    scan(a, b, pa, pb);
    Vec2 qa, qb;
    const double fromA = best;
    scan(b, a, qb, qa);
    if (best < fromA) {
        pa = qa;
        pb = qb;
    }
    return std::sqrt(best);
}

} // namespace

RoundedPolygon makeRoundedPolygon(const RigidBody& body, Vec2 position, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    const auto toWorld = [&](double x, double y) { return position + Vec2{c * x - s * y, s * x + c * y}; };
    const double hx = body.halfExtents.x, hy = body.halfExtents.y;
    if (body.shape == BodyShape::capsule) return twoVertex(toWorld(-hx, 0.0), toWorld(hx, 0.0), hy);
    RoundedPolygon p;
    p.count = 4;
    p.vertices[0] = toWorld(-hx, -hy);
    p.vertices[1] = toWorld(hx, -hy);
    p.vertices[2] = toWorld(hx, hy);
    p.vertices[3] = toWorld(-hx, hy);
    for (int i = 0; i < 4; ++i) p.normals[i] = outwardNormal(p.vertices[(i + 1) % 4] - p.vertices[i]);
    return p;
}

RoundedPolygon makeRoundedPolygon(const Circle& circle) {
    RoundedPolygon p;
    p.vertices[0] = circle.position;
    p.count = 1;
    p.radius = circle.radius;
    return p;
}

RoundedPolygon makeRoundedPolygon(const Segment& segment) { return twoVertex(segment.a, segment.b, segment.radius); }

double coreDistance(const RoundedPolygon& a, const RoundedPolygon& b, Vec2& pa, Vec2& pb) {
    // Two convex polygons are apart exactly when one of their edge normals separates them (a segment's
    // two normals are its only ones); vertex against edge then finds the closest pair.
    int edge = -1;
    const double separation = std::max(maxSeparation(a, b, edge), maxSeparation(b, a, edge));
    if (separation < -kCoreOverlap) return -1.0;
    return closestPoints(a, b, pa, pb);
}

Manifold collideRoundedPolygons(const RoundedPolygon& a, const RoundedPolygon& b, double speculative) {
    Manifold m;
    const double radius = a.radius + b.radius;
    int edgeA = -1, edgeB = -1;
    const double sepA = a.count >= 2 ? maxSeparation(a, b, edgeA) : -std::numeric_limits<double>::infinity();
    const double sepB = b.count >= 2 ? maxSeparation(b, a, edgeB) : -std::numeric_limits<double>::infinity();
    const double separation = std::max(sepA, sepB);
    // The separating-axis gap never exceeds the true distance: beyond the reach, nothing can touch.
    if (separation > speculative + radius) return m;

    const bool flip = edgeB >= 0 && (edgeA < 0 || sepB > sepA + kReferenceTolerance);
    const RoundedPolygon& ref = flip ? b : a;
    const RoundedPolygon& inc = flip ? a : b;
    const int edge = flip ? edgeB : edgeA;
    const Vec2 faceNormal = edge >= 0 ? (flip ? -ref.normals[edge] : ref.normals[edge]) : Vec2{};

    if (edge < 0 || separation > kTouchingCores) {
        // The cores are apart: a rounded corner or cap may be what touches first.
        Vec2 pa, pb;
        const double d = closestPoints(a, b, pa, pb);
        if (d - radius > speculative) return m;
        if (d > 0.0) {
            const Vec2 n = (pb - pa) / d;
            if (edge < 0 || n.dot(faceNormal) < kFaceAlignment) {
                m.normal = n;
                m.points[0] = {(pa + n * a.radius + pb - n * b.radius) * 0.5, d - radius, kRoundedId};
                m.count = 1;
                return m;
            }
        } else if (edge < 0) {
            return m; // two coincident points: no direction to push along
        }
    }

    // Clip the incident edge (the one facing the reference face most) to the reference face's sides.
    const Vec2 n = ref.normals[edge];
    const Vec2 v11 = ref.vertices[edge];
    const Vec2 v12 = ref.vertices[(edge + 1) % ref.count];
    Vec2 w1 = inc.vertices[0], w2 = inc.vertices[0];
    int best = 0;
    if (inc.count >= 2) {
        for (int j = 1; j < inc.count; ++j)
            if (inc.normals[j].dot(n) < inc.normals[best].dot(n)) best = j;
        w1 = inc.vertices[best];
        w2 = inc.vertices[(best + 1) % inc.count];
    }
    const double length = (v12 - v11).length();
    const Vec2 t = (v12 - v11) / length;
    double a1 = (w1 - v11).dot(t), a2 = (w2 - v11).dot(t);
    if (!((a1 < 0.0 && a2 < 0.0) || (a1 > length && a2 > length))) {
        const Vec2 o1 = w1, o2 = w2;
        if (a1 < 0.0 && a2 > a1) w1 = lerp(o1, o2, -a1 / (a2 - a1));
        if (a1 > length && a2 < a1) w1 = lerp(o1, o2, (a1 - length) / (a1 - a2));
        if (a2 < 0.0 && a1 > a2) w2 = lerp(o2, o1, -a2 / (a1 - a2));
        if (a2 > length && a1 < a2) w2 = lerp(o2, o1, (a2 - length) / (a2 - a1));
    } else if (std::abs(a2 - (a2 < 0.0 ? 0.0 : length)) < std::abs(a1 - (a1 < 0.0 ? 0.0 : length))) {
        w1 = w2; // wholly beside the face: keep the end nearest to it
    } else {
        w2 = w1;
    }
    const int candidates = (w1 - w2).lengthSquared() > 0.0 ? 2 : 1;
    const Vec2 clipped[2] = {w1, w2};
    m.normal = flip ? -n : n;
    for (int k = 0; k < candidates; ++k) {
        const double core = n.dot(clipped[k] - v11);
        if (core - radius > speculative) continue;
        // Midway between the two surfaces: the reference surface is ref.radius out along n, the
        // incident one inc.radius back from the clipped core point.
        // Which shape holds the reference face, which face, which incident edge and which of its ends.
        const auto id = static_cast<std::uint32_t>((flip ? 1u : 0u) << 12 | static_cast<unsigned>(edge) << 8 |
                                                   static_cast<unsigned>(best) << 4 | static_cast<unsigned>(k));
        m.points[m.count++] = {clipped[k] + n * (0.5 * (ref.radius - inc.radius - core)), core - radius, id};
    }
    return m;
}

} // namespace rube
