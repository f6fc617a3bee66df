// The solver's continuous pass: swept circles against circles and capsules, clamped at the time of impact.
#include "solver_sweep.hpp"

#include "broadphase_grid.hpp"
#include "joint_stage.hpp"

#include <algorithm>
#include <cmath>

namespace rube {

namespace {

/// Left between the surfaces at a clamped time of impact, so the next step starts just apart.
constexpr double kClampGap = 1e-4;

/// The box around a straight motion from p to q of a disc of radius r.
BoundingBox sweptBox(Vec2 p, Vec2 q, double r) {
    return BoundingBox{{std::min(p.x, q.x) - r, std::min(p.y, q.y) - r},
                       {std::max(p.x, q.x) + r, std::max(p.y, q.y) + r}};
}

/// The closest point of segment ab to p, by clamped scalar projection (lecture 5).
Vec2 closestOnSegment(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 ab = b - a;
    const double l2 = ab.lengthSquared();
    return l2 > 0.0 ? a + ab * std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : a;
}

} // namespace

double sweepPointCircle(Vec2 q0, Vec2 d, Vec2 c, double reach) {
    // |m + t d|^2 = R^2 with m = q0 - c: a t^2 + 2 b t + cc = 0, a = d.d, b = m.d, cc = m.m - R^2.
    const Vec2 m = q0 - c;
    const double cc = m.dot(m) - reach * reach;
    const double b = m.dot(d);
    if (cc < 0.0 || b >= 0.0) return -1.0; // inside already, or not closing
    const double a = d.dot(d);
    const double disc = b * b - a * cc;
    if (disc < 0.0) return -1.0;
    // The smaller root (-b - sqrt(disc)) / a, written as cc / (-b + sqrt(disc)) to avoid cancellation.
    const double t = cc / (-b + std::sqrt(disc));
    return t <= 1.0 ? t : -1.0;
}

double sweepPointCapsule(Vec2 q0, Vec2 d, Vec2 a, Vec2 b, double reach) {
    double best = -1.0;
    const auto keep = [&best](double t) {
        if (t >= 0.0 && (best < 0.0 || t < best)) best = t;
    };
    keep(sweepPointCircle(q0, d, a, reach));
    keep(sweepPointCircle(q0, d, b, reach));
    const Vec2 ab = b - a;
    const double l2 = ab.lengthSquared();
    if (l2 == 0.0) return best;
    // The face on q0's side: the signed distance h(t) = n . (q0 + t d - a) reaches the reach.
    const Vec2 n = ab.normal();
    const double h0 = n.dot(q0 - a);
    const double side = h0 >= 0.0 ? 1.0 : -1.0;
    const double closing = -side * n.dot(d);
    const double gap = side * h0 - reach;
    if (gap >= 0.0 && closing > 0.0 && gap <= closing) {
        const double t = gap / closing;
        // Only the part of the face between the caps counts; beyond it the caps above decide.
        const double u = (q0 + d * t - a).dot(ab) / l2;
        if (u >= 0.0 && u <= 1.0) keep(t);
    }
    return best;
}

ContinuousSweep::Hit ContinuousSweep::earliestHit(int i, const SweepInput& in, BroadphaseGrid& grid,
                                                  const StepContext& ctx, double dt) {
    std::span<const Circle> circles = ctx.circles;
    std::span<const Segment> segments = ctx.segments;
    std::span<const Vec2> start = in.start;
    const int circleCount = static_cast<int>(circles.size());
    const int segmentCount = static_cast<int>(segments.size());
    const Circle& ci = circles[i];
    const Vec2 p0 = start[i];
    const Vec2 move = ci.position - p0;
    const BoundingBox box = sweptBox(p0, ci.position, ci.radius);
    Hit hit;
    // Pairs are kept as contacts while their gap is below the sum of their margins, so a pair whose
    // relative motion stays within that sum cannot have closed a gap unseen; and a pair with a
    // contact was the solver's, whose speculative constraint kept the two apart.
    const auto needsSweep = [&](Vec2 relativeMove, int other) {
        const double margins = in.margins[i] + in.margins[other];
        if (relativeMove.lengthSquared() <= margins * margins) return false;
        if (other < circleCount && in.isDynamic[other] && other < i)
            return in.contacts.find(other, i, circleCount, segmentCount) == nullptr;
        return in.contacts.find(i, other, circleCount, segmentCount) == nullptr;
    };
    const auto trySegment = [&](int s) {
        const Segment& seg = segments[s];
        const Vec2 segMove = seg.motion() == Motion::kinematic ? seg.velocity * dt : Vec2{};
        BoundingBox sb = sweptBox(seg.a, seg.b, seg.radius);
        sb.min = {std::min(sb.min.x, sb.min.x + segMove.x), std::min(sb.min.y, sb.min.y + segMove.y)};
        sb.max = {std::max(sb.max.x, sb.max.x + segMove.x), std::max(sb.max.y, sb.max.y + segMove.y)};
        // In the segment's frame at the start of the step the circle moves by move - segMove.
        const Vec2 d = move - segMove;
        if (!box.overlaps(sb) || !needsSweep(d, circleCount + s)) return;
        const double t = sweepPointCapsule(p0, d, seg.a, seg.b, ci.radius + seg.radius);
        if (t >= 0.0 && t < hit.t) hit = {t, circleCount + s};
    };
    const auto tryCircle = [&](int j) {
        if (j == i || connectedCircles(in.connected, i, j)) return;
        const Circle& cj = circles[j];
        // Of two dynamic circles the one that moved further sweeps: clamping the slower one would
        // drag it back from where its contacts put it.
        const Vec2 moveJ = cj.position - start[j];
        if (cj.motion == Motion::dynamic &&
            (moveJ.lengthSquared() > move.lengthSquared() || (moveJ.lengthSquared() == move.lengthSquared() && j < i)))
            return;
        // Relative to j: q = p_i - p_j, moving by move - move_j.
        const Vec2 d = move - moveJ;
        if (!box.overlaps(sweptBox(start[j], cj.position, cj.radius)) || !needsSweep(d, j)) return;
        const double t = sweepPointCircle(p0 - start[j], d, Vec2{}, ci.radius + cj.radius);
        if (t >= 0.0 && t < hit.t) hit = {t, j};
    };
    // A short path asks the grid (plus the bullets, which were not filed along their paths);
    // a bullet or a path leaving the grid looks at every shape.
    if (!in.isBullet[i] && grid.query(box, in.maxCellsPerAxis, circles_, segments_)) {
        for (int s : segments_) trySegment(s);
        for (int j : circles_) tryCircle(j);
        for (int j : in.bullets) tryCircle(j);
    } else {
        for (int s = 0; s < segmentCount; ++s) trySegment(s);
        for (int j = 0; j < circleCount; ++j) tryCircle(j);
    }
    return hit;
}

bool ContinuousSweep::resolve(int i, const Hit& hit, const SweepInput& in, StepContext& ctx, double dt) {
    std::span<Circle> circles = ctx.circles;
    const int circleCount = static_cast<int>(circles.size());
    Circle& ci = circles[i];
    const Vec2 p0 = in.start[i];
    const Vec2 move = ci.position - p0;
    double t = hit.t; // fraction of the step at the time of impact
    // Clamp at the time of impact, then ride along with the body hit for the rest of the step
    // (it moved less than this circle, or is not dynamic).
    const bool otherIsCircle = hit.other < circleCount;
    Vec2 normal, otherVelocity;
    Vec2 relative; // the circle relative to the other's frame at the time of impact
    double otherInverseMass = 0.0, otherBounciness = 1.0;
    Other kind = Other::circle;
    if (otherIsCircle) {
        const Circle& cj = circles[hit.other];
        const Vec2 moveJ = cj.position - in.start[hit.other];
        relative = p0 - in.start[hit.other] + (move - moveJ) * t;
        normal = relative.length() > 0.0 ? relative.normalized() : Vec2{0.0, 1.0};
        otherVelocity = cj.velocity;
        otherInverseMass = cj.inverseMass;
        otherBounciness = cj.material.bounciness;
        ci.position = cj.position + relative + normal * kClampGap;
    } else {
        const Segment& seg = ctx.segments[hit.other - circleCount];
        const Vec2 segMove = seg.motion() == Motion::kinematic ? seg.velocity * dt : Vec2{};
        // The substeps carried a circle in free flight along p0 + v0 tau + g tau (tau + h) / 2, which
        // passes through both ends of the chord and sags below it by g dt^2 f (1 - f) / 2 at fraction f
        // (0.34 mm mid-step at 60 Hz): enough to turn a glancing cap's normal by half a degree. Two
        // fixed-point passes sweep the straight line through the path's point at the last estimate,
        // exact at that fraction (as aimAtTimeOfImpact does). A circle that contacts pushed did not
        // follow that parabola: its chord stands.
        const Vec2 sag = in.inFlight[static_cast<std::size_t>(i)] ? ctx.def.gravity * (0.5 * dt * dt) : Vec2{};
        const auto along = [&](double f) {
            return (move - segMove) + sag * (f - 1.0);
        }; // p0 + along(f) f is the path at f
        for (int pass = 0; pass < 2; ++pass) {
            const double refined = sweepPointCapsule(p0, along(t), seg.a, seg.b, ci.radius + seg.radius);
            if (refined < 0.0) break;
            t = refined;
        }
        relative = p0 + along(t) * t; // in the segment's start frame
        const Vec2 ab = seg.b - seg.a;
        const double u = ab.lengthSquared() > 0.0 ? (relative - seg.a).dot(ab) / ab.lengthSquared() : 0.0;
        kind = u <= 0.0 || u >= 1.0 ? Other::segmentCap : Other::segment;
        const Vec2 away = relative - closestOnSegment(relative, seg.a, seg.b);
        normal = away.length() > 0.0 ? away.normalized() : ab.normal();
        // A turning segment is swept as translating with its pivot; its surface where it is met moves at v + omega x r.
        otherVelocity = seg.angularVelocity != 0.0 ? seg.velocityAt(relative - normal * ci.radius) : segMove / dt;
        otherBounciness = seg.material.bounciness;
        ci.position = relative + segMove + normal * kClampGap;
    }
    // The circle's velocity is the step's end velocity; against infinite mass it is bounced as it was
    // at the time of impact (gravity for the rest of the step taken off, then given back), as the
    // exact method does. Two dynamic circles fall alike: their relative velocity needs no such care.
    const Vec2 afterImpact = otherInverseMass > 0.0 ? Vec2{} : ctx.def.gravity * ((1.0 - t) * dt);
    const double vn = (ci.velocity - afterImpact - otherVelocity).dot(normal);
    const double inverseMassSum = ci.inverseMass + otherInverseMass;
    if (vn >= 0.0 || inverseMassSum <= 0.0) return false; // leaving already: the clamp keeps it on its side
    // v' = u - C (v - u) along the normal (lecture 3), as an impulse shared by inverse mass; slow
    // touches rest, as in the solver.
    const bool resting = -vn <= ctx.restingSpeed;
    const double bounciness = resting ? 0.0 : ci.material.bounciness * otherBounciness;
    const double impulse = -(1.0 + bounciness) * vn / inverseMassSum;
    // The impulse cancels the approach and C of it; the normal part of gravity after the impact
    // stays in the velocity (it already was).
    ci.velocity += normal * (impulse * ci.inverseMass);
    if (otherIsCircle) circles[hit.other].velocity -= normal * (impulse * otherInverseMass);
    if (resting) {
        ++ctx.stats.restingContacts;
        return false;
    }
    Impact impact;
    impact.circle = i;
    impact.otherKind = kind;
    impact.other = otherIsCircle ? hit.other : hit.other - circleCount;
    impact.time = ctx.time + t * dt;
    impact.pointOfImpact = ci.position - normal * ci.radius;
    impact.normal = normal;
    impact.approachSpeed = -vn;
    ctx.impacts.push_back(impact);
    return true;
}

int ContinuousSweep::run(const SweepInput& in, BroadphaseGrid& grid, StepContext& ctx, double dt) {
    int impacts = 0;
    for (int i = 0; i < static_cast<int>(ctx.circles.size()); ++i) {
        const Circle& ci = ctx.circles[i];
        if (ci.motion != Motion::dynamic) continue;
        // Within its margin every shape it could reach had a contact: nothing to sweep.
        const Vec2 move = ci.position - in.start[i];
        if (move.lengthSquared() <= in.margins[i] * in.margins[i]) continue;
        const Hit hit = earliestHit(i, in, grid, ctx, dt);
        if (hit.other >= 0 && resolve(i, hit, in, ctx, dt)) ++impacts;
    }
    ctx.stats.impacts += impacts;
    return impacts;
}

} // namespace rube
