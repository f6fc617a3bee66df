// The EGL offscreen context: EGL without a window system, the replacement Mesa recommends for
// OSMesa (removed in Mesa 25.1). A desktop GL 3.3 core context with no surface at all
// (EGL_KHR_surfaceless_context) draws into a framebuffer object of RGBA8 that readPixels reads
// back like OSMesa's buffer, so the renderer, its shaders and the frame writer are unchanged.
//
// The display is Mesa's software device (EGL_EXT_platform_device with EGL_MESA_device_software:
// llvmpipe, the same rasteriser OSMesa uses, so the same pixels on every machine), else the
// surfaceless platform (EGL_MESA_platform_surfaceless), which may pick a GPU's render node.
#include "offscreen_backends.hpp"
#include "rgba_rows.hpp"

#include <glad/gl.h> // before the EGL headers, which would otherwise pull in the system gl.h
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace rube::render {
namespace {

// What to install when EGL cannot start: the loader (libegl1), Mesa's EGL (libegl-mesa0) and
// its llvmpipe driver (libgl1-mesa-dri). libegl-dev pulls in only the first.
constexpr const char* kInstallHint = "install libegl1, libegl-mesa0 and libgl1-mesa-dri";

bool hasExtension(const char* list, std::string_view name) {
    if (list == nullptr) return false;
    std::string_view rest(list);
    while (!rest.empty()) {
        const std::size_t space = rest.find(' ');
        if (rest.substr(0, space) == name) return true;
        if (space == std::string_view::npos) break;
        rest.remove_prefix(space + 1);
    }
    return false;
}

std::string eglErrorText() {
    char text[32];
    std::snprintf(text, sizeof text, "EGL error 0x%04x", static_cast<unsigned>(eglGetError()));
    return text;
}

// Mesa's software device, if the EGL implementation lists one: EGL_NO_DISPLAY otherwise.
EGLDisplay softwareDeviceDisplay(std::string& tried) {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(client, "EGL_EXT_platform_device")) {
        tried += "EGL_EXT_platform_device (not offered)";
        return EGL_NO_DISPLAY;
    }
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto queryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
        eglGetProcAddress("eglQueryDeviceStringEXT"));
    auto platformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (queryDevices == nullptr || queryDeviceString == nullptr || platformDisplay == nullptr ||
        !queryDevices(16, devices, &count)) {
        tried += "EGL_EXT_platform_device (no devices)";
        return EGL_NO_DISPLAY;
    }
    for (EGLint i = 0; i < count; ++i) {
        if (hasExtension(queryDeviceString(devices[i], EGL_EXTENSIONS), "EGL_MESA_device_software"))
            return platformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
    }
    tried += "EGL_EXT_platform_device (" + std::to_string(count) + " devices, none EGL_MESA_device_software)";
    return EGL_NO_DISPLAY;
}

EGLDisplay surfacelessDisplay(std::string& tried) {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto platformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!hasExtension(client, "EGL_MESA_platform_surfaceless") || platformDisplay == nullptr) {
        tried += ", EGL_MESA_platform_surfaceless (not offered)";
        return EGL_NO_DISPLAY;
    }
    return platformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
}

// The first display that initialises, software device first. Throws with what was tried.
EGLDisplay openDisplay() {
    std::string tried;
    for (auto open : {softwareDeviceDisplay, surfacelessDisplay}) {
        const std::size_t before = tried.size();
        EGLDisplay display = open(tried);
        if (display == EGL_NO_DISPLAY) continue;
        EGLint major = 0, minor = 0;
        if (eglInitialize(display, &major, &minor)) return display;
        tried += std::string(before == 0 ? "" : ", ") +
                 (open == softwareDeviceDisplay ? "EGL_MESA_device_software" : "EGL_MESA_platform_surfaceless") +
                 " (eglInitialize: " + eglErrorText() + ")";
    }
    throw std::runtime_error("EGL: no display without a window system (tried " + tried + "): " + kInstallHint);
}

// The display is never terminated: it is shared by every context made from the same device
// (eglInitialize on it again is a no-op), and eglTerminate would unload Mesa's driver, whose state
// then could not even be named by a leak checker. It lives until exit, as OSMesa's state does.

class EglContext final : public RenderContext {
public:
    explicit EglContext(FrameSize size) : size_(size) {
        display_ = openDisplay();
        try {
            createContext();
            createFramebuffer();
        } catch (...) {
            release();
            throw;
        }
    }

    ~EglContext() override { release(); }

    void makeCurrent() override {
        if (eglGetCurrentContext() == context_) return;
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
            throw std::runtime_error("EGL could not make the offscreen context current: " + eglErrorText());
        }
    }

    FrameSize size() const override { return size_; }

    void readPixels(Image& into) override {
        makeCurrent();
        readRgbaFramebuffer(size_.width, size_.height, scratch_, into);
    }

    void present() override { glFlush(); }

    std::string_view backendName() const override { return "egl"; }

private:
    void createContext() {
        const char* extensions = eglQueryString(display_, EGL_EXTENSIONS);
        if (!hasExtension(extensions, "EGL_KHR_surfaceless_context")) {
            throw std::runtime_error(
                std::string("EGL: the display (") + vendor() +
                ") cannot make a context current without a surface (no EGL_KHR_surfaceless_context): " + kInstallHint);
        }
        if (!eglBindAPI(EGL_OPENGL_API)) {
            throw std::runtime_error(std::string("EGL: the display (") + vendor() + ") offers no desktop OpenGL (" +
                                     eglErrorText() + "): " + kInstallHint);
        }
        // Any config that renders desktop GL: nothing is drawn to an EGL surface, only to the FBO.
        const EGLint configAttributes[] = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint configs = 0;
        if (!eglChooseConfig(display_, configAttributes, &config, 1, &configs) || configs < 1) {
            throw std::runtime_error(std::string("EGL: the display (") + vendor() +
                                     ") has no config for desktop OpenGL: " + kInstallHint);
        }
        // clang-format off: name, value pairs
        const EGLint contextAttributes[] = {
            EGL_CONTEXT_MAJOR_VERSION,
            3,
            EGL_CONTEXT_MINOR_VERSION,
            3,
            EGL_CONTEXT_OPENGL_PROFILE_MASK,
            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
            EGL_NONE,
        };
        // clang-format on
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, contextAttributes);
        if (context_ == EGL_NO_CONTEXT) {
            throw std::runtime_error(std::string("EGL: no GL 3.3 core context on the display (") + vendor() + ", " +
                                     eglErrorText() + "): install libgl1-mesa-dri (Mesa's llvmpipe)");
        }
        makeCurrent();
        // glad keeps one global table of function pointers, loaded from the context made last.
        if (gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress)) == 0) {
            throw std::runtime_error("glad could not load the GL 3.3 core functions through EGL");
        }
    }

    // The colour buffer: a core context without a surface has no default framebuffer.
    void createFramebuffer() {
        glGenRenderbuffers(1, &colour_);
        glBindRenderbuffer(GL_RENDERBUFFER, colour_);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, size_.width, size_.height);
        glGenFramebuffers(1, &framebuffer_);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
        if (const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER); status != GL_FRAMEBUFFER_COMPLETE) {
            char text[96];
            std::snprintf(text, sizeof text, "EGL: a %dx%d RGBA8 framebuffer is incomplete (status 0x%04x)",
                          size_.width, size_.height, static_cast<unsigned>(status));
            throw std::runtime_error(text);
        }
    }

    const char* vendor() const {
        const char* text = eglQueryString(display_, EGL_VENDOR);
        return text != nullptr ? text : "unknown vendor";
    }

    void release() {
        if (context_ != EGL_NO_CONTEXT) {
            if (eglGetCurrentContext() == context_ ||
                eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
                if (framebuffer_ != 0) glDeleteFramebuffers(1, &framebuffer_);
                if (colour_ != 0) glDeleteRenderbuffers(1, &colour_);
            }
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            eglDestroyContext(display_, context_);
            context_ = EGL_NO_CONTEXT;
        }
        eglReleaseThread();
    }

    FrameSize size_;
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    GLuint framebuffer_ = 0;
    GLuint colour_ = 0;
    std::vector<std::uint8_t> scratch_; // glReadPixels lands here before the flip
};

} // namespace

std::unique_ptr<RenderContext> createEglContext(FrameSize size) { return std::make_unique<EglContext>(size); }

} // namespace rube::render
