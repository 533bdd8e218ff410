// Tests of ThreadPool (host): every index once, exceptions, nested and empty calls, reuse, concurrency.
#include "core/thread_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <set>
#include <stdexcept>
#include <vector>

namespace trazo {
namespace {

TEST(ThreadPool, VisitsEveryIndexExactlyOnceInChunksOfTheGrain) {
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
        ThreadPool pool(threads);
        EXPECT_EQ(pool.threadCount(), threads);
        for (size_t count : {size_t(1), size_t(7), size_t(1000), size_t(12345)}) {
            for (size_t grain : {size_t(0), size_t(1), size_t(3), size_t(64), size_t(999), size_t(1) << 40}) {
                std::vector<std::atomic<int>> visits(count);
                std::atomic<bool> badChunk{false};
                pool.parallelFor(count, grain, [&](size_t begin, size_t end) {
                    const size_t g = std::max<size_t>(grain, 1);
                    // Chunks start at multiples of the grain and hold it, except the last one.
                    if (begin >= end || end > count || begin % g != 0 || (end - begin != g && end != count))
                        badChunk = true;
                    for (size_t i = begin; i < end; ++i) visits[i].fetch_add(1);
                });
                EXPECT_FALSE(badChunk) << threads << " threads, count " << count << ", grain " << grain;
                size_t wrong = 0;
                for (const std::atomic<int>& v : visits) wrong += v.load() != 1;
                EXPECT_EQ(wrong, 0u) << threads << " threads, count " << count << ", grain " << grain;
            }
        }
    }
}

TEST(ThreadPool, AnEmptyRangeCallsNothing) {
    ThreadPool pool(3);
    int calls = 0;
    pool.parallelFor(0, 1, [&](size_t, size_t) { ++calls; });
    pool.parallelFor(0, 0, [&](size_t, size_t) { ++calls; });
    EXPECT_EQ(calls, 0);
}

// Two chunks that each wait for the other to start: they finish only if two threads run them at once.
TEST(ThreadPool, ChunksRunOnSeveralThreadsAtOnce) {
    ThreadPool pool(2);
    std::atomic<int> started{0};
    std::atomic<bool> met{true};
    pool.parallelFor(2, 1, [&](size_t, size_t) {
        ++started;
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        while (started.load() < 2)
            if (std::chrono::steady_clock::now() > deadline) return void(met = false);
    });
    EXPECT_TRUE(met);
}

TEST(ThreadPool, MaxThreadsOneRunsOnTheCallingThread) {
    ThreadPool pool(4);
    const std::thread::id caller = std::this_thread::get_id();
    std::atomic<bool> elsewhere{false};
    pool.parallelFor(
        1000, 1, [&](size_t, size_t) { elsewhere = elsewhere || std::this_thread::get_id() != caller; }, 1);
    EXPECT_FALSE(elsewhere);
}

TEST(ThreadPool, TheFirstExceptionReachesTheCallerAndThePoolStaysUsable) {
    ThreadPool pool(3);
    // Chunk 0 throws; every other chunk waits for the throw, then takes 2 ms: running all 999 would take
    // a second, stopping the hand-out lets only those already taken finish.
    std::atomic<bool> thrown{false};
    std::atomic<int> after{0};
    try {
        pool.parallelFor(1000, 1, [&](size_t begin, size_t) {
            if (begin == 0) {
                thrown = true;
                throw std::runtime_error("chunk 0");
            }
            const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
            while (!thrown && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
            ++after;
        });
        ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "chunk 0");
    }
    EXPECT_LT(after.load(), 999) << "chunks kept being handed out after the exception";
    std::atomic<size_t> sum{0};
    pool.parallelFor(1000, 3, [&](size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) sum += i;
    });
    EXPECT_EQ(sum.load(), 999u * 1000u / 2);
    // On a pool of one thread too (no workers: the chunks run in the caller).
    ThreadPool single(1);
    EXPECT_THROW(single.parallelFor(10, 1, [](size_t, size_t) { throw std::logic_error("x"); }), std::logic_error);
}

TEST(ThreadPool, NestedCallsRunWithoutDeadlock) {
    ThreadPool pool(3);
    std::vector<std::atomic<int>> visits(64 * 50);
    pool.parallelFor(64, 1, [&](size_t outer, size_t) {
        pool.parallelFor(50, 4, [&](size_t begin, size_t end) {
            for (size_t i = begin; i < end; ++i) visits[outer * 50 + i].fetch_add(1);
        });
    });
    size_t wrong = 0;
    for (const std::atomic<int>& v : visits) wrong += v.load() != 1;
    EXPECT_EQ(wrong, 0u);
}

TEST(ThreadPool, ConcurrentCallersFromOtherThreadsBothFinish) {
    ThreadPool pool(3);
    std::atomic<size_t> a{0}, b{0};
    auto sumInto = [&](std::atomic<size_t>& out) {
        for (int k = 0; k < 200; ++k)
            pool.parallelFor(100, 3, [&](size_t begin, size_t end) {
                for (size_t i = begin; i < end; ++i) out += i;
            });
    };
    std::thread other([&] { sumInto(a); });
    sumInto(b);
    other.join();
    EXPECT_EQ(a.load(), 200u * 4950u);
    EXPECT_EQ(b.load(), 200u * 4950u);
}

TEST(ThreadPool, ReusedOverAThousandCallsTrivialOrNot) {
    ThreadPool pool(4);
    std::set<std::thread::id> ids;
    std::mutex idsMutex;
    for (int call = 0; call < 1000; ++call) {
        std::atomic<size_t> sum{0};
        const size_t count = size_t(call % 37);
        pool.parallelFor(count, 1 + call % 5, [&](size_t begin, size_t end) {
            for (size_t i = begin; i < end; ++i) sum += i + 1;
        });
        ASSERT_EQ(sum.load(), count * (count + 1) / 2) << "call " << call;
        pool.parallelFor(8, 1, [](size_t, size_t) {});
    }
    pool.parallelFor(64, 1, [&](size_t, size_t) {
        std::lock_guard<std::mutex> lock(idsMutex);
        ids.insert(std::this_thread::get_id());
    });
    EXPECT_LE(ids.size(), 4u);
}

TEST(ThreadPool, PoolsStartAndStopCleanly) {
    for (int i = 0; i < 50; ++i) {
        ThreadPool pool(1 + unsigned(i % 4));
        if (i % 2) pool.parallelFor(10, 1, [](size_t, size_t) {});
    }
    EXPECT_GE(sharedThreadPool().threadCount(), 1u);
    EXPECT_EQ(&sharedThreadPool(), &sharedThreadPool());
}

}  // namespace
}  // namespace trazo
