// Registries of engines and scenes: each adapter and each scene file adds itself, so a new
// scene is a new file and never an edit of a list elsewhere (the bench is one executable, so
// the linker keeps every registering object).

#include "scene.hpp"
#include "sim.hpp"

namespace bench {

std::vector<Engine>& engines() {
    static std::vector<Engine> all; // function-local: safe whatever the static-initialisation order
    return all;
}

bool registerEngine(Engine engine) {
    engines().push_back(std::move(engine));
    return true;
}

std::vector<Scene>& scenes() {
    static std::vector<Scene> all;
    return all;
}

bool registerScene(Scene scene) {
    scenes().push_back(std::move(scene));
    return true;
}

} // namespace bench
