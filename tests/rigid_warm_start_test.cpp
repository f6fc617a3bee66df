// Warm starting of rigid contacts (rigid_warm_start.hpp): a point found again next step, by its body
// pair and its features, starts with the impulses it ended the last step with and counts as carried;
// a point of another pair, of another feature, or one whose contact went away in between starts from
// zero. Last, through the narrowphase: a box sliding on the ground keeps each corner's impulses.
#include "rigid_manifold.hpp" // internal: tests may reach inside, users may not
#include "rigid_warm_start.hpp"
#include "worker_pool.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

using namespace rube;

namespace {

/// A contact between sides a and b with points of the given features and normal impulses (tangent: half).
RigidContact contact(BodySide a, BodySide b, std::vector<std::uint32_t> features, std::vector<double> impulses) {
    RigidContact c;
    c.a = a;
    c.b = b;
    c.normal = {0.0, 1.0};
    c.count = static_cast<int>(features.size());
    for (int k = 0; k < c.count; ++k) {
        c.points[k].feature = features[static_cast<std::size_t>(k)];
        c.points[k].normalImpulse = impulses[static_cast<std::size_t>(k)];
        c.points[k].tangentImpulse = 0.5 * impulses[static_cast<std::size_t>(k)] - 0.25;
    }
    return c;
}

/// A box of half extents `half`.
RigidBody box(Vec2 half) {
    RigidBody b;
    b.shape = BodyShape::box;
    b.halfExtents = half;
    return b;
}

/// The same contact as found at the start of the next step: impulses zero, not carried.
RigidContact fresh(RigidContact c) {
    for (RigidContactPoint& p : c.points) {
        p.normalImpulse = p.tangentImpulse = 0.0;
        p.carried = false;
    }
    return c;
}

} // namespace

TEST_CASE("a rigid contact point found again next step gets its impulses back", "[rigid][warmstart]") {
    // Random pairs and features, looked up again in a shuffled order: each gets exactly its own impulses.
    std::mt19937_64 rng(5);
    std::uniform_int_distribution<int> index(0, 40);
    std::uniform_real_distribution<double> impulse(0.01, 3.0);
    for (int round = 0; round < 20; ++round) {
        std::vector<RigidContact> last;
        for (int k = 0; k < 60; ++k) {
            const BodySide a{index(rng), true}, b{index(rng), index(rng) % 2 == 0};
            last.push_back(contact(a, b, {static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(0x100 + k)},
                                   {impulse(rng), impulse(rng)}));
        }
        RigidContactCache cache;
        cache.store(last);
        std::vector<RigidContact> next;
        for (const RigidContact& c : last) next.push_back(fresh(c));
        std::shuffle(next.begin(), next.end(), rng);
        cache.apply(next);
        for (const RigidContact& c : next)
            for (int k = 0; k < c.count; ++k) {
                // The contact it came from (pairs repeat, each with features of its own: match all three).
                double expectedNormal = -1.0, expectedTangent = 0.0;
                for (const RigidContact& old : last)
                    for (int j = 0; j < old.count; ++j)
                        if (old.a.index == c.a.index && old.b.index == c.b.index && old.b.rigid == c.b.rigid &&
                            old.points[j].feature == c.points[k].feature) {
                            expectedNormal = old.points[j].normalImpulse;
                            expectedTangent = old.points[j].tangentImpulse;
                        }
                REQUIRE(expectedNormal > 0.0);
                CHECK(c.points[k].normalImpulse == expectedNormal);
                CHECK(c.points[k].tangentImpulse == expectedTangent);
                CHECK(c.points[k].carried);
            }
    }
}

TEST_CASE("rigid contacts stored colour by colour find their impulses again", "[rigid][warmstart]") {
    // As the stage stores them: the list in key order (body by body, rigid others before circles),
    // dealt into colours that each keep list order, a contact's two points in either feature order,
    // some points not pushing. Every pushing point must get its own impulses back, however many colours.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> impulse(0.01, 3.0), unit(0.0, 1.0);
    for (int colours = 1; colours <= 14; ++colours) {
        std::vector<RigidContact> list;
        for (int a = 0; a < 50; ++a)
            for (int other = 0; other < 4; ++other) {
                const bool rigid = other < 2;
                const std::uint32_t f0 = static_cast<std::uint32_t>(7 * a + other), f1 = f0 + 0x1000;
                const bool swapped = unit(rng) < 0.5;
                list.push_back(contact({a, true}, {rigid ? a + 1 + other : 3 * a + other, rigid},
                                       {swapped ? f1 : f0, swapped ? f0 : f1},
                                       {unit(rng) < 0.2 ? 0.0 : impulse(rng), impulse(rng)}));
            }
        std::vector<RigidContact> coloured;
        std::vector<int> place(list.size());
        for (int c = 0; c < colours; ++c)
            for (std::size_t k = static_cast<std::size_t>(c); k < list.size(); k += static_cast<std::size_t>(colours)) {
                place[k] = static_cast<int>(coloured.size());
                coloured.push_back(list[k]);
            }
        // Stored as the stage stores them (visiting the list's order through `place`), and without it.
        const bool withPlaces = colours % 2 == 1;
        RigidContactCache cache;
        if (withPlaces) cache.store(coloured, place);
        else cache.store(coloured);
        std::vector<RigidContact> next;
        for (const RigidContact& c : list) next.push_back(fresh(c));
        cache.apply(next);
        int found = 0;
        for (std::size_t k = 0; k < list.size(); ++k)
            for (int j = 0; j < list[k].count; ++j) {
                const RigidContactPoint &was = list[k].points[j], &now = next[k].points[j];
                INFO("colours " << colours << ", contact " << k << ", point " << j);
                CHECK(now.normalImpulse == was.normalImpulse);
                CHECK(now.tangentImpulse == (was.normalImpulse > 0.0 ? was.tangentImpulse : 0.0));
                found += now.carried ? 1 : 0;
            }
        CHECK(found > 300);
    }
}

TEST_CASE("rigid contacts stored by the workers find their impulses again", "[rigid][warmstart][workers]") {
    // A list long enough for the workers to share the store (chunks of 512 contacts), colour ordered,
    // stored with 1 to 3 workers: every pushing point gets its own impulses back. In some rounds one
    // pair appears as two contacts in a row (features of their own), where the list is not in key
    // order: its feature between the first's two (one swap mends that, unless a seam lies between) or
    // below both (only a sort mends that), placed before, on and after a chunk's seam.
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> impulse(0.01, 3.0), unit(0.0, 1.0);
    for (const int repeatAt : {-1, 511, 512, 1023, 1024, 1500})
        for (const bool below : {false, true}) {
            std::vector<RigidContact> list;
            for (int a = 0; static_cast<int>(list.size()) < 2500; ++a)
                for (int other = 0; other < 4; ++other) {
                    const bool rigid = other < 2;
                    const std::uint32_t f0 = static_cast<std::uint32_t>(7 * a + other + 1), f1 = f0 + 0x100000;
                    const bool swapped = unit(rng) < 0.5;
                    const BodySide b{rigid ? a + 1 + other : 3 * a + other, rigid};
                    list.push_back(contact({a, true}, b, {swapped ? f1 : f0, swapped ? f0 : f1},
                                           {unit(rng) < 0.2 ? 0.0 : impulse(rng), impulse(rng)}));
                    if (static_cast<int>(list.size()) == repeatAt) // the same pair again
                        list.push_back(contact({a, true}, b, {below ? f0 - 1 : f0 + 0x80000}, {impulse(rng)}));
                }
            std::vector<RigidContact> coloured;
            std::vector<int> place(list.size());
            constexpr std::size_t kColours = 5;
            for (std::size_t c = 0; c < kColours; ++c)
                for (std::size_t k = c; k < list.size(); k += kColours) {
                    place[k] = static_cast<int>(coloured.size());
                    coloured.push_back(list[k]);
                }
            for (int workers = 1; workers <= 3; ++workers) {
                WorkerPool pool(workers);
                RigidContactCache cache;
                cache.store(coloured, place, &pool);
                std::vector<RigidContact> next;
                for (const RigidContact& c : list) next.push_back(fresh(c));
                cache.apply(next, &pool);
                int found = 0;
                for (std::size_t k = 0; k < list.size(); ++k)
                    for (int j = 0; j < list[k].count; ++j) {
                        const RigidContactPoint &was = list[k].points[j], &now = next[k].points[j];
                        INFO("repeat at " << repeatAt << (below ? " below" : " between") << ", workers " << workers
                                          << ", contact " << k << ", point " << j);
                        REQUIRE(now.normalImpulse == was.normalImpulse);
                        REQUIRE(now.tangentImpulse == (was.normalImpulse > 0.0 ? was.tangentImpulse : 0.0));
                        found += now.carried ? 1 : 0;
                    }
                CHECK(found > 4000);
            }
        }
}

TEST_CASE("a rigid contact point of another pair or feature, or one that did not push, starts from zero",
          "[rigid][warmstart]") {
    RigidContactCache cache;
    const std::vector<RigidContact> last{contact({3, true}, {7, true}, {0x0201, 0x0210}, {2.0, 1.5}),
                                         contact({3, true}, {7, false}, {0x0201}, {0.0})};
    cache.store(last);
    // Same features on other pairs: body 7 as a circle instead of a rigid body (and back: the second
    // contact pushed nothing, so it is not remembered), another A, another B.
    std::vector<RigidContact> next{
        fresh(contact({3, true}, {7, false}, {0x0210}, {0.0})), fresh(contact({3, true}, {7, false}, {0x0201}, {0.0})),
        fresh(contact({4, true}, {7, true}, {0x0201}, {0.0})), fresh(contact({3, true}, {8, true}, {0x0201}, {0.0})),
        // The right pair with features it did not have (between and after its own).
        fresh(contact({3, true}, {7, true}, {0x0205}, {0.0})), fresh(contact({3, true}, {7, true}, {0x0211}, {0.0}))};
    cache.apply(next);
    for (const RigidContact& c : next) {
        CHECK(c.points[0].normalImpulse == 0.0);
        CHECK(c.points[0].tangentImpulse == 0.0);
        CHECK_FALSE(c.points[0].carried);
    }
    // The right pair and feature does find its impulses: the misses above were misses of the key.
    std::vector<RigidContact> same{fresh(contact({3, true}, {7, true}, {0x0210}, {0.0}))};
    cache.apply(same);
    CHECK(same[0].points[0].normalImpulse == 1.5);
    CHECK(same[0].points[0].carried);
}

TEST_CASE("a rigid contact that disappears for a step is not warm started when it comes back", "[rigid][warmstart]") {
    RigidContactCache cache;
    const RigidContact touching = contact({0, true}, {1, true}, {0x0200, 0x0201}, {1.0, 2.0});
    const RigidContact other = contact({2, true}, {5, false}, {0x0300}, {0.7});
    cache.store(std::vector<RigidContact>{touching, other});
    // A step in which the pair came apart: only the other contact is stored.
    cache.store(std::vector<RigidContact>{other});
    std::vector<RigidContact> back{fresh(touching), fresh(other)};
    cache.apply(back);
    CHECK(back[0].points[0].normalImpulse == 0.0);
    CHECK(back[0].points[1].normalImpulse == 0.0);
    CHECK_FALSE(back[0].points[0].carried);
    CHECK(back[1].points[0].normalImpulse == 0.7);
    // A step with no contacts at all forgets everything.
    cache.store(std::vector<RigidContact>{});
    std::vector<RigidContact> later{fresh(other)};
    cache.apply(later);
    CHECK(later[0].points[0].normalImpulse == 0.0);
}

TEST_CASE("a box sliding on the ground keeps each corner's impulses from step to step", "[rigid][warmstart]") {
    // The manifold's ids carry the features: the left corner's point is found again as the left
    // corner's, however far the box slid, so its impulse follows it and not the right corner's.
    const RoundedPolygon ground = makeRoundedPolygon(box({5.0, 0.5}), {0.0, 0.0}, 0.0);
    const RigidBody crate = box({0.4, 0.3});
    const auto step = [&](double x, double tilt) {
        const Manifold m = collideRoundedPolygons(ground, makeRoundedPolygon(crate, {x, 0.799}, tilt), 0.02);
        RigidContact c;
        c.a = {0, true};
        c.b = {1, true};
        c.normal = m.normal;
        c.count = m.count;
        for (int k = 0; k < m.count; ++k) c.points[k].feature = m.points[k].id;
        return std::make_pair(c, m);
    };
    RigidContactCache cache;
    auto [first, firstManifold] = step(-2.0, 0.0);
    REQUIRE(first.count == 2);
    for (int k = 0; k < 2; ++k)
        first.points[k].normalImpulse = firstManifold.points[k].point.x < -2.0 ? 3.0 : 1.0; // left, right
    cache.store(std::vector<RigidContact>{first});
    for (int n = 1; n <= 30; ++n) {
        auto [now, manifold] = step(-2.0 + 0.1 * n, 0.002 * (n % 3));
        REQUIRE(now.count == 2);
        std::vector<RigidContact> list{now};
        cache.apply(list);
        for (int k = 0; k < 2; ++k) {
            const bool left = manifold.points[k].point.x < -2.0 + 0.1 * n;
            CHECK(list[0].points[k].normalImpulse == (left ? 3.0 : 1.0));
            CHECK(list[0].points[k].carried);
        }
        cache.store(list);
    }
}
