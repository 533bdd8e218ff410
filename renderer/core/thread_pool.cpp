// ThreadPool (host only): the workers' loop and the hand-out of one parallelFor's chunks.
#include "core/thread_pool.h"

#include <algorithm>

namespace trazo {

ThreadPool::ThreadPool(unsigned threads) {
    const unsigned total = threads ? threads : std::max(1u, std::thread::hardware_concurrency());
    workers_.reserve(total - 1);
    for (unsigned i = 1; i < total; ++i) workers_.emplace_back([this] { workerLoop(); });
}

ThreadPool::~ThreadPool() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : workers_) t.join();
}

void ThreadPool::run(size_t count, size_t grain, Chunk chunk, void* fn, unsigned maxThreads) {
    if (count == 0) return;
    grain = std::clamp<size_t>(grain, 1, count);
    const size_t chunks = count / grain + (count % grain != 0);
    const size_t helpers = std::min({workers_.size(), maxThreads ? size_t(maxThreads) - 1 : workers_.size(), chunks - 1});
    bool parallel = helpers > 0;
    const Job job{chunk, fn, count, grain, chunks, unsigned(helpers)};
    if (parallel) {
        std::lock_guard<std::mutex> lock(mutex_);
        parallel = !running_;  // a nested or concurrent call: the workers are taken, so it runs here
        if (parallel) {
            running_ = true;
            job_ = job;
            nextChunk_.store(0, std::memory_order_relaxed);
            error_ = nullptr;
            open_ = true;
            ++generation_;
        }
    }
    if (!parallel) {
        for (size_t begin = 0; begin < count; begin += std::min(grain, count - begin))
            chunk(fn, begin, begin + std::min(grain, count - begin));
        return;
    }
    wake_.notify_all();
    work(job);
    std::exception_ptr error;
    {
        std::unique_lock<std::mutex> lock(mutex_);
        open_ = false;  // a worker that wakes from here on finds nothing to join
        finished_.wait(lock, [this] { return busy_ == 0; });
        running_ = false;
        error = std::move(error_);
        error_ = nullptr;
    }
    if (error) std::rethrow_exception(error);
}

void ThreadPool::work(const Job& job) {
    for (size_t c; (c = nextChunk_.fetch_add(1, std::memory_order_relaxed)) < job.chunks;) {
        const size_t begin = c * job.grain;
        try {
            job.chunk(job.fn, begin, begin + std::min(job.grain, job.count - begin));
        } catch (...) {
            std::lock_guard<std::mutex> lock(mutex_);
            if (!error_) error_ = std::current_exception();
            nextChunk_.store(job.chunks, std::memory_order_relaxed);  // hand out no more
        }
    }
}

void ThreadPool::workerLoop() {
    unsigned long long seen = 0;
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
        if (stop_) return;
        seen = generation_;
        if (!open_ || job_.seats == 0) continue;
        --job_.seats;
        ++busy_;
        const Job job = job_;
        lock.unlock();
        work(job);
        lock.lock();
        if (--busy_ == 0) finished_.notify_one();
    }
}

ThreadPool& sharedThreadPool() {
    static ThreadPool pool;
    return pool;
}

}  // namespace trazo
