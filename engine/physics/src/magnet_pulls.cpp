// The magnets' kicks a step takes back (see magnet_pulls.hpp).
#include "magnet_pulls.hpp"

namespace rube {

double MagnetPulls::restingSpeed(std::size_t i, Vec2 gravity, double dt) const {
    const Vec2 k = kick(i);
    return k == Vec2{} ? 0.0 : 2.0 * (gravity * dt + k).length() + 1e-3;
}

void MagnetPulls::finish(std::span<Circle> circles, std::span<const Magnet> magnets, double dt) const {
    for (std::size_t i = 0; i < kicks_.size(); ++i)
        if (kicks_[i] != Vec2{}) circles[i].velocity += (magnetKick(magnets, circles[i], dt) - kicks_[i]) * 0.5;
}

} // namespace rube
