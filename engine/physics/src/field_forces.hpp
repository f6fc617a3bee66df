#pragma once
// Internal: the pass that turns a world's fields into velocity changes at the start of a step.

#include "rube/physics/body.hpp"
#include "rube/physics/fields.hpp"

#include <span>

namespace rube {

/// Changes the velocity of every dynamic circle by what the fields do to it over [time, time + dt].
/// `gravity` is needed because linear drag is integrated together with it (see fields.cpp).
void applyFields(std::span<Circle> circles, const Fields& fields, const AirDrag& airDrag, Vec2 gravity, double time,
                 double dt);

} // namespace rube
