// PLACEHOLDER: replaced by the real method. Moves dynamic bodies ballistically, no collisions.
#include "step_method.hpp"

namespace rube {
namespace {
class TurnBasedMethod final : public StepMethod {
public:
    void step(StepContext& ctx, double dt) override {
        for (Circle& c : ctx.circles) {
            if (c.motion == Motion::dynamic) c.velocity += ctx.def.gravity * dt;
            c.position += c.velocity * dt;
        }
    }
};
} // namespace
std::unique_ptr<StepMethod> makeTurnBasedMethod() { return std::make_unique<TurnBasedMethod>(); }
} // namespace rube
