#pragma once
// Internal: contacts of the soft-step solver against turning segments (rotating paddles). Not part of
// the public API.
//
// The solver gives every body one velocity, which serves a translating segment but not a turning one:
// its surface moves at v + omega x r, different at every contact. So each contact against a turning
// segment gets a solver body of its own, of infinite mass, moving with the segment's surface at the
// contact point (where the circle touches it at the start of the step). Its displacement over the step
// is then that point's straight-line motion: the contact's gap s = s0 + n . (dpA - dpB) closes as the
// paddle sweeps towards the ball, to first order in dt. Scenes without turning segments never enter this.

#include "solver_friction.hpp"
#include "solver_soft_step.hpp"

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

namespace rube {

/// The contacts pointed at a turning segment's surface for the substeps, and pointed back afterwards.
class TurningContacts {
public:
    /// For every contact against a segment that turns (solver bodies: circles, then segments), appends a
    /// body moving at the segment's velocity at the contact point and points the contact at it;
    /// `inverseMass` and `omega` grow with zeros alike (those bodies have infinite mass and never turn),
    /// and `frictionBodies`, when filled, with the segment's own (a turning belt's surface still moves).
    void attach(std::span<ContactConstraint> contacts, std::span<const Circle> circles,
                std::span<const Segment> segments, std::vector<SolverBody>& bodies, std::vector<double>& inverseMass,
                std::vector<double>& omega, std::vector<FrictionBody>& frictionBodies);
    /// Points every contact `attach` moved back at its segment (the warm-start cache and the impacts name it).
    void detach(std::span<ContactConstraint> contacts);

private:
    std::vector<std::pair<std::size_t, int>> moved_; ///< contact index, and the segment's solver body it had
};

} // namespace rube
