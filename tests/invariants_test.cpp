// Physics invariants over 10,000 random scenes per method (seeded, so every run sees the same
// scenes): no NaN or infinity, nothing leaves a closed box, momentum kept in isolated collisions,
// energy never gained by the exact method with C <= 1, and every step within the event cap.
// RUBE_INVARIANT_SCENES sets another count: the sanitizer run (tests/sanitizers/run.sh) plays the
// first 2,000, where every step costs several times more.
#include "rube/physics/world.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

using namespace rube;

namespace {

// The scenes per method: 10,000, or RUBE_INVARIANT_SCENES when it is a positive count.
const int kScenes = [] {
    const char* text = std::getenv("RUBE_INVARIANT_SCENES");
    const int n = text == nullptr ? 0 : std::atoi(text);
    return n > 0 ? n : 10'000;
}();
constexpr Method kMethods[] = {Method::discrete, Method::turnBased, Method::exact, Method::solver, Method::automatic};

// splitmix64: a tiny, portable generator (std's distributions differ between libraries).
class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    /// Uniform in [lo, hi): the top 53 bits as a double in [0, 1).
    double uniform(double lo, double hi) { return lo + (hi - lo) * (static_cast<double>(next() >> 11) * 0x1.0p-53); }
    int integer(int lo, int hi) { return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1)); }

private:
    std::uint64_t state_;
};

// The box: walls 0.05 m thick around [-3, 3] x [0, 6].
constexpr double kHalfWidth = 3.0, kHeight = 6.0, kWall = 0.05;

// A random closed box of 1 to 5 balls that do not overlap, at most 5 m/s (so even `discrete`,
// which tunnels above v dt = 2 (r + wall), stays below its limit for the whole fall).
World randomBox(Random& random, Method method) {
    WorldDef def;
    def.method = method;
    def.bounds = {{-kHalfWidth - 1.0, -1.0}, {kHalfWidth + 1.0, kHeight + 1.0}};
    World world(def);
    const Vec2 corners[] = {{-kHalfWidth, 0}, {kHalfWidth, 0}, {kHalfWidth, kHeight}, {-kHalfWidth, kHeight}};
    for (int i = 0; i < 4; ++i)
        world.addSegment({corners[i], corners[(i + 1) % 4], kWall, {random.uniform(0.0, 1.0), 0.0}, -1});
    const int count = random.integer(1, 5);
    std::vector<CircleDef> placed;
    for (int attempt = 0; attempt < 50 && static_cast<int>(placed.size()) < count; ++attempt) {
        CircleDef ball;
        ball.radius = random.uniform(0.1, 0.4);
        const double margin = ball.radius + kWall + 0.01;
        ball.position = {random.uniform(-kHalfWidth + margin, kHalfWidth - margin),
                         random.uniform(margin, kHeight - margin)};
        ball.velocity = Vec2::fromAngle(random.uniform(0.0, 6.283185307179586)) * random.uniform(0.0, 5.0);
        ball.mass = random.uniform(0.1, 5.0);
        ball.material = {random.uniform(0.0, 1.0), random.uniform(0.0, 0.8)};
        const bool clear = std::none_of(placed.begin(), placed.end(), [&](const CircleDef& o) {
            return o.position.distance(ball.position) < o.radius + ball.radius + 0.01;
        });
        if (clear) placed.push_back(ball);
    }
    for (const CircleDef& ball : placed) world.addCircle(ball);
    return world;
}

bool insideBox(const Circle& c) {
    return c.position.x > -kHalfWidth && c.position.x < kHalfWidth && c.position.y > 0.0 && c.position.y < kHeight;
}

double energy(const World& world) {
    double e = 0.0;
    for (const Circle& c : world.circles()) {
        if (c.inverseMass == 0.0) continue;
        const double m = 1.0 / c.inverseMass;
        e += 0.5 * m * c.velocity.lengthSquared() - m * world.def().gravity.dot(c.position);
    }
    return e;
}

} // namespace

TEST_CASE("invariants: 10,000 random boxes per method stay finite, closed and within the event cap", "[invariants]") {
    for (const Method method : kMethods) {
        Random random(0x5eed0000u + static_cast<unsigned>(method));
        int escapes = 0, nonFinite = 0, overCap = 0;
        for (int scene = 0; scene < kScenes; ++scene) {
            World world = randomBox(random, method);
            for (int step = 0; step < 30; ++step) {
                world.step();
                for (const Circle& c : world.circles()) {
                    if (!isFinite(c.position) || !isFinite(c.velocity) || !std::isfinite(c.angularVelocity))
                        ++nonFinite;
                    else if (!insideBox(c)) ++escapes;
                }
            }
            if (world.stats().maxEventsInStep > world.def().maxEventsPerStep) ++overCap;
        }
        CAPTURE(methodName(method));
        CHECK(nonFinite == 0);
        CHECK(escapes == 0);
        CHECK(overCap == 0);
    }
}

TEST_CASE("invariants: momentum is kept in 10,000 isolated two-ball collisions per method", "[invariants]") {
    for (const Method method : kMethods) {
        Random random(0xc0111de0u + static_cast<unsigned>(method));
        double worst = 0.0;
        int collided = 0;
        for (int scene = 0; scene < kScenes; ++scene) {
            WorldDef def;
            def.method = method;
            def.gravity = {};
            World world(def);
            CircleDef a, b;
            a.radius = random.uniform(0.1, 1.0);
            b.radius = random.uniform(0.1, 1.0);
            a.mass = random.uniform(0.1, 10.0);
            b.mass = random.uniform(0.1, 10.0);
            a.material = {random.uniform(0.0, 1.0), random.uniform(0.0, 1.0)};
            b.material = {random.uniform(0.0, 1.0), random.uniform(0.0, 1.0)};
            // b ahead of a, offset sideways by less than the sum of radii: they meet within the run.
            b.position = {a.radius + b.radius + random.uniform(0.1, 2.0),
                          random.uniform(-0.9, 0.9) * (a.radius + b.radius)};
            a.velocity = {random.uniform(3.0, 20.0), random.uniform(-0.5, 0.5)};
            b.velocity = {random.uniform(-3.0, 1.0), random.uniform(-0.5, 0.5)};
            world.addCircle(a);
            world.addCircle(b);
            const Vec2 before = a.velocity * a.mass + b.velocity * b.mass;
            for (int step = 0; step < 60; ++step) world.step();
            collided += world.stats().impacts + world.stats().restingContacts > 0 ? 1 : 0;
            const auto c = world.circles();
            const Vec2 after = c[0].velocity * a.mass + c[1].velocity * b.mass;
            worst = std::max(worst, (after - before).length() / before.length());
        }
        CAPTURE(methodName(method));
        CHECK(collided > kScenes * 9 / 10); // the scenes do test collisions
        CHECK(worst <= 1e-12);
    }
}

TEST_CASE("invariants: the exact method never gains energy with C <= 1 in 10,000 random boxes", "[invariants]") {
    Random random(0xe4e76e00u);
    double worstGain = 0.0;
    for (int scene = 0; scene < kScenes; ++scene) {
        World world = randomBox(random, Method::exact);
        const double start = energy(world);
        double scale = 1.0;
        for (const Circle& c : world.circles())
            if (c.inverseMass > 0.0)
                scale += std::abs(0.5 * c.velocity.lengthSquared() / c.inverseMass) + 9.81 * kHeight / c.inverseMass;
        for (int step = 0; step < 30; ++step) {
            world.step();
            worstGain = std::max(worstGain, (energy(world) - start) / scale);
        }
    }
    // Round-off of the exact integration: a few ulps of the total, never a real gain.
    CHECK(worstGain <= 1e-12);
}
