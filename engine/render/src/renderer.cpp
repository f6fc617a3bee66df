// Renderer: one instanced draw of a unit quad per frame. The DrawList becomes ShapeInstances
// on the CPU (shape_instances.cpp); this file only moves them to GL and draws.
#include "rube/render/renderer.hpp"

#include "gl_program.hpp"
#include "shape_instance.hpp"
#include "shape_frag.hpp" // generated from assets/shaders/shape.frag
#include "shape_vert.hpp" // generated from assets/shaders/shape.vert

#include <cstddef>

namespace rube::render {

struct Renderer::Gpu {
    GLuint program = 0;
    GLuint vertexArray = 0;
    GLuint instanceBuffer = 0;
    GLint frameSizeLocation = -1;
    std::vector<ShapeInstance> instances; // reused every frame
};

namespace {

// Per-instance attributes, matching the `layout(location = n)` inputs of shape.vert.
void describeInstanceLayout() {
    constexpr GLsizei stride = sizeof(ShapeInstance);
    auto at = [](std::size_t offset) { return reinterpret_cast<const void*>(offset); };
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, stride, at(offsetof(ShapeInstance, geomA)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, at(offsetof(ShapeInstance, geomB)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride, at(offsetof(ShapeInstance, outlineWidth)));
    glEnableVertexAttribArray(3);
    glVertexAttribIPointer(3, 1, GL_UNSIGNED_INT, stride, at(offsetof(ShapeInstance, kindAndFlags)));
    glEnableVertexAttribArray(4);
    glVertexAttribPointer(4, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride, at(offsetof(ShapeInstance, fill)));
    glEnableVertexAttribArray(5);
    glVertexAttribPointer(5, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride, at(offsetof(ShapeInstance, outline)));
    for (GLuint location = 0; location <= 5; ++location) glVertexAttribDivisor(location, 1);
}

} // namespace

Renderer::Renderer(RenderContext& context) : context_(context), gpu_(std::make_unique<Gpu>()) {
    context_.makeCurrent();
    gpu_->program = linkProgram("shape", assets::shapeVert, assets::shapeFrag);
    gpu_->frameSizeLocation = glGetUniformLocation(gpu_->program, "frameSize");
    glGenVertexArrays(1, &gpu_->vertexArray);
    glGenBuffers(1, &gpu_->instanceBuffer);
    glBindVertexArray(gpu_->vertexArray);
    glBindBuffer(GL_ARRAY_BUFFER, gpu_->instanceBuffer);
    describeInstanceLayout();
    glBindVertexArray(0);
    checkGlError("Renderer setup");
}

Renderer::~Renderer() {
    // GL objects belong to the context, which must still exist (documented in the header).
    context_.makeCurrent();
    glDeleteBuffers(1, &gpu_->instanceBuffer);
    glDeleteVertexArrays(1, &gpu_->vertexArray);
    glDeleteProgram(gpu_->program);
}

FrameSize Renderer::frameSize() const { return context_.size(); }

void Renderer::draw(const DrawList& list, const Camera& camera) {
    context_.makeCurrent();
    FrameSize frame = context_.size();
    buildInstances(list, camera, frame, gpu_->instances);
    const auto& instances = gpu_->instances;

    glViewport(0, 0, frame.width, frame.height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glClearColor(list.background.r / 255.0f, list.background.g / 255.0f, list.background.b / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    stats_ = RenderStats{instances.size(), 0};
    if (instances.empty()) return;

    glBindBuffer(GL_ARRAY_BUFFER, gpu_->instanceBuffer);
    const auto bytes = static_cast<GLsizeiptr>(instances.size() * sizeof(ShapeInstance));
    // New storage every frame: the driver never waits for the last frame to let go of the old.
    glBufferData(GL_ARRAY_BUFFER, bytes, instances.data(), GL_STREAM_DRAW);

    // Premultiplied alpha (the fragment shader multiplies by coverage): over-compositing.
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(gpu_->program);
    glUniform2f(gpu_->frameSizeLocation, static_cast<float>(frame.width), static_cast<float>(frame.height));
    glBindVertexArray(gpu_->vertexArray);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(instances.size()));
    glBindVertexArray(0);
    stats_.drawCalls = 1;
}

void Renderer::readPixels(Image& into) { context_.readPixels(into); }

Image Renderer::render(const DrawList& list, const Camera& camera) {
    draw(list, camera);
    Image image;
    readPixels(image);
    return image;
}

} // namespace rube::render
