// Contacts against turning segments: a solver body per contact, moving with the surface there.
#include "solver_turning.hpp"

namespace rube {

void TurningContacts::attach(std::span<ContactConstraint> contacts, std::span<const Circle> circles,
                             std::span<const Segment> segments, std::vector<SolverBody>& bodies,
                             std::vector<double>& inverseMass, std::vector<double>& omega,
                             std::vector<FrictionBody>& frictionBodies) {
    moved_.clear();
    const int circleCount = static_cast<int>(circles.size());
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        ContactConstraint& c = contacts[k];
        if (c.b < circleCount) continue;
        const Segment& s = segments[static_cast<std::size_t>(c.b - circleCount)];
        if (s.angularVelocity == 0.0) continue;
        // The contact point on the circle's surface, towards the segment: v + omega x r there (lecture 3).
        const Circle& circle = circles[static_cast<std::size_t>(c.a)];
        const Vec2 point = circle.position - c.normal * circle.radius;
        moved_.emplace_back(k, c.b);
        if (!frictionBodies.empty()) {
            const FrictionBody segmentSide =
                frictionBodies[static_cast<std::size_t>(c.b)]; // a belt's surface moves with it
            frictionBodies.push_back(segmentSide);
        }
        c.b = static_cast<int>(bodies.size());
        bodies.push_back(SolverBody{s.velocityAt(point), {}});
    }
    inverseMass.resize(bodies.size(), 0.0); // the surface is the segment's: infinite mass (lecture 3)
    if (!omega.empty()) omega.resize(bodies.size(), 0.0);
}

void TurningContacts::detach(std::span<ContactConstraint> contacts) {
    for (const auto& [k, body] : moved_) contacts[k].b = body;
    moved_.clear();
}

} // namespace rube
