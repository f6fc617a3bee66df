// Springs against the harmonic oscillator at 60 Hz under the solver (issue 21): an undamped spring
// of m = 1 kg, k = 100 N/m keeps the period 2 pi sqrt(m / k) within 0.1 % and its energy within
// 1 % over 100 periods; a damped one (zeta = 0.1) follows the envelope e^(-zeta omega t) within 1 %;
// one-sided springs only push or only pull.
#include "joint_test_world.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace rube;
using test::jointWorld;
using test::kPi;
using test::wheel;

namespace {

struct Oscillator {
    World world;
    JointEnd ball, other;
    JointId spring;
    double mass = 1.0; // the reduced mass of the pair
};

// A ball of 1 kg on a spring of rest length 2 m to the world at the origin (or to a second ball of
// `otherMass` there), stretched by `stretch` along x. No gravity unless `vertical`: then the spring
// hangs along y and gravity acts along it.
Oscillator makeOscillator(double k, double c, double stretch, double otherMass, bool vertical) {
    Oscillator o{jointWorld(vertical ? Vec2{0.0, -9.81} : Vec2{0.0, 0.0}), {}, {}, {}, 1.0};
    const Vec2 along = vertical ? Vec2{0.0, -1.0} : Vec2{1.0, 0.0};
    const double sag = vertical ? 9.81 / k : 0.0; // the equilibrium below the rest length
    o.ball = wheel(o.world, along * (2.0 + sag + stretch), 0.1, 1.0);
    if (otherMass > 0.0) {
        o.other = wheel(o.world, {0.0, 0.0}, 0.1, otherMass);
        o.mass = otherMass / (1.0 + otherMass);
    }
    JointDef d;
    d.kind = JointKind::spring;
    d.a = o.other;
    d.b = o.ball;
    d.restLength = 2.0;
    d.stiffness = k;
    d.damping = c;
    o.spring = o.world.addJoint(d);
    return o;
}

// Spring energy plus kinetic energy (and gravity's, measured from the start).
double energy(const Oscillator& o, double k, Vec2 startBall, Vec2 startOther) {
    const double stretch = o.world.jointCoordinate(o.spring) - 2.0;
    const Circle& ball = o.world.circle(o.ball.circle);
    double e = 0.5 * k * stretch * stretch + 0.5 * ball.velocity.lengthSquared();
    e -= o.world.def().gravity.dot(ball.position - startBall);
    if (!o.other.isWorld()) {
        const Circle& other = o.world.circle(o.other.circle);
        e += 0.5 * other.velocity.lengthSquared() / other.inverseMass;
        e -= o.world.def().gravity.dot(other.position - startOther) / other.inverseMass;
    }
    return e;
}

// Times at which the stretch crosses its mean going up, by linear interpolation between steps.
std::vector<double> upCrossings(const std::vector<double>& x, double mean, double dt) {
    std::vector<double> times;
    for (std::size_t i = 1; i < x.size(); ++i)
        if (x[i - 1] < mean && x[i] >= mean) times.push_back((i - 1 + (mean - x[i - 1]) / (x[i] - x[i - 1])) * dt);
    return times;
}

} // namespace

TEST_CASE("joints: an undamped spring keeps its period within 0.1 % and its energy within 1 % over 100 periods",
          "[joints][spring]") {
    const double k = GENERATE(100.0, 400.0, 25.0);
    // Hung from a fixed point, under gravity too; between two balls, without (a falling pair's energy
    // would measure the substeps' gravity, x0 + v0 t + g t (t + h) / 2, not the spring).
    const auto [otherMass,
                vertical] = GENERATE(table<double, bool>({{0.0, false}, {0.0, true}, {1.0, false}, {3.0, false}}));
    const double stretch = 0.5;
    Oscillator o = makeOscillator(k, 0.0, stretch, otherMass, vertical);
    const double omega = std::sqrt(k / o.mass), period = 2.0 * kPi / omega, dt = 1.0 / 60;
    const Vec2 start = o.world.circle(o.ball.circle).position;
    const Vec2 otherStart = o.other.isWorld() ? Vec2{} : o.world.circle(o.other.circle).position;
    const double e0 = energy(o, k, start, otherStart);
    const double mean = vertical ? 9.81 / k * (otherMass > 0.0 ? 0.0 : 1.0) : 0.0;
    std::vector<double> x{o.world.jointCoordinate(o.spring) - 2.0};
    double worstEnergy = 0.0;
    const int steps = static_cast<int>(std::ceil(100.5 * period / dt));
    for (int s = 0; s < steps; ++s) {
        o.world.step();
        x.push_back(o.world.jointCoordinate(o.spring) - 2.0);
        worstEnergy = std::max(worstEnergy, std::abs(energy(o, k, start, otherStart) - e0) / e0);
    }
    const std::vector<double> ups = upCrossings(x, mean, dt);
    REQUIRE(ups.size() >= 100);
    const double measured = (ups.back() - ups.front()) / static_cast<double>(ups.size() - 1);
    INFO("k " << k << " other " << otherMass << (vertical ? " vertical" : "") << ": period " << measured << " of "
              << period << ", energy off by " << worstEnergy * 100 << " %");
    CHECK(std::abs(measured - period) / period < 0.001);
    CHECK(worstEnergy < 0.01);
}

TEST_CASE("joints: a damped spring (zeta = 0.1) decays on the envelope e^(-zeta omega t) within 1 %",
          "[joints][spring]") {
    const double k = GENERATE(100.0, 50.0);
    const double zeta = 0.1, m = 1.0;
    const double c = 2.0 * zeta * std::sqrt(k * m);
    Oscillator o = makeOscillator(k, c, 0.5, 0.0, false);
    const double omega = std::sqrt(k / m), omegaD = omega * std::sqrt(1.0 - zeta * zeta), dt = 1.0 / 60;
    // x(t) = A e^(-zeta omega t) cos(omegaD t - phi) from x = A0, v = 0: A = A0 / cos(phi), tan(phi) = zeta omega /
    // omegaD.
    const double phi = std::atan2(zeta * omega, omegaD);
    const double amplitude = 0.5 / std::cos(phi);
    double worst = 0.0;
    for (int s = 1; s <= static_cast<int>(5 * 2 * kPi / omegaD / dt); ++s) {
        o.world.step();
        const double t = s * dt;
        const double expected = amplitude * std::exp(-zeta * omega * t) * std::cos(omegaD * t - phi);
        const double envelope = amplitude * std::exp(-zeta * omega * t);
        worst = std::max(worst, std::abs(o.world.jointCoordinate(o.spring) - 2.0 - expected) / envelope);
    }
    INFO("k " << k << ": off the damped solution by " << worst * 100 << " % of the envelope");
    CHECK(worst < 0.01);
}

TEST_CASE("joints: a one-sided spring only pushes or only pulls", "[joints][spring]") {
    for (const SpringSide side : {SpringSide::pushOnly, SpringSide::pullOnly}) {
        // Stretched: a pull-only spring pulls the ball back, a push-only one lets it fly on.
        Oscillator o = makeOscillator(100.0, 0.0, 0.5, 0.0, false);
        JointDef d = o.world.joint(o.spring).def;
        o.world.remove(o.spring);
        d.springSide = side;
        o.spring = o.world.addJoint(d);
        o.world.setVelocity(o.ball.circle, {1.0, 0.0});
        for (int s = 0; s < 6; ++s) o.world.step();
        const double vx = o.world.circle(o.ball.circle).velocity.x;
        if (side == SpringSide::pushOnly) CHECK(vx == 1.0);
        else CHECK(vx < 0.9);
    }
}

TEST_CASE("joints: a spring too stiff for the explicit step is solved implicitly and stays finite",
          "[joints][spring]") {
    // omega h = sqrt(1e7) / 480 = 6.6, past velocity Verlet's stability (2): the soft constraint takes it.
    Oscillator o = makeOscillator(1e7, 0.0, 0.01, 0.0, false);
    double widest = 0.0;
    for (int s = 0; s < 600; ++s) {
        o.world.step();
        widest = std::max(widest, std::abs(o.world.jointCoordinate(o.spring) - 2.0));
    }
    CHECK(o.world.stats().isolatedBodies == 0);
    CHECK(widest <= 0.01 + 1e-9); // it never swings wider than it started: the implicit spring loses energy
}
