// The rigid contacts' colours, their blocks and the two-lane sweep (issue 26): a colour never holds
// two contacts of one movable body, the colouring is the greedy one in list order, and the blocks'
// warm start, approach measure, arms and sweep (SSE2, or the plain pair of doubles without it) give
// the same bits as the one-contact-at-a-time forms over the list, over random contacts, masses,
// arms, anchors, turns, gaps and impulses.
#include "rigid_colours.hpp"
#include "rigid_contact_blocks.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace rube;

namespace {

struct Scene {
    std::vector<RigidState> bodies;
    std::vector<RigidContact> contacts;
};

/// `n` bodies (about a fifth immovable, as the ground and fixed boxes are) and `m` contacts between
/// random pairs of them, with everything the sweep reads drawn at random; tag = list position.
Scene randomScene(std::mt19937_64& rng, int n, int m) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> pick(0, n - 1);
    Scene s;
    s.bodies.resize(static_cast<std::size_t>(n));
    for (RigidState& b : s.bodies) {
        b.velocity = {u(rng) * 3.0, u(rng) * 3.0};
        b.omega = u(rng) * 2.0;
        b.displacement = {u(rng) * 0.01, u(rng) * 0.01};
        b.turn = u(rng) * 0.1;
        b.turnRotation = {std::cos(b.turn), std::sin(b.turn)};
        if (u(rng) > 0.8) b.velocity = {-0.0, 0.0};
        if (u(rng) > -0.6) {
            b.inverseMass = 0.5 + u(rng) * 0.4;
            b.inverseInertia = u(rng) > -0.5 ? 2.0 + u(rng) : 0.0;
        } else {
            b.omega = 0.0;
        }
    }
    for (int k = 0; k < m; ++k) {
        RigidContact c;
        c.bodyA = pick(rng);
        do c.bodyB = pick(rng);
        while (c.bodyB == c.bodyA);
        const double angle = u(rng) * 3.14159;
        c.normal = {std::cos(angle), std::sin(angle)};
        c.tangent = c.normal.perpendicular();
        c.friction = u(rng) > 0.0 ? 0.6 + 0.3 * u(rng) : 0.0;
        c.tangentSpeed = u(rng) > 0.5 ? 2.0 * u(rng) : 0.0; // some run on a conveyor's belt
        c.stacking = u(rng) > 0.3;                          // a stack's softness, or the others'
        c.againstFixed = s.bodies[static_cast<std::size_t>(c.bodyA)].inverseMass == 0.0 ||
                         s.bodies[static_cast<std::size_t>(c.bodyB)].inverseMass == 0.0;
        c.count = u(rng) > -0.3 ? 2 : 1;
        for (int j = 0; j < c.count; ++j) {
            RigidContactPoint& p = c.points[j];
            p.anchorA = {u(rng) * 0.5, u(rng) * 0.5};
            p.anchorB = {u(rng) * 0.5, u(rng) * 0.5};
            p.armA = {u(rng) * 0.5, u(rng) * 0.5};
            p.armB = {u(rng) * 0.5, u(rng) * 0.5};
            p.baseSeparation = u(rng) * 0.02; // both speculative gaps and overlaps
            p.normalMass = 0.5 + u(rng) * 0.3;
            p.tangentMass = 0.5 + u(rng) * 0.3;
            p.normalImpulse = u(rng) > 0.0 ? 0.2 + 0.1 * u(rng) : 0.0;
            p.tangentImpulse = 0.05 * u(rng);
            p.deliveredNormal = 0.3 * u(rng);
            p.deliveredTangent = u(rng) > 0.0 ? 0.1 * u(rng) : 0.0;
            p.maxNormalImpulse = u(rng) > 0.0 ? 0.3 : 0.0;
            // The edges where max, min and clamp differ by operand order: signed zeros and NaN.
            const double edge = u(rng);
            if (edge > 0.8) {
                p.normalImpulse = p.tangentImpulse = -0.0;
                p.normalMass = p.tangentMass = 0.0;
            } else if (edge < -0.97) {
                p.baseSeparation = std::numeric_limits<double>::quiet_NaN();
            } else if (edge < -0.94) {
                p.tangentMass = std::numeric_limits<double>::quiet_NaN();
            }
        }
        c.points[0].feature = static_cast<std::uint32_t>(k); // the tag
        s.contacts.push_back(c);
    }
    return s;
}

bool movable(const Scene& s, int body) { return s.bodies[static_cast<std::size_t>(body)].inverseMass > 0.0; }

bool shareMovable(const Scene& s, const RigidContact& x, const RigidContact& y) {
    const auto shared = [&](int body) { return movable(s, body) && (body == y.bodyA || body == y.bodyB); };
    return shared(x.bodyA) || shared(x.bodyB);
}

/// The same bits, or both NaN (a NaN's sign may follow how the compiler negated it; the body is
/// isolated either way).
bool sameBits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0 || (std::isnan(x) && std::isnan(y)); }

/// Every number the sweep writes, bit for bit.
void requireSameBits(const Scene& x, const Scene& y) {
    for (std::size_t i = 0; i < x.bodies.size(); ++i) {
        INFO("body " << i);
        REQUIRE(sameBits(x.bodies[i].velocity.x, y.bodies[i].velocity.x));
        REQUIRE(sameBits(x.bodies[i].velocity.y, y.bodies[i].velocity.y));
        REQUIRE(sameBits(x.bodies[i].omega, y.bodies[i].omega));
    }
    for (std::size_t k = 0; k < x.contacts.size(); ++k)
        for (int j = 0; j < x.contacts[k].count; ++j) {
            INFO("contact " << k << " point " << j);
            const RigidContactPoint &p = x.contacts[k].points[j], &q = y.contacts[k].points[j];
            REQUIRE(sameBits(p.normalImpulse, q.normalImpulse));
            REQUIRE(sameBits(p.tangentImpulse, q.tangentImpulse));
            REQUIRE(sameBits(p.deliveredNormal, q.deliveredNormal));
            REQUIRE(sameBits(p.deliveredTangent, q.deliveredTangent));
            REQUIRE(sameBits(p.maxNormalImpulse, q.maxNormalImpulse));
            REQUIRE(sameBits(p.armA.x, q.armA.x));
            REQUIRE(sameBits(p.armA.y, q.armA.y));
            REQUIRE(sameBits(p.armB.x, q.armB.x));
            REQUIRE(sameBits(p.armB.y, q.armB.y));
            REQUIRE(sameBits(p.approachSpeed, q.approachSpeed));
            REQUIRE(p.touchSubstep == q.touchSubstep);
        }
}

RigidContactSoftness softness() {
    RigidContactSoftness s;
    s.movable = makeSoftness(60.0, 10.0, 1.0 / 480.0);
    s.fixed = makeSoftness(120.0, 10.0, 1.0 / 480.0);
    s.stackMovable = makeSoftness(70.0, 10.0, 1.0 / 480.0);
    s.stackFixed = makeSoftness(140.0, 10.0, 1.0 / 480.0);
    return s;
}

} // namespace

TEST_CASE("no colour holds two contacts of one movable body, and each contact takes the first colour free",
          "[rigid][colours]") {
    std::mt19937_64 rng(26);
    for (int round = 0; round < 40; ++round) {
        const int n = 3 + round * 5, m = 2 + round * 17;
        Scene s = randomScene(rng, n, m);
        const std::vector<RigidContact> list = s.contacts;
        RigidColours colours;
        colours.build(s.contacts, s.bodies);
        REQUIRE(s.contacts.size() == list.size());
        REQUIRE(colours.start(0) == 0);
        REQUIRE(colours.start(kRigidColours + 1) == static_cast<int>(list.size()));
        std::vector<int> colourOf(list.size(), -1);
        for (int colour = 0; colour <= kRigidColours; ++colour)
            for (int k = colours.start(colour); k < colours.start(colour + 1); ++k) {
                const RigidContact& c = s.contacts[static_cast<std::size_t>(k)];
                colourOf[c.points[0].feature] = colour;
                // List order within a colour.
                if (k > colours.start(colour))
                    REQUIRE(s.contacts[static_cast<std::size_t>(k - 1)].points[0].feature < c.points[0].feature);
            }
        for (std::size_t k = 0; k < list.size(); ++k) {
            INFO("round " << round << " contact " << k << " colour " << colourOf[k]);
            REQUIRE(colourOf[k] >= 0);
            // Greedy: every lower colour already held an earlier contact sharing a movable body with it.
            for (int lower = 0; lower < colourOf[k] && lower < kRigidColours; ++lower) {
                bool blocked = false;
                for (std::size_t j = 0; j < k; ++j)
                    blocked = blocked || (colourOf[j] == lower && shareMovable(s, list[j], list[k]));
                REQUIRE(blocked);
            }
            // Nothing of its own colour (but the overflow) shares a movable body with it.
            if (colourOf[k] < kRigidColours)
                for (std::size_t j = 0; j < list.size(); ++j)
                    if (j != k && colourOf[j] == colourOf[k]) REQUIRE_FALSE(shareMovable(s, list[j], list[k]));
        }
    }
}

TEST_CASE("contacts past the last colour go to the overflow, in list order", "[rigid][colours]") {
    // A star: one movable body touching 20 others, so every contact needs a colour of its own.
    for (const int spokes : {kRigidColours - 1, kRigidColours, kRigidColours + 8}) {
        Scene s;
        s.bodies.resize(static_cast<std::size_t>(spokes + 1));
        for (RigidState& b : s.bodies) b.inverseMass = 1.0;
        for (int k = 0; k < spokes; ++k) {
            RigidContact c;
            c.bodyA = 0;
            c.bodyB = k + 1;
            c.points[0].feature = static_cast<std::uint32_t>(k);
            s.contacts.push_back(c);
        }
        RigidColours colours;
        colours.build(s.contacts, s.bodies);
        const int coloured = std::min(spokes, kRigidColours);
        REQUIRE(colours.overflow() == spokes - coloured);
        for (int k = 0; k < spokes; ++k)
            REQUIRE(s.contacts[static_cast<std::size_t>(k)].points[0].feature == static_cast<std::uint32_t>(k));
    }
}

namespace {

/// Every form of the block passes: AVX-512VL's registers (the best where the processor has them),
/// AVX, and the build's own target.
constexpr LaneCode kCodes[] = {LaneCode::best, LaneCode::avx, LaneCode::portable};
const char* nameOf(LaneCode code) {
    return code == LaneCode::best ? " best" : code == LaneCode::avx ? " avx" : " portable";
}

} // namespace

TEST_CASE("a colour solved four contacts at a time in blocks gives the bits of the contacts solved one by one",
          "[rigid][colours][determinism]") {
    if (!blocksRunAvx()) WARN("no AVX here: every code is the portable code");
    else if (!blocksRunAvx512()) WARN("no AVX-512VL here: the best code is the AVX code");
    std::mt19937_64 rng(2026);
    for (int round = 0; round < 60; ++round) {
        const int n = 2 + round * 4, m = 1 + round * 9;
        Scene start = randomScene(rng, n, m);
        RigidColours colours;
        colours.build(start.contacts, start.bodies);
        for (const LaneCode code : kCodes)
            for (const bool useBias : {true, false}) {
                INFO("round " << round << (useBias ? " biased" : " relax") << nameOf(code));
                // Three sweeps each, so warm impulses and moved velocities feed the next.
                Scene one = start, wide = start;
                RigidBlocks blocks;
                blocks.pack(wide.contacts, colours, wide.bodies);
                refreshArms(one.contacts, one.bodies);
                refreshBlockArms(blocks.all(), wide.bodies, code);
                for (int sweep = 0; sweep < 3; ++sweep) {
                    solveRigidContacts(one.contacts, one.bodies, softness(), 1.0 / 480.0, useBias);
                    solveBlocks(blocks.all(), wide.bodies, softness(), 1.0 / 480.0, useBias, false, code);
                }
                blocks.unpack(wide.contacts);
                requireSameBits(one, wide);
            }
    }
}

TEST_CASE("the blocks' warm start, approach measure and arms give the bits of the contacts' own",
          "[rigid][colours][determinism]") {
    std::mt19937_64 rng(1226);
    for (int round = 0; round < 40; ++round) {
        const int n = 2 + round * 4, m = 1 + round * 9;
        Scene start = randomScene(rng, n, m);
        RigidColours colours;
        colours.build(start.contacts, start.bodies);
        // A body spinning past the warm start's limit (0.3 rad in the substep) starts its contacts cold.
        const double h = 1.0 / 480.0, maxTurn = 0.3;
        if (n > 3) start.bodies[1].omega = 200.0;
        for (const LaneCode code : kCodes) {
            Scene from = start;
            for (int substep = 0; substep < 3; ++substep) {
                INFO("round " << round << " substep " << substep << nameOf(code));
                Scene one = from, wide = from;
                RigidBlocks blocks;
                blocks.pack(wide.contacts, colours, wide.bodies);
                // In the stage's order: arms, approach, warm start (colour after colour), arms after a move.
                refreshArms(one.contacts, one.bodies);
                refreshBlockArms(blocks.all(), wide.bodies, code);
                measureApproach(one.contacts, one.bodies, substep);
                warmStartRigidContacts(one.contacts, one.bodies, h, maxTurn);
                measureBlockApproach(blocks.all(), wide.contacts, wide.bodies, substep, code);
                warmStartBlocks(blocks.all(), wide.bodies, h, maxTurn, code);
                for (RigidState& b : one.bodies) b.turnRotation = {b.turnRotation.y, -b.turnRotation.x};
                for (RigidState& b : wide.bodies) b.turnRotation = {b.turnRotation.y, -b.turnRotation.x};
                refreshArms(one.contacts, one.bodies);
                refreshBlockArms(blocks.all(), wide.bodies, code);
                blocks.unpack(wide.contacts);
                requireSameBits(one, wide);
                from = one;
            }
        }
    }
}
