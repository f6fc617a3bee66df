// Determinism, as Box2D's determinism test does it: each scene runs a fixed number of steps and
// its state hash must equal a constant recorded here. The same constants must hold for every
// compiler and optimisation level (the cross-build test checks whole traces too), so a changed
// hash means the physics changed: on purpose, update the table (RUBE_PRINT_HASHES=1 prints it);
// by accident, it is a determinism bug.
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

using namespace rube;
using namespace rube::game;

namespace {

struct Expected {
    const char* scene;
    const char* method; // "" for the scene's own method
    int steps;
    std::uint64_t hash;
};

// Recorded with g++ 12 -O2 on x86-64; clang++ 14 and -O0 give the same.
constexpr Expected kExpected[] = {
    {"ball-stack", "", 240, 0xf7c2706edd06f761ull},
    {"bounce", "", 240, 0xbe16949d447ac7d5ull},
    {"bullet", "", 6, 0xe722c6f4896b642eull},
    {"newtons-cradle", "", 240, 0xa3c94e00690e1aeaull},
    {"pile", "", 120, 0x517448299881dfd3ull},
    {"pool-break", "", 240, 0x9b407725a5517d9dull},
    {"projectile", "", 108, 0x8b851db09620c938ull},
    {"slope-rest", "", 180, 0xe4a9957e1f6981b0ull},
    {"pool-break", "discrete", 240, 0x726f330a97a17ab4ull},
    {"pool-break", "turn-based", 240, 0x64d8d8595ee8c6ddull},
    {"pool-break", "solver", 240, 0x334eef1e5f079606ull},
    {"ball-stack", "exact", 240, 0x241cf71538a36ba7ull},
};

std::uint64_t runAndHash(const Expected& e) {
    const SceneLoad load = loadSceneFile(std::filesystem::path(RUBE_LEVELS_DIR) / (std::string(e.scene) + ".toml"));
    REQUIRE(load.ok());
    World world = buildWorld(*load.scene);
    if (*e.method) world.setMethod(*methodFromName(e.method));
    for (int i = 0; i < e.steps; ++i) world.step();
    return stateHash(world);
}

} // namespace

TEST_CASE("every scene reaches its recorded state hash", "[determinism]") {
    const bool print = std::getenv("RUBE_PRINT_HASHES") != nullptr;
    for (const Expected& e : kExpected) {
        const std::uint64_t hash = runAndHash(e);
        if (print)
            std::printf("    {\"%s\", \"%s\", %d, 0x%016" PRIx64 "ull},\n", e.scene, e.method, e.steps, hash);
        INFO(e.scene << " " << (*e.method ? e.method : "(own method)") << " after " << e.steps << " steps");
        CHECK(hash == e.hash);
    }
}

TEST_CASE("the same scene run twice gives the same hash", "[determinism]") {
    CHECK(runAndHash(kExpected[5]) == runAndHash(kExpected[5]));
    CHECK(runAndHash(kExpected[4]) == runAndHash(kExpected[4]));
}
