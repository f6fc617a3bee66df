// Mass properties of rigid bodies.
#include "rube/physics/rigid_body.hpp"

#include <numbers>

namespace rube {

double momentOfInertia(BodyShape shape, Vec2 halfExtents, double mass) {
    const double hx = halfExtents.x;
    const double hy = halfExtents.y;
    if (shape == BodyShape::box) {
        const double w = 2.0 * hx, h = 2.0 * hy;
        return mass * (w * w + h * h) / 12.0; // I = m (w^2 + h^2) / 12
    }
    // Capsule of core length 2 hx and radius r = hy, uniform density: a 2hx x 2r rectangle and two
    // half discs whose centroids sit 4r/(3 pi) beyond the core ends.
    const double r = hy;
    const double rectArea = 4.0 * hx * r;
    const double discArea = std::numbers::pi * r * r;
    const double density = mass / (rectArea + discArea);
    const double mRect = density * rectArea;
    const double mDisc = density * discArea; // both halves together
    const double iRect = mRect * (4.0 * hx * hx + 4.0 * r * r) / 12.0;
    // Each half disc about its own flat edge: m r^2 / 2 (half of m_half r^2 / 2 for the full disc of
    // twice the mass); shifted to the centre: about the centroid c = 4r/(3 pi) then out to hx + c.
    const double c = 4.0 * r / (3.0 * std::numbers::pi);
    const double iHalfAtCentroid = 0.5 * mDisc * (0.5 * r * r) - 0.5 * mDisc * c * c;
    const double d = hx + c;
    const double iDiscs = 2.0 * (iHalfAtCentroid + 0.5 * mDisc * d * d);
    return iRect + iDiscs;
}

} // namespace rube
