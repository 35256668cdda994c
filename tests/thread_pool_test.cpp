// The thread pool when threads cannot be created: it must fail with a message, not hang.
// Creation failure is provoked through the pool's thread factory, deterministically (a process
// limit such as `ulimit -u` depends on everything else the user runs).

#include <atomic>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/system/thread_pool.h"

namespace {

// Starts the first `allowed` threads, then fails as pthread_create does at a process limit.
wt::ThreadPool::ThreadFactory failing_after(int allowed, std::atomic<int>& started) {
    return [allowed, &started](std::function<void()> body) {
        if (started.load() >= allowed) throw std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again));
        ++started;
        return std::thread(std::move(body));
    };
}

TEST(ThreadPool, RunsEveryItemOnceWithTheFactoryItWasGiven) {
    std::atomic<int> started{0};
    wt::ThreadPool pool(4, failing_after(100, started));
    EXPECT_EQ(started.load(), 3);  // the caller is worker 0
    EXPECT_EQ(pool.thread_count(), 4);
    std::vector<std::atomic<int>> runs(1000);
    pool.parallel_for(runs.size(), [&](std::size_t item, int worker) {
        EXPECT_GE(worker, 0);
        EXPECT_LT(worker, 4);
        ++runs[item];
    });
    for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
}

TEST(ThreadPool, ThreadsThatCannotBeCreatedGiveAnErrorNotAHang) {
    // Before the fix the constructor threw while 11 started workers waited on its condition
    // variable, and destroying them never returned.
    std::atomic<int> started{0};
    try {
        wt::ThreadPool pool(64, failing_after(11, started));
        ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("cannot start 64 threads (12 could be started"), std::string::npos) << message;
        EXPECT_NE(message.find("use fewer threads"), std::string::npos) << message;
    }
    EXPECT_EQ(started.load(), 11);
}

TEST(ThreadPool, NoThreadAtAllCanBeCreated) {
    std::atomic<int> started{0};
    EXPECT_THROW(wt::ThreadPool(2, failing_after(0, started)), std::runtime_error);
    // One thread is the caller alone: nothing to create, nothing to fail.
    wt::ThreadPool alone(1, failing_after(0, started));
    int runs = 0;
    alone.parallel_for(5, [&](std::size_t, int) { ++runs; });
    EXPECT_EQ(runs, 5);
}

}  // namespace
