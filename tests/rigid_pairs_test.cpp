// The rigid bodies' broadphase (rigid_pairs.hpp) against brute force: on seeded random scenes of
// boxes of many sizes (planks, crates, a long ground, a wheel far bigger than the rest), boxes
// touching exactly on cell borders, boxes far apart (so the grid is coarse), circles among them and
// none at all, find() must list exactly the pairs the brute-force double loop finds, in its order.
#include "rigid_pairs.hpp" // internal: tests may reach inside, users may not

#include <catch2/catch.hpp>

#include <random>
#include <vector>

using namespace rube;

namespace {

BoundingBox boxAt(Vec2 centre, Vec2 half) { return {centre - half, centre + half}; }

// The order and the pairs of RigidStage's former n^2 search: body i, then rigid j > i, then circles.
std::vector<RigidPair> bruteForce(const std::vector<BoundingBox>& rigid, const std::vector<BoundingBox>& circles) {
    std::vector<RigidPair> pairs;
    const int n = static_cast<int>(rigid.size());
    for (int i = 0; i < n; ++i) {
        for (int j = i + 1; j < n; ++j)
            if (rigid[static_cast<std::size_t>(i)].overlaps(rigid[static_cast<std::size_t>(j)])) pairs.push_back({i, j});
        for (int c = 0; c < static_cast<int>(circles.size()); ++c)
            if (rigid[static_cast<std::size_t>(i)].overlaps(circles[static_cast<std::size_t>(c)]))
                pairs.push_back({i, n + c});
    }
    return pairs;
}

struct Layout {
    int rigid;
    int circles;
    double spread; // m: centres within +-spread
    bool onGrid;   // centres on a 1 m lattice with half-size 0.5: boxes touch exactly, edge to edge
};

void randomScene(std::mt19937_64& rng, const Layout& l, std::vector<BoundingBox>& rigid,
                 std::vector<BoundingBox>& circles) {
    std::uniform_real_distribution<double> at(-l.spread, l.spread), size(0.01, 1.5), unit(0.0, 1.0);
    std::uniform_int_distribution<int> cell(-static_cast<int>(l.spread), static_cast<int>(l.spread));
    rigid.clear();
    circles.clear();
    for (int i = 0; i < l.rigid; ++i) {
        if (l.onGrid) {
            rigid.push_back(boxAt({static_cast<double>(cell(rng)), static_cast<double>(cell(rng))}, {0.5, 0.5}));
            continue;
        }
        const double kind = unit(rng);
        Vec2 half{size(rng), size(rng)};
        if (kind < 0.05) half = {50.0 * size(rng), 0.5};        // a long ground or wall
        else if (kind < 0.08) half = {8.0, 8.0};                // a wheel far bigger than the rest
        else if (kind < 0.3) half = {size(rng) * 2.0, 0.05};    // a plank
        rigid.push_back(boxAt({at(rng), at(rng)}, half));
    }
    for (int c = 0; c < l.circles; ++c) {
        const double r = 0.05 + 0.3 * unit(rng);
        circles.push_back(boxAt({at(rng), at(rng)}, {r, r}));
    }
}

} // namespace

TEST_CASE("rigid broadphase: the pairs and their order are the brute-force search's", "[rigid_pairs]") {
    const Layout layouts[] = {
        {1, 0, 5.0, false},     {2, 0, 1.0, false},    {40, 0, 5.0, false},  {200, 0, 10.0, false},
        {200, 300, 10.0, false}, {30, 500, 20.0, false}, {5, 50, 1e5, false}, {300, 0, 6.0, true},
        {150, 80, 4.0, true},   {0, 50, 5.0, false},
    };
    std::mt19937_64 rng(20261127);
    RigidPairFinder finder; // reused across scenes, as the stage reuses it across steps
    std::vector<BoundingBox> rigid, circles;
    std::vector<RigidPair> pairs;
    int scenes = 0;
    for (const Layout& layout : layouts) {
        for (int round = 0; round < 12; ++round) {
            randomScene(rng, layout, rigid, circles);
            finder.find(rigid, circles, pairs);
            const std::vector<RigidPair> expected = bruteForce(rigid, circles);
            INFO("rigid " << layout.rigid << ", circles " << layout.circles << ", spread " << layout.spread
                          << ", round " << round);
            REQUIRE(pairs.size() == expected.size());
            CHECK(pairs == expected);
            ++scenes;
        }
    }
    CHECK(scenes == 120);
}

TEST_CASE("rigid broadphase: a pyramid's pairs are its neighbours, not n^2", "[rigid_pairs]") {
    // Unit boxes resting in a pyramid of base 40 (820 boxes), each touching its row and the rows
    // above and below: the pairs are the touching ones only (far fewer than the 335,790 of n^2).
    std::vector<BoundingBox> rigid, none;
    const int base = 40;
    for (int row = 0; row < base; ++row)
        for (int i = 0; i < base - row; ++i)
            rigid.push_back(boxAt({(i - 0.5 * (base - row - 1)) * 1.0, 0.5 + row}, {0.52, 0.52}));
    RigidPairFinder finder;
    std::vector<RigidPair> pairs;
    finder.find(rigid, none, pairs);
    CHECK(pairs == bruteForce(rigid, none));
    CHECK(pairs.size() < 6 * rigid.size());
}

TEST_CASE("rigid broadphase: kept candidates give the brute-force pairs step after step", "[rigid_pairs]") {
    // Boxes and circles that breathe and drift a little every step (as a resting pile's boxes do with
    // their speed), with now and then one thrown far: each step's pairs must be the brute-force ones
    // whether the grid was filed again or its candidates kept, and jitter alone must not refile it.
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<BoundingBox> rigid, circles;
    randomScene(rng, {120, 60, 6.0, false}, rigid, circles);
    RigidPairFinder finder;
    std::vector<RigidPair> pairs;
    finder.find(rigid, circles, pairs);
    const long long first = finder.refilings();
    int mismatches = 0, throws = 0;
    for (int step = 0; step < 200; ++step) {
        const bool jitterOnly = step < 100;
        for (auto* list : {&rigid, &circles})
            for (BoundingBox& b : *list) {
                const double side = std::max(b.max.x - b.min.x, b.max.y - b.min.y);
                const Vec2 drift{1e-4 * side * unit(rng), 1e-4 * side * unit(rng)};
                const double breathe = 1e-4 * side * unit(rng);
                b = {b.min + drift - Vec2{breathe, breathe}, b.max + drift + Vec2{breathe, breathe}};
            }
        if (!jitterOnly && step % 7 == 0) {
            BoundingBox& b = rigid[static_cast<std::size_t>(step) % rigid.size()];
            const Vec2 jump{3.0 * unit(rng), 3.0 * unit(rng)};
            b = {b.min + jump, b.max + jump};
            ++throws;
        }
        finder.find(rigid, circles, pairs);
        if (pairs != bruteForce(rigid, circles)) ++mismatches;
        if (jitterOnly) {
            INFO("step " << step);
            CHECK(finder.refilings() == first);
        }
    }
    CHECK(mismatches == 0);
    CHECK(throws > 10);
    CHECK(finder.refilings() > first); // the throws refiled it
}
