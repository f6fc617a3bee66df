// The rigid bodies' continuous pass: a box or capsule that moved or turned further in a step than
// its own thickness is swept against the segments (static lines, moving and turning ones), and one
// found through or deep inside a segment at the step's end is put back at its time of impact and
// bounced there, as the circles' sweep does for bullets (solver_sweep.cpp).
#include "rigid_stage.hpp"
#include "rigid_sweep.hpp"

#include <algorithm>
#include <cmath>

namespace rube {

namespace {

/// The sweep stops this close (m): the surfaces are left just apart at the time of impact.
constexpr double kSweepTarget = 1e-3;
/// Conservative advancement converges in a few steps on a straight approach; a body spinning
/// against a segment may take more. Past this many the last safe time is taken as the impact's.
constexpr int kMaxAdvances = 64;
/// A body ending this far through a segment, as a fraction of its half thickness, has passed the
/// solver's contacts: its centre would cross at 1, and resting contact overlaps far less.
constexpr double kThroughPerHalfThickness = 0.5;
/// Impulses at the time of impact: the point approaching fastest is bounced, then the next, at most this often.
constexpr int kMaxBounceIterations = 8;

/// The farthest core vertex from `centre`.
double coreExtent(const RoundedPolygon& p, Vec2 centre) {
    double e = 0.0;
    for (int i = 0; i < p.count; ++i) e = std::max(e, (p.vertices[i] - centre).length());
    return e;
}

/// Everywhere the shape can be over the step: its centre's path grown by its extent and radius.
RigidStage::Box sweptBounds(const SweptShape& s) {
    const Vec2 end = s.centre + s.move;
    const double r = s.extent + s.start.radius;
    return {{std::min(s.centre.x, end.x) - r, std::min(s.centre.y, end.y) - r},
            {std::max(s.centre.x, end.x) + r, std::max(s.centre.y, end.y) + r}};
}

SweptShape sweptSegment(const Segment& seg, double dt) {
    SweptShape s;
    s.start = makeRoundedPolygon(seg);
    s.centre = lerp(seg.a, seg.b, seg.pivotAlong);
    s.move = seg.motion() == Motion::kinematic ? seg.velocity * dt : Vec2{};
    s.turn = seg.motion() == Motion::kinematic ? seg.angularVelocity * dt : 0.0;
    s.extent = coreExtent(s.start, s.centre);
    return s;
}

/// How far the body at the end of the step is behind the surface it met at the time of impact: the
/// plane through the segment's core point `contact` (carried to the step's end) with unit normal n
/// towards the body. A body that met a segment and ends behind it went through it (or, having met
/// it, slid round its end: then bouncing it where it met the segment is no worse).
double throughDepth(const RoundedPolygon& body, double radii, Vec2 n, Vec2 contact) {
    double lowest = n.dot(body.vertices[0] - contact);
    for (int i = 1; i < body.count; ++i) lowest = std::min(lowest, n.dot(body.vertices[i] - contact));
    return radii - lowest;
}

} // namespace

RoundedPolygon SweptShape::at(double t) const {
    RoundedPolygon p = start;
    const double angle = turn * t;
    const Vec2 q{std::cos(angle), std::sin(angle)};
    const Vec2 shift = move * t;
    for (int i = 0; i < p.count; ++i) {
        p.vertices[i] = centre + shift + rotate(q, start.vertices[i] - centre);
        if (p.count >= 2) p.normals[i] = rotate(q, start.normals[i]);
    }
    return p;
}

double sweptTimeOfImpact(const SweptShape& a, const SweptShape& b, double target) {
    const double radii = a.start.radius + b.start.radius;
    const double turning = std::abs(a.turn) * a.extent + std::abs(b.turn) * b.extent;
    double t = 0.0;
    for (int k = 0; k < kMaxAdvances; ++k) {
        const RoundedPolygon pa = a.at(t), pb = b.at(t);
        Vec2 ca, cb;
        const double d = coreDistance(pa, pb, ca, cb);
        if (d <= 0.0) return t; // cores overlapping or touching: already met
        const double gap = d - radii;
        if (gap <= target) return t;
        // n from A towards B: A closes on B at most at n . (moveA - moveB) plus both turns' reach.
        const Vec2 n = (cb - ca) / d;
        const double closing = n.dot(a.move - b.move) + turning;
        if (closing <= 0.0) return -1.0;
        // Advance to where the gap could first be half the target: a straight approach lands there.
        t += (gap - 0.5 * target) / closing;
        if (t > 1.0) return -1.0;
    }
    return t;
}

int RigidStage::sweep(StepContext& ctx, double dt) {
    // Without segments there is nothing to pass through (the bodies' own pairs are the solver's).
    if (ctx.segments.empty()) return 0;
    // Which bodies moved or turned further than their half thickness: each body's own slot, so any
    // split among the workers gives the same marks. A body that moved less cannot have passed a
    // line: the step's speculative contacts were enough.
    const std::size_t n = ctx.bodies.size();
    fast_.resize(n);
    forShares(pool_, n, kBodyChunk, [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) {
            const RigidState& s = states_[i];
            // shapes_[i] is the body at its start pose (prepare), as the sweep starts from.
            fast_[i] = s.inverseMass != 0.0 &&
                       !(s.displacement.length() + std::abs(s.turn) * coreExtent(shapes_[i], startPosition_[i]) <=
                         thickness_[i]);
        }
    });
    int impacts = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!fast_[i]) continue;
        RigidBody& body = ctx.bodies[i];
        const RigidState& s = states_[i];
        const double thick = thickness_[i];
        SweptShape shape;
        shape.centre = startPosition_[i];
        shape.start = shapes_[i];
        shape.move = s.displacement;
        shape.turn = s.turn;
        shape.extent = coreExtent(shape.start, shape.centre);
        const Box bounds = sweptBounds(shape);
        const RoundedPolygon end = makeRoundedPolygon(body, body.position, body.angle);
        double first = 2.0;
        int hit = -1;
        for (std::size_t k = 0; k < ctx.segments.size(); ++k) {
            const SweptShape seg = sweptSegment(ctx.segments[k], dt);
            if (!bounds.overlaps(sweptBounds(seg))) continue;
            const double t = sweptTimeOfImpact(shape, seg, kSweepTarget);
            if (t < 0.0 || t >= first) continue;
            // Met on the way: did the solver keep it on its side? Judge by where it ends against the
            // surface it met (its normal at the time of impact, carried with the segment).
            Vec2 pa, pb;
            const RoundedPolygon atBody = shape.at(t), atSeg = seg.at(t);
            const double d = coreDistance(atBody, atSeg, pa, pb);
            if (d <= 0.0) continue; // started inside: the solver's contacts push it out
            const Vec2 n = (pa - pb) / d;
            const Vec2 contact = pb + seg.move * (1.0 - t);
            if (throughDepth(end, atBody.radius + atSeg.radius, n, contact) <= kThroughPerHalfThickness * thick)
                continue;
            first = t;
            hit = static_cast<int>(k);
        }
        if (hit < 0) continue;
        if (resolveSweptHit(ctx, i, hit, shape, first, dt)) ++impacts;
    }
    ctx.stats.impacts += impacts;
    return impacts;
}

bool RigidStage::resolveSweptHit(StepContext& ctx, std::size_t i, int segment, const SweptShape& shape, double t,
                                 double dt) {
    RigidBody& body = ctx.bodies[i];
    const Segment& seg = ctx.segments[static_cast<std::size_t>(segment)];
    const SweptShape swept = sweptSegment(seg, dt);
    // Back to the time of impact, then carried along with the segment for the rest of the step (as
    // the circles' sweep rides a bullet along with what it hit): a moving line would otherwise run on
    // into the body it stopped.
    const Vec2 carry = swept.move * (1.0 - t);
    body.position = shape.centre + shape.move * t + carry;
    body.angle = startAngle_[i] + shape.turn * t;
    const RoundedPolygon atBody = makeRoundedPolygon(body, body.position, body.angle);
    SweptShape carried = swept;
    carried.move = swept.move * t + carry; // where the segment is at the step's end
    carried.turn = swept.turn * t;         // turned as far as at the time of impact
    const RoundedPolygon atSeg = carried.at(1.0);
    Manifold m = collideRoundedPolygons(atBody, atSeg, 4.0 * kSweepTarget);
    if (m.count == 0) {
        Vec2 pa, pb;
        const double d = coreDistance(atBody, atSeg, pa, pb);
        if (d <= 0.0) return false;
        m.normal = (pb - pa) / d;
        m.points[0].point = (pa + pb) * 0.5;
        m.count = 1;
    }
    const Vec2 n = -m.normal; // from the segment towards the body
    // The segment's surface velocity where it is met: v + omega x r about its pivot where the body
    // was put, at the step's end (the segment itself is still where the step began: p - move there).
    const auto surface = [&](Vec2 p) { return seg.velocityAt(p - swept.move); };
    const double bounciness = body.material.bounciness * seg.material.bounciness;
    const double invM = body.inverseMass, invI = body.inverseInertia;
    double approach = 0.0;
    int struck = 0;
    for (int iteration = 0; iteration < kMaxBounceIterations; ++iteration) {
        // The point approaching fastest gets v' = -C vn (lecture 3), an impulse j = -(1 + C) vn / K with
        // K = 1/m + (r x n)^2 / I; one point at a time, each such impulse loses (1 - C^2) vn^2 / 2K.
        int worst = -1;
        double worstVn = 0.0;
        for (int k = 0; k < m.count; ++k) {
            const Vec2 r = m.points[k].point - body.position;
            const double vn = n.dot(body.velocity + r.perpendicular() * body.angularVelocity -
                                    surface(m.points[k].point));
            if (vn < worstVn) {
                worstVn = vn;
                worst = k;
            }
        }
        if (worst < 0) break;
        if (iteration == 0) {
            approach = -worstVn;
            struck = worst;
        }
        const Vec2 r = m.points[worst].point - body.position;
        const double rn = r.cross(n);
        const double c = -worstVn > ctx.restingSpeed ? bounciness : 0.0;
        const double j = -(1.0 + c) * worstVn / (invM + invI * rn * rn);
        body.velocity += n * (j * invM);
        body.angularVelocity += invI * rn * j;
    }
    if (approach <= ctx.restingSpeed) {
        if (approach > 0.0) ++ctx.stats.restingContacts;
        return false;
    }
    Impact impact;
    impact.body = static_cast<int>(i);
    impact.otherKind = Other::segment;
    impact.other = segment;
    impact.time = ctx.time + t * dt;
    impact.pointOfImpact = m.points[struck].point;
    impact.normal = n;
    impact.approachSpeed = approach;
    ctx.impacts.push_back(impact);
    return true;
}

} // namespace rube
