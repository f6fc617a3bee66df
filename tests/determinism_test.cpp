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
    {"ball-stack", "", 240, 0x4d2087e7c4ed17e1ull},
    {"bounce", "", 240, 0x4c2cef3fd00aef15ull},
    {"bullet", "", 6, 0x044cdc1b9d00e2aeull},
    {"newtons-cradle", "", 240, 0x266d4f74569c1a6aull},
    {"pile", "", 120, 0xe0b4312b91281da8ull},
    {"pool-break", "", 240, 0x264554b93f25ccddull},
    {"projectile", "", 108, 0xad425ba6c5def038ull},
    {"slope-rest", "", 180, 0x29c6b15c4aad14b0ull},
    {"rolling", "", 180, 0x6c36752f98a83189ull},
    {"float", "", 300, 0x72fe7040c1674a66ull},
    {"pendulum", "", 300, 0x52e300f873b9a241ull},
    {"pendulum", "solver", 300, 0x91f9089acb221935ull},
    {"pool-break", "discrete", 240, 0x8cd878b4b51a0b74ull},
    {"pool-break", "turn-based", 240, 0xe626442c4809d8ddull},
    {"pool-break", "solver", 240, 0xeccc6c082bbcf7c6ull},
    {"ball-stack", "exact", 240, 0xb5cb247fd653b627ull},
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
