// The World's worker threads (see worker_pool.hpp).
#include "worker_pool.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rube {

namespace {

/// Spins before a waiter blocks (a count, never a clock): about 30 us at 30 ns a pause, enough to
/// cover a chunk or the caller's serial work between two runs on a running peer. On a machine with
/// no processor to spare, spinning only takes time from the thread it waits for: 20,000 spins made a
/// 2-worker large pyramid 2 x slower than one worker there, 2000 1.15 x (bench, load 6 on 2 cores).
constexpr int kSpins = 1000;

inline void pause() {
#if defined(__SSE2__)
    _mm_pause();
#endif
}

/// Waits until `value` differs from `seen`: a bounded spin, then the atomic's futex wait.
template <class T>
T awaitChange(const std::atomic<T>& value, T seen) {
    for (int i = 0; i < kSpins; ++i) {
        const T now = value.load(std::memory_order_acquire);
        if (now != seen) return now;
        pause();
    }
    for (;;) {
        const T now = value.load(std::memory_order_acquire);
        if (now != seen) return now;
        value.wait(seen, std::memory_order_acquire);
    }
}

/// Where thread t's share of n chunks begins: thread t of T has [n t / T, n (t + 1) / T).
std::size_t shareStart(std::size_t chunks, int t, int threads) {
    return chunks * static_cast<std::size_t>(t) / static_cast<std::size_t>(threads);
}

} // namespace

WorkerPool::WorkerPool(int workers)
    : workers_(workers), shares_(static_cast<std::size_t>(kMaxPhases) * static_cast<std::size_t>(workers)) {
    threads_.reserve(static_cast<std::size_t>(workers - 1));
    for (int w = 1; w < workers; ++w) threads_.emplace_back([this, w] { loop(w); });
}

bool WorkerPool::claim(int p, int t, bool own, std::size_t& chunk) {
    std::atomic<std::uint64_t>& share = shares_[static_cast<std::size_t>(p * workers_ + t)].value;
    // A relaxed load first, so a share already used up costs no write to its line.
    std::uint64_t now = share.load(std::memory_order_relaxed);
    for (;;) {
        const std::uint64_t front = now & kFrontMask, back = now >> 32;
        if (front >= back) return false;
        // The owner takes from the front, a thief from the back: far from where the owner works, so
        // the two meet other bodies (a colour's contacts are in body order) until the share runs out.
        const std::uint64_t taken = own ? (back << 32 | (front + 1)) : ((back - 1) << 32 | front);
        if (share.compare_exchange_weak(now, taken, std::memory_order_relaxed)) {
            chunk = static_cast<std::size_t>(own ? front : back - 1);
            return true;
        }
    }
}

WorkerPool::~WorkerPool() {
    if (threads_.empty()) return;
    stop_.store(true, std::memory_order_relaxed); // published by the generation's seq_cst bump
    generation_.fetch_add(1, std::memory_order_seq_cst);
    generation_.notify_all();
    for (std::thread& t : threads_) t.join();
}

void WorkerPool::work(int self) {
    for (int p = 0; p < phases_; ++p) {
        const std::size_t chunks = chunks_[p];
        // The own share first, then the others' in turn. The chunks this thread did are counted
        // once, when none is left to claim: one write to the shared counter a phase, not one a
        // chunk (each write takes the counter's line from the other processor).
        std::size_t did = 0;
        for (int i = 0; i < workers_; ++i) {
            const int t = (self + i) % workers_;
            for (std::size_t k; claim(p, t, i == 0, k);) {
                const std::size_t first = k * chunk_[p];
                call_(work_, p, first, first + chunk_[p] < size_[p] ? first + chunk_[p] : size_[p]);
                ++did;
            }
        }
        if (did > 0 && done_[p].value.fetch_add(did, std::memory_order_acq_rel) + did == chunks)
            done_[p].value.notify_all();
        // Every chunk is claimed: wait for the ones still being worked on.
        for (std::size_t done = done_[p].value.load(std::memory_order_acquire); done != chunks;)
            done = awaitChange(done_[p].value, done);
    }
}

void WorkerPool::dispatch(int phases, const std::size_t* sizes, const std::size_t* chunks, Call call, void* work) {
    call_ = call;
    work_ = work;
    phases_ = phases;
    for (int p = 0; p < phases; ++p) {
        size_[p] = sizes[p];
        chunk_[p] = chunks[p];
        chunks_[p] = (sizes[p] + chunks[p] - 1) / chunks[p];
        for (int t = 0; t < workers_; ++t)
            shares_[static_cast<std::size_t>(p * workers_ + t)].value.store(
                static_cast<std::uint64_t>(shareStart(chunks_[p], t + 1, workers_)) << 32 |
                    static_cast<std::uint64_t>(shareStart(chunks_[p], t, workers_)),
                std::memory_order_relaxed);
        done_[p].value.store(0, std::memory_order_relaxed);
    }
    const std::uint64_t generation = generation_.fetch_add(1, std::memory_order_seq_cst) + 1;
    generation_.notify_all();
    this->work(0);
    // Close the run, then wait only for the workers that joined it (seq_cst on both sides: a worker
    // either sees the run closed and leaves without touching it, or is counted here).
    closed_.store(generation, std::memory_order_seq_cst);
    for (int active = active_.load(std::memory_order_seq_cst); active != 0;) active = awaitChange(active_, active);
}

void WorkerPool::loop(int self) {
    std::uint64_t seen = 0;
    for (;;) {
        seen = awaitChange(generation_, seen);
        if (stop_.load(std::memory_order_acquire)) return;
        active_.fetch_add(1, std::memory_order_seq_cst);
        if (closed_.load(std::memory_order_seq_cst) < seen) work(self);
        if (active_.fetch_sub(1, std::memory_order_seq_cst) == 1) active_.notify_all();
    }
}

} // namespace rube
