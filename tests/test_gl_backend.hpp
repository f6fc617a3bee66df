#pragma once
// The offscreen back end a screenshot test draws with: RUBE_TEST_GL=egl, osmesa or auto (unset:
// auto). tests/CMakeLists.txt registers every screenshot test once per back end built, so the
// goldens are checked under EGL and OSMesa alike with the same thresholds.

#include "rube/render/render_context.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace rube::test {

/// The back end named by RUBE_TEST_GL; throws for a name that is not one.
inline render::GlBackend testGlBackend() {
    const char* name = std::getenv("RUBE_TEST_GL");
    if (name == nullptr || *name == '\0') return render::GlBackend::automatic;
    const auto backend = render::glBackendFromName(name);
    if (!backend) throw std::runtime_error(std::string("RUBE_TEST_GL=") + name + ": expected auto, egl or osmesa");
    return *backend;
}

} // namespace rube::test
