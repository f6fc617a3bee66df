// The solver's bodies for a step (velocities, margins, which circles are bullets) and the step's
// contacts: candidate pairs from the uniform grid, narrowphase once per step (solver_method.hpp).
#include "solver_method.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rube {

namespace {

/// Speculative distance every circle gets on top of its motion, as a fraction of its radius: a struck
/// row with gaps of up to half a radius still has its contacts when the blow runs through it.
constexpr double kSpeculativePerRadius = 0.25;
/// A dynamic circle's margin never exceeds this many radii; beyond it the continuous sweep takes over,
/// so a bullet does not drag every shape along its 83 m path into the contact list.
constexpr double kMaxMarginPerRadius = 1.0;
/// Grid cells this much wider than the typical filing box, so that box fits one cell.
constexpr double kCellPerFilingSpan = 1.1;

} // namespace

std::span<const BoundingBox> SolverMethod::bulletPaths(double dt) {
    bulletPaths_.clear();
    for (const int i : bullets_) {
        const BoundingBox& box = circleBoxes_[static_cast<std::size_t>(i)];
        const Vec2 move = bodies_[static_cast<std::size_t>(i)].velocity * dt;
        bulletPaths_.push_back({{box.min.x + std::min(move.x, 0.0), box.min.y + std::min(move.y, 0.0)},
                                {box.max.x + std::max(move.x, 0.0), box.max.y + std::max(move.y, 0.0)}});
    }
    return bulletPaths_;
}

void SolverMethod::prepareBodies(const StepContext& ctx, double dt) {
    circleCount_ = static_cast<int>(ctx.circles.size());
    segmentCount_ = static_cast<int>(ctx.segments.size());
    const std::size_t bodyCount = ctx.circles.size() + ctx.segments.size();
    bodies_.resize(bodyCount);
    inverseMass_.resize(bodyCount);
    margins_.resize(bodyCount);
    start_.resize(ctx.circles.size());
    isDynamic_.resize(ctx.circles.size());
    circleBoxes_.resize(ctx.circles.size());
    filingBoxes_.resize(ctx.circles.size());
    isBullet_.resize(ctx.circles.size());
    segmentBoxes_.resize(ctx.segments.size());
    sweptSegments_.resize(ctx.segments.size());
    // Over a step a body moves at most |v| dt + |g| dt^2 (its speed grows by at most |g| dt).
    const double gravityTravel = ctx.def.gravity.length() * dt * dt;
    fastStep_ = false;
    anyRotation_ = false;
    turning_ = false;
    for (int i = 0; i < circleCount_; ++i) {
        const Circle& c = ctx.circles[i];
        // An asleep circle is fixed for the step: no gravity, no contacts of its own.
        const bool dynamic = c.motion == Motion::dynamic && c.inverseMass > 0.0 && !c.sleep.asleep;
        const Vec2 v = c.motion == Motion::fixed ? Vec2{} : c.velocity;
        start_[i] = c.position;
        bodies_[i] = {v, {}};
        inverseMass_[i] = dynamic ? c.inverseMass : 0.0;
        isDynamic_[i] = dynamic ? 1 : 0;
        // Model no more than the scene needs: rotation only once a circle can turn (it spins, or it
        // could meet friction); otherwise no angular state is touched at all.
        if (dynamic && c.inverseInertia > 0.0 && (c.material.friction > 0.0 || c.angularVelocity != 0.0))
            anyRotation_ = true;
        const double travel = v.length() * dt;
        if (dynamic && travel > kFastTravelPerRadius * c.radius) fastStep_ = true;
        double margin = kSpeculativePerRadius * c.radius + travel;
        if (dynamic) margin = std::min(margin + gravityTravel, kMaxMarginPerRadius * c.radius);
        margins_[i] = margin;
        const Vec2 reach{c.radius + margin, c.radius + margin};
        circleBoxes_[i] = {c.position - reach, c.position + reach};
    }
    // A joint on a circle turns it (a wheel on its axle, a gear): the step models rotation.
    if (!ctx.joints.empty() && jointsTurnCircles(ctx.joints)) anyRotation_ = true;
    for (int s = 0; s < segmentCount_; ++s) {
        const Segment& seg = ctx.segments[s];
        const Vec2 v = seg.motion() == Motion::kinematic ? seg.velocity : Vec2{};
        const int body = circleCount_ + s;
        bodies_[body] = {v, {}};
        inverseMass_[body] = 0.0;
        margins_[body] = v.length() * dt; // the circle's own margin carries the slop
        sweptSegments_[s] = {seg.a, seg.b, v * dt, seg.radius};
        const Vec2 m = v * dt;
        double reach = seg.radius;
        if (seg.angularVelocity != 0.0) {
            // A turning segment's ends move up to |omega| times their distance from the pivot farther.
            const Vec2 pivot = lerp(seg.a, seg.b, seg.pivotAlong);
            const double turn = std::abs(seg.angularVelocity) *
                                std::max((seg.a - pivot).length(), (seg.b - pivot).length()) * dt;
            margins_[body] += turn;
            reach += turn;
            turning_ = true;
        }
        const Vec2 lo{std::min({seg.a.x, seg.b.x, seg.a.x + m.x, seg.b.x + m.x}),
                      std::min({seg.a.y, seg.b.y, seg.a.y + m.y, seg.b.y + m.y})};
        const Vec2 hi{std::max({seg.a.x, seg.b.x, seg.a.x + m.x, seg.b.x + m.x}),
                      std::max({seg.a.y, seg.b.y, seg.a.y + m.y, seg.b.y + m.y})};
        segmentBoxes_[s] = {lo - Vec2{reach, reach}, hi + Vec2{reach, reach}};
    }
}

void SolverMethod::findContacts(const StepContext& ctx, double dt) {
    // Circles are filed along the path they are heading for, so the continuous pass finds them
    // through the grid. Cells are a little wider than the typical filing box (each counted at most
    // twice its contact box, so a few bullets do not blow the cells up), so most circles are "small".
    double spanSum = 0.0;
    int dynamicCount = 0;
    for (int i = 0; i < circleCount_; ++i) {
        BoundingBox filing = circleBoxes_[i];
        const double r = ctx.circles[i].radius;
        const Vec2 end = start_[i] + bodies_[i].velocity * dt;
        filing.min = {std::min(filing.min.x, end.x - r), std::min(filing.min.y, end.y - r)};
        filing.max = {std::max(filing.max.x, end.x + r), std::max(filing.max.y, end.y + r)};
        filingBoxes_[i] = filing;
        if (!isDynamic_[i]) continue;
        const double span = std::max(filing.max.x - filing.min.x, filing.max.y - filing.min.y);
        spanSum += std::min(span, 2.0 * (circleBoxes_[i].max.x - circleBoxes_[i].min.x));
        ++dynamicCount;
    }
    pairs_.clear();
    bullets_.clear();
    if (dynamicCount > 0) {
        const double cellSize = kCellPerFilingSpan * spanSum / dynamicCount;
        constexpr double inf = std::numeric_limits<double>::infinity();
        BoundingBox region{{inf, inf}, {-inf, -inf}};
        for (int i = 0; i < circleCount_; ++i) {
            const BoundingBox& filing = filingBoxes_[i];
            const double span = std::max(filing.max.x - filing.min.x, filing.max.y - filing.min.y);
            // A bullet's path would cover too many cells: it is filed where it starts.
            isBullet_[i] = isDynamic_[i] && span > kMaxSweepCellsPerAxis * cellSize ? 1 : 0;
            if (isBullet_[i]) {
                filingBoxes_[i] = circleBoxes_[i];
                bullets_.push_back(i);
            }
            if (!isDynamic_[i] && !ctx.circles[i].sleep.asleep)
                continue; // sleepers inside the grid, not in its border cells
            region.min = {std::min(region.min.x, filingBoxes_[i].min.x), std::min(region.min.y, filingBoxes_[i].min.y)};
            region.max = {std::max(region.max.x, filingBoxes_[i].max.x), std::max(region.max.y, filingBoxes_[i].max.y)};
        }
        // Within the world's bounds: escaped bodies are clamped into the grid's border cells.
        const BoundingBox bounds{ctx.def.bounds.min - Vec2{cellSize, cellSize},
                                 ctx.def.bounds.max + Vec2{cellSize, cellSize}};
        const BoundingBox clipped{{std::max(region.min.x, bounds.min.x), std::max(region.min.y, bounds.min.y)},
                                  {std::min(region.max.x, bounds.max.x), std::min(region.max.y, bounds.max.y)}};
        if (clipped.min.x <= clipped.max.x && clipped.min.y <= clipped.max.y) region = clipped;
        grid_.build(filingBoxes_, sweptSegments_, region, cellSize, 4 * circleCount_ + 64);
        grid_.findPairs(circleBoxes_, segmentBoxes_, isDynamic_, pairs_);
    }
    // Two circles a joint joins do not touch unless it says they collide (collideConnected).
    connectedCirclePairs(ctx.joints, connected_);
    if (!connected_.empty())
        std::erase_if(pairs_, [&](const CandidatePair& p) {
            return p.other < circleCount_ && connectedCircles(connected_, p.circle, p.other);
        });
    buildContacts(pairs_, ctx.circles, ctx.segments, margins_, inverseMass_, cache_, contacts_, records_);
    // A pair closing fast is caught where it will touch, not where it starts (a glance at a cap).
    aimAtTimeOfImpact(contacts_, records_, ctx.circles, ctx.segments, inverseMass_, ctx.def.gravity, dt,
                      dt / std::max(1, ctx.def.substeps), ctx.restingSpeed);
    const Vec2 up = ctx.def.gravity.lengthSquared() > 0.0 ? -ctx.def.gravity.normalized() : Vec2{0.0, 1.0};
    orderContacts(contacts_, records_, start_, inverseMass_, up, grid_.cellSize(), orderScratch_);
    hasRigid_ = !ctx.bodies.empty() || !ctx.joints.empty(); // joints are solved in the rigid stage
    if (hasRigid_) rigid_.prepare(ctx, dt);
    frictions_.clear();
    frictionBodies_.clear();
    rotating_.clear();
    if (anyRotation_) findFriction(ctx);
}

void SolverMethod::findFriction(const StepContext& ctx) {
    const auto& circles = ctx.circles;
    const auto& segments = ctx.segments;
    // A pair's friction is the product of both materials' (as its bounciness is, and as Chipmunk does).
    buildFriction(
        contacts_, records_, circles, inverseMass_,
        [&](std::size_t k) {
            const ContactConstraint& c = contacts_[k];
            const double other = c.b < circleCount_
                                     ? circles[static_cast<std::size_t>(c.b)].material.friction
                                     : segments[static_cast<std::size_t>(c.b - circleCount_)].material.friction;
            return circles[static_cast<std::size_t>(c.a)].material.friction * other;
        },
        frictions_);
    buildFrictionBodies(circles, segments, bodies_.size(), frictionBodies_);
    omega_.assign(bodies_.size(), 0.0);
    marks_.assign(ctx.circles.size(), 0);
    const auto list = [&](int body) {
        if (body >= circleCount_ || marks_[static_cast<std::size_t>(body)] ||
            !isDynamic_[static_cast<std::size_t>(body)])
            return;
        marks_[static_cast<std::size_t>(body)] = 1;
        rotating_.push_back(body);
    };
    for (int i = 0; i < circleCount_; ++i)
        if (circles[static_cast<std::size_t>(i)].angularVelocity != 0.0) list(i);
    for (std::size_t k = 0; k < frictions_.size(); ++k) {
        if (frictions_[k].friction <= 0.0) continue;
        list(contacts_[k].a);
        list(contacts_[k].b);
    }
    if (hasRigid_) rigid_.listFrictionCircles(list);
    listJointedCircles(ctx.joints, list);
    for (const int i : rotating_)
        omega_[static_cast<std::size_t>(i)] = circles[static_cast<std::size_t>(i)].angularVelocity;
    turn_.assign(rotating_.size(), 0.0);
}

} // namespace rube
