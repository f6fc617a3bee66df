// Overlap and energy measurements for the probes.

#include "measure.hpp"

#include "rube/physics/collision.hpp"

#include <algorithm>
#include <vector>

namespace bench {

double largestOverlap(const Sim& sim, double radius, std::span<const LineSpec> lines) {
    const int n = sim.ballCount();
    std::vector<Vec2> centres(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) centres[static_cast<std::size_t>(i)] = sim.ball(i).position;
    std::sort(centres.begin(), centres.end(), [](Vec2 a, Vec2 b) { return a.x < b.x; });

    double largest = 0.0;
    const double reach = 2.0 * radius;
    for (std::size_t i = 0; i < centres.size(); ++i) {
        // Only balls within one diameter in x can overlap: stop the sweep there.
        for (std::size_t j = i + 1; j < centres.size() && centres[j].x - centres[i].x < reach; ++j) {
            if (const auto o = rube::circleCircleOverlap(centres[i], radius, centres[j], radius))
                largest = std::max(largest, o->depth);
        }
        for (const LineSpec& line : lines) {
            if (const auto o = rube::circleSegmentOverlap(centres[i], radius, line.a, line.b, line.radius))
                largest = std::max(largest, o->depth);
        }
    }
    return largest;
}

double energyHeight(const BallState& ball, double gravity) {
    return ball.position.y + ball.velocity.lengthSquared() / (2.0 * gravity);
}

} // namespace bench
