#pragma once
// Internal: the World's worker threads (WorldDef::workers). A small persistent pool that runs work
// in phases: each phase's items are cut into chunks of a fixed length, and no thread starts phase
// p + 1 before every chunk of phase p is done. Each thread (the caller is thread 0) has a home
// share of every phase's chunks, the same place in each, and claims chunks there first, front to
// back, then from the back of the others' shares until none is left: the rigid contacts of every
// colour are in body order, so a thread keeps meeting the same bodies colour after colour and their
// cache lines stay with its processor, where claiming anywhere sent them back and forth (and a thief
// works far from where the owner is working). Which thread does a chunk is left to chance,
// so a chunk's result must not depend on it: the rigid solver hands out only work whose items
// write disjoint slots (the contacts of one colour, one body each), which gives the same bits for
// any split. A worker the machine has not scheduled holds nothing up: the others take its chunks,
// and the caller never waits for a worker that has not joined. Nothing waits on a clock: a waiting
// thread spins a bounded number of times, then blocks on the atomic (a futex). Not part of the
// public API.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <thread>
#include <vector>

namespace rube {

class WorkerPool {
public:
    /// The most phases one run may have (a sweep over the rigid contacts' colours and the overflow).
    static constexpr int kMaxPhases = 16;

    /// Starts workers - 1 threads (none for 1); workers must be at least 1.
    explicit WorkerPool(int workers);
    /// Stops and joins the threads.
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    int workers() const { return workers_; }

    /// Runs `phases` phases of sizes[p] items in chunks of chunks[p] items (> 0): work(p, first,
    /// last) once for each chunk [first, last), on any thread; returns when all are done. Phase p + 1
    /// starts after every chunk of phase p is done, and what they wrote is then visible to all.
    /// Not reentrant: work must not call run().
    template <class Work>
    void run(int phases, const std::size_t* sizes, const std::size_t* chunks, Work& work) {
        dispatch(
            phases, sizes, chunks,
            [](void* w, int p, std::size_t a, std::size_t b) { (*static_cast<Work*>(w))(p, a, b); }, &work);
    }

private:
    using Call = void (*)(void*, int, std::size_t, std::size_t);
    void dispatch(int phases, const std::size_t* sizes, const std::size_t* chunks, Call call, void* work);
    void work(int self);
    void loop(int self);
    /// Claims a chunk of phase p in thread t's share (its first if `own`, else its last), or returns
    /// false when none is left there.
    bool claim(int p, int t, bool own, std::size_t& chunk);

    int workers_;
    std::vector<std::thread> threads_;
    // The run in progress, set before its generation is published.
    Call call_ = nullptr;
    void* work_ = nullptr;
    int phases_ = 0;
    std::size_t size_[kMaxPhases] = {}, chunk_[kMaxPhases] = {}, chunks_[kMaxPhases] = {};
    struct alignas(64) Counter {
        std::atomic<std::size_t> value{0};
    };
    struct alignas(64) Share {
        std::atomic<std::uint64_t> value{0};
    };
    static constexpr std::uint64_t kFrontMask = 0xffffffffu;
    // Per phase and thread: the chunks left in its share, [front, back) as back << 32 | front (a phase
    // of 2^32 chunks would need more items than memory holds).
    std::vector<Share> shares_;
    Counter done_[kMaxPhases];   // per phase: chunks finished
    alignas(64) std::atomic<std::uint64_t> generation_{0}; // bumped to publish a run
    std::atomic<std::uint64_t> closed_{0};                 // the last run whose chunks are all done
    std::atomic<int> active_{0};                           // workers inside a run
    std::atomic<bool> stop_{false}; // read by a worker that may not have joined the last run
};

/// Whether n items in chunks of `chunk` are worth handing to the pool: more than one worker and at
/// least two chunks (a hand-over costs about a microsecond).
inline bool worthSharing(const WorkerPool* pool, std::size_t n, std::size_t chunk) {
    return pool != nullptr && pool->workers() > 1 && n >= 2 * chunk;
}

/// Calls part(begin, end) over chunks of [0, n) on the pool's threads when worthSharing, else
/// part(0, n) here. For loops whose items write only their own slots, so any split gives the same bits.
template <class Part>
void forShares(WorkerPool* pool, std::size_t n, std::size_t chunk, Part part) {
    if (!worthSharing(pool, n, chunk)) {
        part(std::size_t{0}, n);
        return;
    }
    auto work = [&](int, std::size_t first, std::size_t last) { part(first, last); };
    pool->run(1, &n, &chunk, work);
}

} // namespace rube
