// The one Catch2 main shared by every test executable. It adds one option to Catch2's own:
// --gl NAME (auto, egl, osmesa) picks the offscreen back end the screenshot tests draw with,
// by setting RUBE_TEST_GL (test_gl_backend.hpp); CTest runs each screenshot test once per back end.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
    Catch::Session session;
    std::string gl;
    session.cli(session.cli() | Catch::clara::Opt(gl, "auto|egl|osmesa")["--gl"](
                                    "the offscreen GL back end the screenshot tests draw with"));
    if (const int status = session.applyCommandLine(argc, argv); status != 0) return status;
    if (!gl.empty()) ::setenv("RUBE_TEST_GL", gl.c_str(), 1);
    return session.run();
}
