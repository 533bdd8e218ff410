// ThreadPool (host only): workers started once and kept, and one parallel-for over them.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace trazo {

class ThreadPool {
public:
    // `threads` counts the thread that calls parallelFor, which works too: threads − 1 workers are started.
    // 0 = one per hardware thread.
    explicit ThreadPool(unsigned threads = 0);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    unsigned threadCount() const { return unsigned(workers_.size()) + 1; }

    // Calls fn(begin, end) over [0, count) in chunks of `grain` indices (the last may be shorter), each
    // chunk exactly once, taken in order from a shared counter by the calling thread and at most
    // maxThreads − 1 workers (0: all of them). Returns when every chunk is done. The first exception thrown
    // stops the handing out of chunks and is rethrown here once the others have finished. A parallelFor
    // called from inside fn, or from a thread while another's parallelFor on this pool is running, waits
    // for nothing: the nested one runs its chunks on the calling thread, in order.
    template <class Fn>
    void parallelFor(size_t count, size_t grain, Fn&& fn, unsigned maxThreads = 0) {
        using F = std::remove_reference_t<Fn>;
        run(count, grain, [](void* f, size_t b, size_t e) { (*static_cast<F*>(f))(b, e); },
            const_cast<void*>(static_cast<const void*>(&fn)), maxThreads);
    }

private:
    using Chunk = void (*)(void* fn, size_t begin, size_t end);
    struct Job {
        Chunk chunk = nullptr;
        void* fn = nullptr;
        size_t count = 0, grain = 1, chunks = 0;
        unsigned seats = 0;  // workers that may still join
    };

    void run(size_t count, size_t grain, Chunk chunk, void* fn, unsigned maxThreads);
    void work(const Job& job);  // takes chunks until none is left or one has thrown
    void workerLoop();

    std::vector<std::thread> workers_;
    std::mutex mutex_;                  // guards everything below but nextChunk_
    std::condition_variable wake_;      // a job was posted, or the pool stops
    std::condition_variable finished_;  // the last worker left the job
    Job job_;
    bool open_ = false;                 // job_ may be joined
    bool stop_ = false;
    unsigned long long generation_ = 0;
    unsigned busy_ = 0;                 // workers inside job_
    std::exception_ptr error_;
    bool running_ = false;              // a parallelFor is in progress
    std::atomic<size_t> nextChunk_{0};  // the work counter: read without the mutex
};

// One pool for the whole process, with a thread per hardware thread, started on first use: for work that
// has no pool of its own to run on (the BVH builds of scene flattening).
ThreadPool& sharedThreadPool();

}  // namespace trazo
