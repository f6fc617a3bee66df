// The solver's uniform-grid broadphase (broadphase_grid.hpp) against brute force: on seeded random
// scenes of small, big and tiny circles, bullets, long and moving segments, and bodies placed on cell
// borders, findPairs must report every pair a brute-force scan of all pairs finds, each once, in the
// documented order, and nothing whose boxes do not overlap; query must list every shape near a box.
#include "broadphase_grid.hpp" // internal: tests may reach inside, users may not

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <set>
#include <utility>
#include <vector>

using namespace rube;

namespace {

struct Scene {
    std::vector<BoundingBox> circleBoxes; // contact boxes
    std::vector<BoundingBox> filingBoxes; // contact boxes plus where the circle is heading
    std::vector<std::uint8_t> isDynamic;
    std::vector<SweptSegment> segments;
    std::vector<BoundingBox> segmentBoxes;
    BoundingBox region;
};

BoundingBox around(Vec2 c, double reach) { return {c - Vec2{reach, reach}, c + Vec2{reach, reach}}; }

BoundingBox merged(const BoundingBox& a, const BoundingBox& b) {
    return {{std::min(a.min.x, b.min.x), std::min(a.min.y, b.min.y)},
            {std::max(a.max.x, b.max.x), std::max(a.max.y, b.max.y)}};
}

/// The box of a segment's swept capsule, as the solver gives it (its four end positions fattened by its reach).
BoundingBox sweptBox(const SweptSegment& s) {
    BoundingBox box{s.a, s.a};
    for (const Vec2 p : {s.b, s.a + s.motion, s.b + s.motion}) box = merged(box, {p, p});
    return {box.min - Vec2{s.reach, s.reach}, box.max + Vec2{s.reach, s.reach}};
}

/// Distance from point p to segment ab.
double pointSegmentDistance(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 d = b - a;
    const double dd = d.lengthSquared();
    const double t = dd > 0.0 ? std::clamp((p - a).dot(d) / dd, 0.0, 1.0) : 0.0;
    return (p - (a + d * t)).length();
}

/// Distance from point p to box (0 inside).
double pointBoxDistance(Vec2 p, const BoundingBox& box) {
    const double dx = std::max({box.min.x - p.x, 0.0, p.x - box.max.x});
    const double dy = std::max({box.min.y - p.y, 0.0, p.y - box.max.y});
    return std::hypot(dx, dy);
}

/// True when segment ab crosses the box (Liang-Barsky clipping).
bool segmentCrossesBox(Vec2 a, Vec2 b, const BoundingBox& box) {
    double t0 = 0.0, t1 = 1.0;
    const Vec2 d = b - a;
    const double p[4] = {-d.x, d.x, -d.y, d.y};
    const double q[4] = {a.x - box.min.x, box.max.x - a.x, a.y - box.min.y, box.max.y - a.y};
    for (int k = 0; k < 4; ++k) {
        if (p[k] == 0.0) {
            if (q[k] < 0.0) return false;
            continue;
        }
        const double t = q[k] / p[k];
        if (p[k] < 0.0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
        if (t0 > t1) return false;
    }
    return true;
}

/// Distance between a box and a segment (two convex shapes: when apart, the closest pair has a vertex of one).
double segmentBoxDistance(Vec2 a, Vec2 b, const BoundingBox& box) {
    if (segmentCrossesBox(a, b, box)) return 0.0;
    double best = std::min(pointBoxDistance(a, box), pointBoxDistance(b, box));
    for (const Vec2 corner : {box.min, box.max, Vec2{box.min.x, box.max.y}, Vec2{box.max.x, box.min.y}})
        best = std::min(best, pointSegmentDistance(corner, a, b));
    return best;
}

/// Distance from the box to the region the segment sweeps over the step (the parallelogram of its
/// four end positions) fattened by its reach: the hull's edges are among the six chords of its corners.
double sweptCapsuleBoxDistance(const SweptSegment& s, const BoundingBox& box) {
    const Vec2 pts[4] = {s.a, s.b, s.b + s.motion, s.a + s.motion};
    const Vec2 centre = (box.min + box.max) * 0.5;
    // The box's centre inside the parallelogram: every edge has it on the same side.
    double sides[4];
    for (int k = 0; k < 4; ++k) sides[k] = (pts[(k + 1) % 4] - pts[k]).cross(centre - pts[k]);
    const bool inside = std::all_of(sides, sides + 4, [](double v) { return v > 0.0; }) ||
                        std::all_of(sides, sides + 4, [](double v) { return v < 0.0; });
    if (inside) return -s.reach;
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) best = std::min(best, segmentBoxDistance(pts[i], pts[j], box));
    return best - s.reach;
}

/// A random scene: mostly small circles, some big, some tiny, some bullets filed along a long path,
/// static circles anywhere (also outside the region, clamped into its border cells), and segments
/// long and short, still and moving. Some circles then sit exactly on cell borders.
Scene randomScene(std::mt19937_64& rng, int circles, int segments) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
    Scene s;
    const double side = uniform(4.0, 20.0);
    for (int i = 0; i < circles; ++i) {
        const double kind = unit(rng);
        const double r = kind < 0.1 ? uniform(1.0, 3.0) : kind < 0.2 ? uniform(1e-5, 1e-3) : uniform(0.05, 0.25);
        const Vec2 c{uniform(0.0, side), uniform(0.0, side)};
        const bool dynamic = unit(rng) < 0.7;
        const BoundingBox contact = around(c, r + uniform(0.0, 0.5) * r);
        Vec2 move{};
        if (dynamic)
            move = Vec2{uniform(-1.0, 1.0), uniform(-1.0, 1.0)} *
                   (unit(rng) < 0.1 ? uniform(2.0, 8.0) : uniform(0.0, 0.3));
        const BoundingBox end = around(c + move, r);
        s.circleBoxes.push_back(contact);
        s.filingBoxes.push_back(merged(contact, end));
        s.isDynamic.push_back(dynamic ? 1 : 0);
    }
    for (int k = 0; k < segments; ++k) {
        const Vec2 a{uniform(-2.0, side + 2.0), uniform(-2.0, side + 2.0)};
        const double length = unit(rng) < 0.3 ? uniform(5.0, 2.0 * side) : uniform(0.0, 2.0);
        const double angle = uniform(0.0, 6.283185307179586);
        SweptSegment seg;
        seg.a = a;
        seg.b = a + Vec2{std::cos(angle), std::sin(angle)} * length;
        seg.motion = unit(rng) < 0.3 ? Vec2{uniform(-1.0, 1.0), uniform(-1.0, 1.0)} : Vec2{};
        seg.reach = unit(rng) < 0.5 ? 0.0 : uniform(0.0, 0.3);
        s.segments.push_back(seg);
        s.segmentBoxes.push_back(sweptBox(seg));
    }
    // The region the dynamic circles' filing boxes cover, as the solver lays the grid.
    bool first = true;
    for (std::size_t i = 0; i < s.filingBoxes.size(); ++i) {
        if (!s.isDynamic[i]) continue;
        s.region = first ? s.filingBoxes[i] : merged(s.region, s.filingBoxes[i]);
        first = false;
    }
    return s;
}

/// The solver's cell size: a little wider than the mean filing box of the dynamic circles.
double typicalCellSize(const Scene& s) {
    double sum = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < s.filingBoxes.size(); ++i) {
        if (!s.isDynamic[i]) continue;
        sum += std::max(s.filingBoxes[i].max.x - s.filingBoxes[i].min.x,
                        s.filingBoxes[i].max.y - s.filingBoxes[i].min.y);
        ++n;
    }
    return 1.1 * sum / std::max(n, 1);
}

/// Moves some dynamic small circles so their centres, or their boxes' edges, lie exactly on cell
/// borders of a grid with cells `c` from `origin`, and puts a neighbour's box exactly touching
/// theirs across the border (boxes that share a point overlap).
void snapToCellBorders(Scene& s, Vec2 origin, double c, std::mt19937_64& rng) {
    const int nx = static_cast<int>(std::floor((s.region.max.x - origin.x) / c));
    const int ny = static_cast<int>(std::floor((s.region.max.y - origin.y) / c));
    if (nx < 2 || ny < 2) return;
    std::uniform_int_distribution<int> cellX(1, nx - 1), cellY(1, ny - 1);
    for (std::size_t i = 0; i + 1 < s.circleBoxes.size(); i += 3) {
        if (!s.isDynamic[i]) continue;
        const BoundingBox box = s.circleBoxes[i];
        const Vec2 half = (box.max - box.min) * 0.5;
        if (2.0 * half.x > c) continue;
        const Vec2 corner = origin + Vec2{cellX(rng) * c, cellY(rng) * c};
        // Centre on a corner of four cells, or the box's right edge on a vertical border.
        const Vec2 centre = (i % 2 == 0) ? corner : corner - Vec2{half.x, 0.0};
        s.circleBoxes[i] = s.filingBoxes[i] = {centre - half, centre + half};
        // Its neighbour's box starts exactly where this one ends.
        const Vec2 nextHalf = (s.circleBoxes[i + 1].max - s.circleBoxes[i + 1].min) * 0.5;
        const Vec2 nextCentre{centre.x + half.x + nextHalf.x, centre.y};
        s.circleBoxes[i + 1] = s.filingBoxes[i + 1] = {nextCentre - nextHalf, nextCentre + nextHalf};
    }
}

using PairSet = std::set<std::pair<int, int>>;

/// Brute force: every pair in which a circle is dynamic whose contact boxes overlap (a segment's
/// box overlapping too and its swept capsule reaching the circle's box), in the documented order:
/// the dynamic circle first, the lower index when both are.
void bruteForce(const Scene& s, PairSet& must, PairSet& may) {
    const int n = static_cast<int>(s.circleBoxes.size());
    for (int i = 0; i < n; ++i) {
        if (!s.isDynamic[i]) continue;
        for (int j = 0; j < n; ++j) {
            if (j == i || (s.isDynamic[j] && j < i)) continue;
            if (s.circleBoxes[i].overlaps(s.circleBoxes[j])) must.insert({i, j});
        }
        for (int k = 0; k < static_cast<int>(s.segments.size()); ++k) {
            if (!s.circleBoxes[i].overlaps(s.segmentBoxes[k])) continue;
            may.insert({i, n + k});
            // Clear of the capsule's surface by round-off: the grid files the capsule, not its box.
            if (sweptCapsuleBoxDistance(s.segments[k], s.circleBoxes[i]) < -1e-9) must.insert({i, n + k});
        }
    }
    may.insert(must.begin(), must.end());
}

void checkPairs(const Scene& s, BroadphaseGrid& grid) {
    std::vector<CandidatePair> pairs;
    grid.findPairs(s.circleBoxes, s.segmentBoxes, s.isDynamic, pairs);
    PairSet must, may, found;
    bruteForce(s, must, may);
    for (const CandidatePair& p : pairs) {
        INFO("pair " << p.circle << " " << p.other);
        CHECK(found.insert({p.circle, p.other}).second); // each pair once
        CHECK(may.count({p.circle, p.other}) == 1);      // boxes overlap, in the documented order
    }
    int missing = 0;
    for (const auto& pair : must)
        if (!found.count(pair)) {
            ++missing;
            UNSCOPED_INFO("missed pair " << pair.first << " " << pair.second);
        }
    CHECK(missing == 0);
}

} // namespace

TEST_CASE("the grid's pairs are the brute-force pairs on random scenes of varied sizes", "[solver][broadphase]") {
    std::mt19937_64 rng(20);
    int scenes = 0, pairsChecked = 0;
    for (int scene = 0; scene < 60; ++scene) {
        const int circles = 20 + 10 * (scene % 12);
        Scene s = randomScene(rng, circles, 1 + scene % 7);
        const double cellSizes[3] = {typicalCellSize(s), 0.25 * typicalCellSize(s), 4.0 * typicalCellSize(s)};
        for (const double cellSize : cellSizes) {
            BroadphaseGrid grid;
            // The solver's cap on cells (4 per circle and 64), which enlarges the small cells.
            grid.build(s.filingBoxes, s.segments, s.region, cellSize, 4 * circles + 64);
            INFO("scene " << scene << " cell " << cellSize << " (built " << grid.cellSize() << ")");
            checkPairs(s, grid);
            // The same scene with circles on the borders of the cells this grid uses, rebuilt.
            Scene snapped = s;
            snapToCellBorders(snapped, s.region.min, grid.cellSize(), rng);
            BroadphaseGrid again;
            again.build(snapped.filingBoxes, snapped.segments, snapped.region, cellSize, 4 * circles + 64);
            REQUIRE(again.cellSize() == grid.cellSize());
            checkPairs(snapped, again);
            PairSet must, may;
            bruteForce(snapped, must, may);
            pairsChecked += static_cast<int>(must.size());
            ++scenes;
        }
    }
    CHECK(scenes == 180);
    CHECK(pairsChecked > 1000); // the scenes are crowded enough to mean something
}

TEST_CASE("a grid query lists every shape filed near the box, each once", "[solver][broadphase]") {
    std::mt19937_64 rng(27);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int scene = 0; scene < 20; ++scene) {
        Scene s = randomScene(rng, 80, 5);
        BroadphaseGrid grid;
        grid.build(s.filingBoxes, s.segments, s.region, typicalCellSize(s), 4 * 80 + 64);
        const double c = grid.cellSize();
        std::vector<int> circles, segments;
        int answered = 0;
        for (int q = 0; q < 50; ++q) {
            const Vec2 lo{s.region.min.x + unit(rng) * (s.region.max.x - s.region.min.x),
                          s.region.min.y + unit(rng) * (s.region.max.y - s.region.min.y)};
            const BoundingBox box{lo, lo + Vec2{unit(rng), unit(rng)} * (3.0 * c)};
            if (!grid.query(box, 8, circles, segments)) continue;
            ++answered;
            const std::set<int> circleSet(circles.begin(), circles.end()), segmentSet(segments.begin(), segments.end());
            CHECK(circleSet.size() == circles.size());
            CHECK(segmentSet.size() == segments.size());
            for (std::size_t i = 0; i < s.filingBoxes.size(); ++i)
                if (s.filingBoxes[i].overlaps(box)) CHECK(circleSet.count(static_cast<int>(i)) == 1);
            for (std::size_t k = 0; k < s.segments.size(); ++k)
                if (sweptCapsuleBoxDistance(s.segments[k], box) < -1e-9)
                    CHECK(segmentSet.count(static_cast<int>(k)) == 1);
        }
        CHECK(answered > 10);
    }
}
