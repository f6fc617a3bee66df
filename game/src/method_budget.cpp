// The pair budget of the methods without a broadphase (see method_budget.hpp).
#include "method_budget.hpp"

#include <algorithm>

namespace rube::game {

std::int64_t pairTestsPerSearch(const SceneDesc& scene) {
    const auto dynamicBodies = static_cast<std::int64_t>(std::count_if(
        scene.bodies.begin(), scene.bodies.end(), [](const RigidBodyDef& b) { return b.motion == Motion::dynamic; }));
    const std::int64_t moving = static_cast<std::int64_t>(scene.dynamicCircleCount()) + dynamicBodies;
    const auto shapes = static_cast<std::int64_t>(scene.circles.size() + scene.segments.size() + scene.bodies.size());
    return moving * shapes; // at most 1e5 x 2e5 or so: far from overflow
}

std::string methodBudgetRefusal(const SceneDesc& scene, Method method) {
    if (method != Method::discrete && method != Method::turnBased && method != Method::exact) return "";
    const std::int64_t pairs = pairTestsPerSearch(scene);
    if (pairs <= kMaxPairTests) return "";
    return "method " + std::string(methodName(method)) + " tests every pair of shapes, and " +
           std::to_string(pairs / std::max<std::int64_t>(1, static_cast<std::int64_t>(scene.circles.size() +
                                                                                      scene.segments.size() +
                                                                                      scene.bodies.size()))) +
           " moving bodies among " +
           std::to_string(scene.circles.size() + scene.segments.size() + scene.bodies.size()) + " shapes make " +
           std::to_string(pairs) + " pair tests " + (method == Method::discrete ? "a step" : "a search") +
           ", more than the " + std::to_string(kMaxPairTests) + " it affords: use auto or solver";
}

} // namespace rube::game
