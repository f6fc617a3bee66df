#pragma once
// Internal: compiling and linking GLSL programs, with the info log in the exception.

#include <glad/gl.h>

#include <string_view>

namespace rube::render {

/// Links a program from vertex and fragment shader sources; `name` labels errors.
/// Throws std::runtime_error with GL's info log when compiling or linking fails.
GLuint linkProgram(std::string_view name, std::string_view vertexSource, std::string_view fragmentSource);

/// Throws std::runtime_error naming `what` when GL has recorded an error.
void checkGlError(std::string_view what);

} // namespace rube::render
