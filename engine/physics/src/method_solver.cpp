// PLACEHOLDER: replaced by the real method. Moves dynamic bodies ballistically, no collisions.
#include "step_method.hpp"

namespace rube {
namespace {
class SolverMethod final : public StepMethod {
public:
    void step(StepContext& ctx, double dt) override {
        for (Circle& c : ctx.circles) {
            if (c.motion == Motion::dynamic) c.velocity += ctx.def.gravity * dt;
            c.position += c.velocity * dt;
        }
    }
};
} // namespace
std::unique_ptr<StepMethod> makeSolverMethod() { return std::make_unique<SolverMethod>(); }
} // namespace rube
