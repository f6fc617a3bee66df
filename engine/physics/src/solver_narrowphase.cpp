// The circle solver's narrowphase: warm-start cache, contacts from candidate pairs, Gauss-Seidel order, impact records.
#include "solver_narrowphase.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rube {

namespace {

/// Ordering layers beyond this many only cost memory: the order is a heuristic for convergence.
constexpr double kMaxLayers = 256.0;

/// Normal (from the other body towards the circle), start gap and kind of one candidate pair.
struct PairGeometry {
    Vec2 normal;
    double gap = 0.0;
    double reach = 0.0; // sum of the radii: the gap is the centre distance minus this
    Other kind = Other::circle;
};

PairGeometry circleCircle(const Circle& a, const Circle& b) {
    const Vec2 d = a.position - b.position;
    const double dist = std::sqrt(d.lengthSquared()); // not hypot: hot, and no separation overflows
    // Coincident centres have no direction between them; +y keeps the push-back defined.
    const Vec2 n = dist > 0.0 ? d / dist : Vec2{0.0, 1.0};
    return {n, dist - a.radius - b.radius, a.radius + b.radius, Other::circle};
}

PairGeometry circleSegment(const Circle& a, const Segment& s) {
    const Vec2 ab = s.b - s.a;
    const double l2 = ab.lengthSquared();
    // The closest point by scalar projection, clamped to the segment (lecture 5); past an end the
    // circle meets the line cap.
    const double t = l2 > 0.0 ? (a.position - s.a).dot(ab) / l2 : 0.0;
    const double u = std::clamp(t, 0.0, 1.0);
    const Vec2 d = a.position - (s.a + ab * u);
    const double dist = std::sqrt(d.lengthSquared());
    // A centre exactly on the line takes the line's left normal (+y for a degenerate segment).
    const Vec2 fallback = l2 > 0.0 ? ab.normal() : Vec2{0.0, 1.0};
    const Vec2 n = dist > 0.0 ? d / dist : fallback;
    return {n, dist - a.radius - s.radius, a.radius + s.radius,
            (t <= 0.0 || t >= 1.0) ? Other::segmentCap : Other::segment};
}

} // namespace

const PreviousContact* ContactCache::find(int circle, int other, int circleCount, int segmentCount) const {
    if (circleCount != circleCount_ || segmentCount != segmentCount_) return nullptr;
    for (int k = ownerStart_[circle]; k < ownerStart_[circle + 1]; ++k)
        if (other_[k] == other) return &previous_[k];
    return nullptr;
}

void ContactCache::store(std::span<const ContactConstraint> contacts, std::span<const double> tangentImpulses,
                         int circleCount, int segmentCount) {
    circleCount_ = circleCount;
    segmentCount_ = segmentCount;
    // Counting sort by circle: each circle's pairs become one short run to scan next step.
    ownerStart_.assign(static_cast<std::size_t>(circleCount) + 1, 0);
    for (const ContactConstraint& c : contacts) ++ownerStart_[c.a + 1];
    for (int i = 0; i < circleCount; ++i) ownerStart_[i + 1] += ownerStart_[i];
    cursor_.assign(ownerStart_.begin(), ownerStart_.end() - 1);
    other_.resize(contacts.size());
    previous_.resize(contacts.size());
    const bool friction = tangentImpulses.size() == contacts.size();
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        const ContactConstraint& c = contacts[i];
        const int k = cursor_[c.a]++;
        other_[k] = c.b;
        previous_[k] = {c.normal, c.impulse, friction ? tangentImpulses[i] : 0.0};
    }
}

void ContactCache::storeNone(int circleCount, int segmentCount) {
    if (other_.empty() && circleCount == circleCount_ && segmentCount == segmentCount_) return;
    store({}, {}, circleCount, segmentCount);
}

void ContactCache::remap(const SlotRemap& remap) {
    const int oldCircles = static_cast<int>(remap.circles.to.size()),
              oldSegments = static_cast<int>(remap.segments.to.size());
    if (circleCount_ != oldCircles || segmentCount_ != oldSegments) {
        circleCount_ = segmentCount_ = -1; // already stale: found by nothing
        return;
    }
    const int circles = remap.circles.size;
    // Each surviving pair under its new numbers (other: a circle, or circles + a segment), then
    // grouped by circle again as store does.
    std::vector<std::pair<int, int>> keys;
    std::vector<PreviousContact> kept;
    for (int owner = 0; owner < oldCircles; ++owner) {
        const int a = remap.circles(owner);
        for (int k = ownerStart_[static_cast<std::size_t>(owner)]; k < ownerStart_[static_cast<std::size_t>(owner) + 1];
             ++k) {
            const int old = other_[static_cast<std::size_t>(k)];
            const int b = old < oldCircles ? remap.circles(old) : remap.segments(old - oldCircles);
            if (a < 0 || b < 0) continue;
            keys.emplace_back(a, old < oldCircles ? b : circles + b);
            kept.push_back(previous_[static_cast<std::size_t>(k)]);
        }
    }
    circleCount_ = circles;
    segmentCount_ = remap.segments.size;
    ownerStart_.assign(static_cast<std::size_t>(circles) + 1, 0);
    for (const auto& key : keys) ++ownerStart_[static_cast<std::size_t>(key.first) + 1];
    for (int i = 0; i < circles; ++i)
        ownerStart_[static_cast<std::size_t>(i) + 1] += ownerStart_[static_cast<std::size_t>(i)];
    cursor_.assign(ownerStart_.begin(), ownerStart_.end() - 1);
    other_.resize(keys.size());
    previous_.resize(keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const int k = cursor_[static_cast<std::size_t>(keys[i].first)]++;
        other_[static_cast<std::size_t>(k)] = keys[i].second;
        previous_[static_cast<std::size_t>(k)] = kept[i];
    }
}

void buildContacts(std::span<const CandidatePair> pairs, std::span<const Circle> circles,
                   std::span<const Segment> segments, std::span<const double> margins,
                   std::span<const double> inverseMass, const ContactCache& cache,
                   std::vector<ContactConstraint>& contacts, std::vector<ContactRecord>& records) {
    contacts.clear();
    records.clear();
    const int circleCount = static_cast<int>(circles.size());
    const int segmentCount = static_cast<int>(segments.size());
    for (const CandidatePair& pair : pairs) {
        const Circle& a = circles[pair.circle];
        const bool otherIsCircle = pair.other < circleCount;
        PairGeometry g = otherIsCircle ? circleCircle(a, circles[pair.other])
                                       : circleSegment(a, segments[pair.other - circleCount]);
        const PreviousContact* previous = cache.find(pair.circle, pair.other, circleCount, segmentCount);
        // A circle crushed past a thin line or another circle's centre would now be pushed out the
        // far side: a pair that was pushing keeps the side it was touching on (not at a cap, which
        // the circle may legitimately round). Then the gap is measured through the shape: -s - 2R.
        if (previous && previous->impulse > 0.0 && g.kind != Other::segmentCap &&
            previous->normal.dot(g.normal) < 0.0) {
            g.normal = -g.normal;
            g.gap = -g.gap - 2.0 * g.reach;
        }
        // Speculative: a pair counts while its gap is within how far both may move this step.
        if (g.gap >= margins[pair.circle] + margins[pair.other]) continue;
        const double invA = inverseMass[pair.circle], invB = inverseMass[pair.other];
        if (invA + invB <= 0.0) continue;
        ContactConstraint c;
        c.a = pair.circle;
        c.b = pair.other;
        c.normal = g.normal;
        c.baseSeparation = g.gap;
        c.normalMass = 1.0 / (invA + invB);
        c.impulse = previous ? previous->impulse : 0.0;
        contacts.push_back(c);
        const Material& other = otherIsCircle ? circles[pair.other].material
                                              : segments[pair.other - circleCount].material;
        ContactRecord r;
        r.kind = g.kind;
        // The pair's bounciness is the product of both materials' (body.hpp, Material).
        r.bounciness = a.material.bounciness * other.bounciness;
        r.tangentImpulse = previous ? previous->tangentImpulse : 0.0;
        records.push_back(r);
    }
}

void orderContacts(std::vector<ContactConstraint>& contacts, std::vector<ContactRecord>& records,
                   std::span<const Vec2> positions, std::span<const double> inverseMass, Vec2 up, double layerHeight,
                   ContactOrderScratch& scratch) {
    const std::size_t n = contacts.size();
    if (n == 0) return;
    const int circleCount = static_cast<int>(positions.size());
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Vec2& p : positions) {
        lo = std::min(lo, p.dot(up));
        hi = std::max(hi, p.dot(up));
    }
    // Far-flung bodies would make too many layers: then the layers grow thicker.
    const double layers = std::min((hi - lo) / layerHeight + 1.0, kMaxLayers);
    const int layerCount = std::max(1, static_cast<int>(layers));
    const double perLayer = layerCount / (hi - lo + layerHeight);
    // Rank among the circle's contacts: its first contact, its second, ...
    scratch.rank.resize(n);
    scratch.perCircle.assign(positions.size(), 0);
    int rankCount = 1;
    for (std::size_t k = 0; k < n; ++k) {
        scratch.rank[k] = scratch.perCircle[contacts[k].a]++;
        rankCount = std::max(rankCount, scratch.rank[k] + 1);
    }
    // Key: (infinite mass last, layer from the top, rank, pushing first), then a stable counting sort.
    // Pushing first: whether a contact pushes decides the sweeps' branches (gap closed or not, impulse
    // clamped at zero or not, friction to solve or not). Mixed, about a third of consecutive contacts
    // differ; the CPU learns such a pattern by heart for a 1000-ball pile's 2850 contacts but not for
    // a 20,000-ball pile's 57,000, and mispredicts. Grouped (0.7 % of neighbours differ), one step's
    // relax pass costs 3.2 ns a contact at 20,000 balls (it was 5.1) and 3.1 at 1000. The warm-start
    // impulse is the best guess of this step's: it is last step's final one.
    scratch.key.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const ContactConstraint& c = contacts[k];
        const bool dynamicPair = c.b < circleCount && inverseMass[static_cast<std::size_t>(c.b)] > 0.0;
        const double height = dynamicPair ? 0.5 * (positions[c.a].dot(up) + positions[c.b].dot(up))
                                          : positions[c.a].dot(up);
        const int layer = std::clamp(static_cast<int>((height - lo) * perLayer), 0, layerCount - 1);
        const int fromTop = layerCount - 1 - layer + (dynamicPair ? 0 : layerCount);
        const int notPushing = c.impulse > 0.0 ? 0 : 1;
        scratch.key[k] = (fromTop * rankCount + scratch.rank[k]) * 2 + notPushing;
    }
    const int keyCount = 4 * layerCount * rankCount;
    scratch.start.assign(static_cast<std::size_t>(keyCount) + 1, 0);
    for (std::size_t k = 0; k < n; ++k) ++scratch.start[scratch.key[k] + 1];
    for (int r = 0; r < keyCount; ++r) scratch.start[r + 1] += scratch.start[r];
    scratch.contacts.resize(n);
    scratch.records.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const int to = scratch.start[scratch.key[k]]++;
        scratch.contacts[to] = contacts[k];
        scratch.records[to] = records[k];
    }
    contacts.swap(scratch.contacts);
    records.swap(scratch.records);
}

int recordContactImpacts(std::span<const ContactConstraint> contacts, std::span<const ContactRecord> records,
                         std::span<const Circle> circles, StepContext& ctx) {
    const int circleCount = static_cast<int>(circles.size());
    int impacts = 0;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const ContactConstraint& c = contacts[k];
        const ContactRecord& r = records[k];
        if (r.firstTouch < 0) {
            // Pushing since the step began (warm started): resting contact.
            if (c.impulse > 0.0) ++ctx.stats.restingContacts;
            continue;
        }
        if (r.approachSpeed <= ctx.restingSpeed) {
            ++ctx.stats.restingContacts;
            continue;
        }
        const Circle& circle = circles[c.a];
        Impact impact;
        impact.circle = c.a;
        impact.otherKind = r.kind;
        impact.other = c.b < circleCount ? c.b : c.b - circleCount;
        impact.time = ctx.time + r.touchTime;
        impact.pointOfImpact = r.carried ? r.pointOfImpact : circle.position - c.normal * circle.radius;
        impact.normal = c.normal;
        impact.approachSpeed = r.approachSpeed;
        ctx.impacts.push_back(impact);
        ++impacts;
    }
    ctx.stats.impacts += impacts;
    return impacts;
}

} // namespace rube
