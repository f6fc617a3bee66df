// The World's worker threads (see worker_pool.hpp).
#include "worker_pool.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rube {

namespace {

/// Spins before a waiter blocks: long enough to cover a colour's share of a large pyramid on a
/// running peer, short enough that a descheduled peer costs little (a count, never a clock).
constexpr int kSpins = 4000;

inline void pause() {
#if defined(__SSE2__)
    _mm_pause();
#endif
}

} // namespace

WorkerPool::WorkerPool(int workers) : workers_(workers) {
    threads_.reserve(static_cast<std::size_t>(workers - 1));
    for (int w = 1; w < workers; ++w) threads_.emplace_back([this, w] { loop(w); });
}

WorkerPool::~WorkerPool() {
    if (threads_.empty()) return;
    stop_ = true;
    generation_.fetch_add(1, std::memory_order_release);
    generation_.notify_all();
    for (std::thread& t : threads_) t.join();
}

void WorkerPool::awaitChange(const std::atomic<unsigned>& value, unsigned seen) {
    for (int i = 0; i < kSpins; ++i) {
        if (value.load(std::memory_order_acquire) != seen) return;
        pause();
    }
    while (value.load(std::memory_order_acquire) == seen) value.wait(seen, std::memory_order_acquire);
}

void WorkerPool::dispatch(Call call, void* task) {
    call_ = call;
    task_ = task;
    running_.store(workers_ - 1, std::memory_order_relaxed);
    generation_.fetch_add(1, std::memory_order_release);
    generation_.notify_all();
    call(task, 0);
    for (int i = 0; i < kSpins && running_.load(std::memory_order_acquire) != 0; ++i) pause();
    for (int left = running_.load(std::memory_order_acquire); left != 0;
         left = running_.load(std::memory_order_acquire))
        running_.wait(left, std::memory_order_acquire);
}

void WorkerPool::loop(int w) {
    unsigned seen = 0;
    for (;;) {
        awaitChange(generation_, seen);
        seen = generation_.load(std::memory_order_acquire);
        if (stop_) return;
        call_(task_, w);
        if (running_.fetch_sub(1, std::memory_order_acq_rel) == 1) running_.notify_one();
    }
}

void WorkerPool::barrier() {
    const unsigned seen = barrierGeneration_.load(std::memory_order_acquire);
    if (arrived_.fetch_add(1, std::memory_order_acq_rel) == workers_ - 1) {
        arrived_.store(0, std::memory_order_relaxed);
        barrierGeneration_.fetch_add(1, std::memory_order_release);
        barrierGeneration_.notify_all();
        return;
    }
    awaitChange(barrierGeneration_, seen);
}

WorkerPool::Range WorkerPool::share(std::size_t n, int w, std::size_t align) const {
    const std::size_t units = (n + align - 1) / align, k = static_cast<std::size_t>(workers_);
    const std::size_t u = static_cast<std::size_t>(w);
    const std::size_t begin = (units * u / k) * align, end = (units * (u + 1) / k) * align;
    return {begin < n ? begin : n, end < n ? end : n};
}

} // namespace rube
