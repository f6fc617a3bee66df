// Choosing the offscreen back end: the one asked for, or for auto EGL where it works and OSMesa
// otherwise. The choice depends only on what was built and what the machine offers, never on
// timing, so one machine always gets the same back end (and the run summary names it).
#include "offscreen_backends.hpp"

#include <exception>
#include <stdexcept>
#include <string>

namespace rube::render {

std::string_view glBackendName(GlBackend backend) {
    switch (backend) {
    case GlBackend::automatic: return "auto";
    case GlBackend::egl: return "egl";
    case GlBackend::osmesa: return "osmesa";
    }
    return "auto";
}

std::optional<GlBackend> glBackendFromName(std::string_view name) {
    for (GlBackend backend : {GlBackend::automatic, GlBackend::egl, GlBackend::osmesa}) {
        if (glBackendName(backend) == name) return backend;
    }
    return std::nullopt;
}

bool glBackendBuilt(GlBackend backend) {
    switch (backend) {
    case GlBackend::automatic: return true;
    case GlBackend::egl: return RUBE_HAVE_EGL != 0;
    case GlBackend::osmesa: return RUBE_HAVE_OSMESA != 0;
    }
    return false;
}

namespace {

std::unique_ptr<RenderContext> create(GlBackend backend, FrameSize size) {
    if (!glBackendBuilt(backend)) {
        const GlBackend other = backend == GlBackend::egl ? GlBackend::osmesa : GlBackend::egl;
        throw std::runtime_error(std::string(backend == GlBackend::egl ? "EGL" : "OSMesa") +
                                 ": this rube was built without it (cmake -DRUBE_" +
                                 (backend == GlBackend::egl ? "EGL" : "OSMESA") + "=OFF): use --gl " +
                                 std::string(glBackendName(other)) + " or --gl auto");
    }
#if RUBE_HAVE_EGL
    if (backend == GlBackend::egl) return createEglContext(size);
#endif
#if RUBE_HAVE_OSMESA
    if (backend == GlBackend::osmesa) return createOsmesaContext(size);
#endif
    throw std::logic_error("no offscreen back end");
}

} // namespace

std::unique_ptr<RenderContext> createOffscreenContext(FrameSize size, GlBackend backend) {
    if (size.width <= 0 || size.height <= 0) {
        throw std::invalid_argument("offscreen context: size " + std::to_string(size.width) + "x" +
                                    std::to_string(size.height) + " is empty");
    }
    if (backend != GlBackend::automatic) return create(backend, size);
    // auto: EGL first (it outlives OSMesa), OSMesa if EGL cannot start; both reasons if neither can.
    std::string reasons;
    for (GlBackend candidate : {GlBackend::egl, GlBackend::osmesa}) {
        if (!glBackendBuilt(candidate)) continue;
        try {
            return create(candidate, size);
        } catch (const std::exception& e) {
            reasons += (reasons.empty() ? "" : "; ") + std::string(e.what());
        }
    }
    throw std::runtime_error("no offscreen GL context: " + reasons);
}

} // namespace rube::render
