// GLSL compile and link with readable errors: a broken shader should say which and why.
#include "gl_program.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>

namespace rube::render {
namespace {

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log;
}

std::string programLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    return log;
}

GLuint compile(std::string_view name, GLenum stage, std::string_view source) {
    GLuint shader = glCreateShader(stage);
    const GLchar* text = source.data();
    GLint length = static_cast<GLint>(source.size());
    glShaderSource(shader, 1, &text, &length);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        std::string log = shaderLog(shader);
        glDeleteShader(shader);
        throw std::runtime_error(std::string(name) + (stage == GL_VERTEX_SHADER ? ".vert" : ".frag") +
                                 " does not compile:\n" + log);
    }
    return shader;
}

} // namespace

GLuint linkProgram(std::string_view name, std::string_view vertexSource, std::string_view fragmentSource) {
    GLuint vertex = compile(name, GL_VERTEX_SHADER, vertexSource);
    GLuint fragment = 0;
    try {
        fragment = compile(name, GL_FRAGMENT_SHADER, fragmentSource);
    } catch (...) {
        glDeleteShader(vertex);
        throw;
    }
    GLuint program = glCreateProgram();
    glAttachShader(program, vertex);
    glAttachShader(program, fragment);
    glLinkProgram(program);
    // The program keeps the compiled code; the shader objects can go now.
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        std::string log = programLog(program);
        glDeleteProgram(program);
        throw std::runtime_error(std::string(name) + " shaders do not link:\n" + log);
    }
    return program;
}

void checkGlError(std::string_view what) {
    GLenum error = glGetError();
    if (error != GL_NO_ERROR) {
        throw std::runtime_error("GL error 0x" + [&] {
            char hex[16];
            std::snprintf(hex, sizeof hex, "%04x", static_cast<unsigned>(error));
            return std::string(hex);
        }() + " in " + std::string(what));
    }
}

} // namespace rube::render
