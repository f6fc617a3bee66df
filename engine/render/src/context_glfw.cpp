// The window context: GLFW with a GL 3.3 core context, for playing interactively. Nothing
// here runs unless a caller asks for a window, so tests and headless runs never touch GLFW.
#include "rube/render/render_context.hpp"

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE // glad provides the GL declarations
#include <GLFW/glfw3.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace rube::render {
namespace {

// GLFW's key codes in the renderer's words; letters are contiguous in both.
Key toKey(int key) {
    if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) return static_cast<Key>(static_cast<int>(Key::a) + (key - GLFW_KEY_A));
    switch (key) {
    case GLFW_KEY_SPACE: return Key::space;
    case GLFW_KEY_ESCAPE: return Key::escape;
    case GLFW_KEY_ENTER: return Key::enter;
    case GLFW_KEY_KP_ENTER: return Key::enter;
    case GLFW_KEY_BACKSPACE: return Key::backspace;
    case GLFW_KEY_DELETE: return Key::deleteKey;
    case GLFW_KEY_TAB: return Key::tab;
    case GLFW_KEY_LEFT: return Key::left;
    case GLFW_KEY_RIGHT: return Key::right;
    case GLFW_KEY_UP: return Key::up;
    case GLFW_KEY_DOWN: return Key::down;
    case GLFW_KEY_LEFT_BRACKET: return Key::leftBracket;
    case GLFW_KEY_RIGHT_BRACKET: return Key::rightBracket;
    case GLFW_KEY_LEFT_CONTROL: return Key::control;
    case GLFW_KEY_RIGHT_CONTROL: return Key::control;
    default: return Key::other;
    }
}

MouseButton toButton(int button) {
    switch (button) {
    case GLFW_MOUSE_BUTTON_LEFT: return MouseButton::left;
    case GLFW_MOUSE_BUTTON_RIGHT: return MouseButton::right;
    case GLFW_MOUSE_BUTTON_MIDDLE: return MouseButton::middle;
    default: return MouseButton::other;
    }
}

std::string lastGlfwError() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description != nullptr ? description : "no reason given";
}

class WindowContext final : public RenderContext {
public:
    WindowContext(FrameSize size, const WindowOptions& options) {
        if (glfwInit() != GLFW_TRUE) {
            throw std::runtime_error("GLFW could not start (is there a display?): " + lastGlfwError());
        }
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
        glfwWindowHint(GLFW_DEPTH_BITS, 0);
        glfwWindowHint(GLFW_STENCIL_BITS, 0);
        window_ = glfwCreateWindow(size.width, size.height, options.title.c_str(), nullptr, nullptr);
        if (window_ == nullptr) {
            std::string reason = lastGlfwError();
            glfwTerminate();
            throw std::runtime_error("GLFW could not open a " + std::to_string(size.width) + "x" +
                                     std::to_string(size.height) + " window with GL 3.3 core: " + reason);
        }
        glfwMakeContextCurrent(window_);
        if (gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress)) == 0) {
            glfwDestroyWindow(window_);
            glfwTerminate();
            throw std::runtime_error("glad could not load the GL 3.3 core functions through GLFW");
        }
        glfwSwapInterval(options.vsync ? 1 : 0);
        glfwSetWindowUserPointer(window_, this);
        installCallbacks();
    }

    ~WindowContext() override {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }

    void makeCurrent() override {
        if (glfwGetCurrentContext() != window_) glfwMakeContextCurrent(window_);
    }

    FrameSize size() const override {
        // The framebuffer, not the window: on high-DPI screens they differ.
        FrameSize size;
        glfwGetFramebufferSize(window_, &size.width, &size.height);
        return size;
    }

    void readPixels(Image& into) override {
        makeCurrent();
        FrameSize frame = size();
        into.resize(frame.width, frame.height);
        const std::size_t row = static_cast<std::size_t>(frame.width) * 3;
        scratch_.resize(row * frame.height);
        glReadBuffer(GL_BACK); // the frame just drawn, before present() swaps it away
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, frame.width, frame.height, GL_RGB, GL_UNSIGNED_BYTE, scratch_.data());
        for (int y = 0; y < frame.height; ++y) {
            std::copy_n(scratch_.data() + row * static_cast<std::size_t>(frame.height - 1 - y), row, into.pixel(0, y));
        }
    }

    void present() override {
        glfwSwapBuffers(window_);
        glfwPollEvents();
    }

    std::string_view backendName() const override { return "glfw"; }

    bool closeRequested() const override { return glfwWindowShouldClose(window_) == GLFW_TRUE; }

    void setInputListener(InputListener* listener) override { listener_ = listener; }

private:
    static WindowContext& of(GLFWwindow* window) {
        return *static_cast<WindowContext*>(glfwGetWindowUserPointer(window));
    }

    // The callbacks only translate: GLFW's codes into the renderer's, window coordinates into
    // framebuffer pixels (they differ by the content scale on high-DPI screens).
    void installCallbacks() {
        glfwSetCursorPosCallback(window_, [](GLFWwindow* window, double x, double y) {
            WindowContext& self = of(window);
            if (!self.listener_) return;
            int windowWidth = 0, windowHeight = 0, frameWidth = 0, frameHeight = 0;
            glfwGetWindowSize(window, &windowWidth, &windowHeight);
            glfwGetFramebufferSize(window, &frameWidth, &frameHeight);
            const double sx = windowWidth > 0 ? static_cast<double>(frameWidth) / windowWidth : 1.0;
            const double sy = windowHeight > 0 ? static_cast<double>(frameHeight) / windowHeight : 1.0;
            self.listener_->cursorMoved(static_cast<float>(x * sx), static_cast<float>(y * sy));
        });
        glfwSetMouseButtonCallback(window_, [](GLFWwindow* window, int button, int action, int /*mods*/) {
            WindowContext& self = of(window);
            if (self.listener_) self.listener_->mouseButton(toButton(button), action == GLFW_PRESS);
        });
        glfwSetScrollCallback(window_, [](GLFWwindow* window, double /*dx*/, double dy) {
            WindowContext& self = of(window);
            if (self.listener_) self.listener_->scrolled(static_cast<float>(dy));
        });
        glfwSetKeyCallback(window_, [](GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
            WindowContext& self = of(window);
            if (!self.listener_) return;
            self.listener_->key(toKey(key), action == GLFW_PRESS    ? KeyAction::press
                                            : action == GLFW_REPEAT ? KeyAction::repeat
                                                                    : KeyAction::release);
        });
        glfwSetCharCallback(window_, [](GLFWwindow* window, unsigned int codePoint) {
            WindowContext& self = of(window);
            if (self.listener_) self.listener_->typed(static_cast<char32_t>(codePoint));
        });
    }

    InputListener* listener_ = nullptr;
    GLFWwindow* window_ = nullptr;
    std::vector<std::uint8_t> scratch_;
};

} // namespace

std::unique_ptr<RenderContext> createWindowContext(FrameSize size, const WindowOptions& options) {
    return std::make_unique<WindowContext>(size, options);
}

} // namespace rube::render
