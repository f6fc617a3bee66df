#pragma once
// Internal: the World's worker threads (WorldDef::workers). A small persistent pool: run() hands one
// task to every worker at once (worker 0 is the calling thread) and returns when all are done;
// inside a task, barrier() waits for every worker, so a task can sweep the contacts colour after
// colour. Nothing waits on a clock: a worker spins a bounded number of times, then blocks on the
// atomic (a futex), so a loaded machine loses no time to a sleeping worker. Which worker does which
// share is fixed by the share's index, never by who came first, so results do not depend on timing.
// Not part of the public API.

#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace rube {

class WorkerPool {
public:
    /// Starts workers - 1 threads (none for 1); workers must be at least 1.
    explicit WorkerPool(int workers);
    /// Stops and joins the threads.
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    int workers() const { return workers_; }

    /// Calls task(w) for every worker w in [0, workers()), w = 0 on the calling thread, and returns
    /// once every call has returned. Not reentrant: a task must not call run().
    template <class Task>
    void run(Task& task) {
        if (workers_ == 1) {
            task(0);
            return;
        }
        dispatch([](void* t, int w) { (*static_cast<Task*>(t))(w); }, &task);
    }

    /// Inside a task: returns once every worker has reached it (what each wrote before is then
    /// visible to all).
    void barrier();

    /// Worker w's share [begin, end) of n items split into workers() runs as equal as can be, each
    /// starting at a multiple of `align` (so pairs of contacts stay together).
    struct Range {
        std::size_t begin, end;
    };
    Range share(std::size_t n, int w, std::size_t align = 1) const;

private:
    using Call = void (*)(void*, int);
    void dispatch(Call call, void* task);
    void loop(int w);
    /// Waits until `value` differs from `seen` (a bounded spin, then the atomic's futex wait).
    static void awaitChange(const std::atomic<unsigned>& value, unsigned seen);

    int workers_;
    std::vector<std::thread> threads_;
    Call call_ = nullptr;
    void* task_ = nullptr;
    bool stop_ = false;
    std::atomic<unsigned> generation_{0}; // bumped to start a task (or to stop)
    std::atomic<int> running_{0};         // workers still in the task
    std::atomic<int> arrived_{0};         // at the current barrier
    std::atomic<unsigned> barrierGeneration_{0};
};

} // namespace rube

namespace rube {

/// Calls part(begin, end) over shares of [0, n): one share per worker when every worker gets at
/// least `leastEach` items (and `pool` has more than one), else part(0, n) here. For loops whose
/// items write only their own slots, so any split gives the same bits.
template <class Part>
void forShares(WorkerPool* pool, std::size_t n, std::size_t leastEach, Part part) {
    if (pool == nullptr || pool->workers() == 1 || n < leastEach * static_cast<std::size_t>(pool->workers())) {
        part(std::size_t{0}, n);
        return;
    }
    auto task = [&](int w) {
        const WorkerPool::Range r = pool->share(n, w);
        if (r.begin < r.end) part(r.begin, r.end);
    };
    pool->run(task);
}

} // namespace rube
