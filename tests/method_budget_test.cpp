// The pair budget of the methods without a broadphase (issue 27), and the output folder's lock.
#include "method_budget.hpp"
#include "out_folder_lock.hpp"
#include "scene_file.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <unistd.h>

using namespace rube;
using namespace rube::game;

namespace {

// n falling circles in one row and k floor segments: n x (n + k) pair tests a search.
std::string rowScene(int n, int k, const std::string& method) {
    std::string text = "name = \"row\"\n";
    if (!method.empty()) text += "[world]\nmethod = \"" + method + "\"\n";
    for (int i = 0; i < k; ++i)
        text += "[[segment]]\na = [-300, " + std::to_string(-i) + "]\nb = [300, " + std::to_string(-i) + "]\n";
    text += "[[circle_grid]]\norigin = [-250, 1]\ncolumns = " + std::to_string(n) +
            "\nrows = 1\nspacing = 0.24\nradius = 0.1\n";
    return text;
}

} // namespace

TEST_CASE(
    "discrete, turn-based and exact take a scene exactly while n (n + k) <= 2^22, no method means exact, else auto",
    "[scene][budget]") {
    for (const int k : {0, 1, 7}) {
        for (int n = 2030; n <= 2060; n += 3) {
            const std::int64_t pairs = std::int64_t{n} * (n + k);
            const bool affordable = pairs <= kMaxPairTests;
            INFO("n = " << n << ", k = " << k << ", pairs = " << pairs);
            for (const std::string method : {"discrete", "turn-based", "exact"}) {
                const SceneLoad named = parseScene(rowScene(n, k, method), "s.toml");
                REQUIRE(named.ok() == affordable);
                if (!affordable) {
                    CHECK(named.errors.size() == 1);
                    CHECK(named.errors[0].format().find(std::to_string(pairs) + " pair tests") != std::string::npos);
                    CHECK(named.errors[0].format().ends_with("use auto or solver"));
                } else {
                    CHECK(pairTestsPerSearch(*named.scene) == pairs);
                }
            }
            for (const std::string method : {"solver", "auto"})
                CHECK(parseScene(rowScene(n, k, method), "s.toml").ok());
            const SceneLoad unnamed = parseScene(rowScene(n, k, ""), "s.toml");
            REQUIRE(unnamed.ok());
            CHECK(unnamed.scene->world.method == (affordable ? Method::exact : Method::automatic));
        }
    }
}

TEST_CASE("an output folder has one holder at a time, the lock goes with its holder", "[frames][lock]") {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() /
                                         ("rube-lock-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    {
        const OutFolderLock first(folder);
        REQUIRE(first.locked());
        for (int attempt = 0; attempt < 3; ++attempt) {
            const OutFolderLock second(folder); // flock is per open file: this process's second open conflicts too
            CHECK_FALSE(second.locked());
            CHECK(second.why() ==
                  folder.string() + " is in use by another rube run (pid " + std::to_string(::getpid()) + ")");
        }
    }
    const OutFolderLock again(folder);
    CHECK(again.locked());
    CHECK(again.why().empty());
    std::filesystem::remove_all(folder);
}
