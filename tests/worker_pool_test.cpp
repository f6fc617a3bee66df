// The worker pool (worker_pool.hpp) on its own: every chunk of every phase runs exactly once, over
// the right items, and no chunk of a phase starts before every chunk of the phase before it is done,
// for 1 to 4 threads, phases of every size (none, fewer items than threads, many), and chunks whose
// cost is lopsided, so that threads run out of their own share and take from the back of others'.
#include "worker_pool.hpp" // internal: tests may reach inside, users may not

#include <catch2/catch.hpp>

#include <atomic>
#include <cstddef>
#include <vector>

using namespace rube;

TEST_CASE("worker pool: every chunk runs once, phase after phase, with any number of threads", "[workers][pool]") {
    constexpr int kPhases = 6;
    const std::size_t sizes[kPhases] = {0, 1, 37, 1000, 5, 513};
    const std::size_t chunks[kPhases] = {4, 1, 3, 7, 10, 16};
    for (int workers = 1; workers <= 4; ++workers) {
        WorkerPool pool(workers);
        for (int round = 0; round < 50; ++round) {
            std::vector<std::vector<std::atomic<int>>> hits;
            for (const std::size_t n : sizes) hits.emplace_back(n);
            std::atomic<std::size_t> done[kPhases] = {};
            std::atomic<int> early{0}, wrongSpan{0};
            std::atomic<double> sink{0.0};
            auto work = [&](int p, std::size_t first, std::size_t last) {
                // Every earlier phase is complete before any chunk of this one starts.
                for (int q = 0; q < p; ++q)
                    if (done[q].load(std::memory_order_acquire) != sizes[q]) early.fetch_add(1);
                const auto pu = static_cast<std::size_t>(p);
                if (first % chunks[pu] != 0 || last <= first || last > sizes[pu] ||
                    (last - first != chunks[pu] && last != sizes[pu]))
                    wrongSpan.fetch_add(1);
                // The first half of a phase costs far more than the second: thread 0's share runs
                // long and the others finish theirs and take from it.
                double x = 0.0;
                const int cost = first < sizes[pu] / 2 ? 2000 : 10;
                for (int k = 0; k < cost; ++k) x += 1e-9 * k;
                sink.store(x, std::memory_order_relaxed);
                for (std::size_t i = first; i < last; ++i) hits[pu][i].fetch_add(1);
                done[p].fetch_add(last - first, std::memory_order_acq_rel);
            };
            pool.run(kPhases, sizes, chunks, work);
            INFO("workers " << workers << ", round " << round);
            REQUIRE(early.load() == 0);
            REQUIRE(wrongSpan.load() == 0);
            for (int p = 0; p < kPhases; ++p)
                for (std::size_t i = 0; i < sizes[p]; ++i) REQUIRE(hits[static_cast<std::size_t>(p)][i].load() == 1);
        }
    }
}
