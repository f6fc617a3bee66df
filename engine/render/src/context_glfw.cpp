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

    bool closeRequested() const override { return glfwWindowShouldClose(window_) == GLFW_TRUE; }

private:
    GLFWwindow* window_ = nullptr;
    std::vector<std::uint8_t> scratch_;
};

} // namespace

std::unique_ptr<RenderContext> createWindowContext(FrameSize size, const WindowOptions& options) {
    return std::make_unique<WindowContext>(size, options);
}

} // namespace rube::render
