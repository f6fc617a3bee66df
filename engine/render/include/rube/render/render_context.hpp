#pragma once
/// RenderContext: a GL 3.3 core context and the framebuffer it draws into, offscreen or in a window.

#include "rube/render/camera.hpp"
#include "rube/render/image.hpp"
#include "rube/render/window_input.hpp"

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace rube::render {

/// Where frames are drawn. Deliberately narrow, so that each back end (OSMesa, EGL, a GLFW
/// window) only has to provide these few calls.
/// GL functions are loaded into one global table when a context is made, so a process draws
/// with one kind of context at a time (offscreen or window), though it may make several of that kind.
class RenderContext {
public:
    virtual ~RenderContext() = default;
    /// Makes this context current on the calling thread (GL calls go to it).
    virtual void makeCurrent() = 0;
    /// The framebuffer's size in pixels.
    virtual FrameSize size() const = 0;
    /// Waits for drawing to finish and copies the frame into `into` as RGB, top row first.
    virtual void readPixels(Image& into) = 0;
    /// Shows the frame: swaps a window's buffers and handles its events; offscreen, nothing.
    virtual void present() = 0;
    /// Whether the user asked to close the window; an offscreen context never closes.
    virtual bool closeRequested() const { return false; }
    /// Sends the window's keyboard and mouse input to `listener` (nullptr: to no one) from now
    /// on; the listener must outlive the context or be unset. Offscreen there is no input.
    virtual void setInputListener(InputListener* /*listener*/) {}
    /// The back end that draws: "egl", "osmesa" or "glfw".
    virtual std::string_view backendName() const = 0;
};

/// The offscreen back ends. Both render on the CPU with Mesa's llvmpipe; OSMesa is gone from
/// Mesa 25.1 on, EGL without a window system is what replaces it.
enum class GlBackend {
    automatic, ///< EGL where it works, else OSMesa: decided by what was built and what the machine offers
    egl,       ///< EGL without a window system (Mesa's software device, else the surfaceless platform), into an FBO
    osmesa,    ///< Mesa's OSMesa
};

/// "auto", "egl" or "osmesa": the name `rube run --gl` takes.
std::string_view glBackendName(GlBackend backend);

/// The back end named `name` ("auto", "egl", "osmesa"); nothing for any other text.
std::optional<GlBackend> glBackendFromName(std::string_view name);

/// Whether this build has `backend` (cmake -DRUBE_EGL / -DRUBE_OSMESA); automatic is always there.
bool glBackendBuilt(GlBackend backend);

/// An offscreen context rendered on the CPU by Mesa's llvmpipe through `backend`: needs no display
/// and no GPU, and draws the same pixels on every run. Throws std::invalid_argument for an empty
/// size, std::runtime_error (one line: what was tried, what to install) when it cannot be made.
std::unique_ptr<RenderContext> createOffscreenContext(FrameSize size, GlBackend backend = GlBackend::automatic);

/// Options for a window; a caller changes only what it needs.
struct WindowOptions {
    std::string title = "rube";
    bool vsync = true; ///< wait for the display's refresh in present()
};

/// A window (GLFW) with a GL 3.3 core context. Only for interactive use: it needs a display,
/// and tests never create one. Throws std::runtime_error when there is no display.
std::unique_ptr<RenderContext> createWindowContext(FrameSize size, const WindowOptions& options = {});

} // namespace rube::render
