#pragma once
// A fixed set of std::thread workers that run one indexed job at a time. Work items are handed
// out by an atomic counter, so the hot path takes no lock; the mutex is touched only to start a
// job and to learn that it finished. The calling thread works too, as worker 0.

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace wt {

class ThreadPool {
public:
    // Starts a thread running the given function; std::thread's constructor unless a test
    // needs creation to fail. Throws (std::system_error) when no thread can be created.
    using ThreadFactory = std::function<std::thread(std::function<void()>)>;

    // Throws std::runtime_error naming how many threads could be started when not all of them
    // can (a process limit, `ulimit -u`); the ones started are stopped and joined first.
    explicit ThreadPool(int thread_count, const ThreadFactory& start_thread = {});
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    int thread_count() const { return int(workers_.size()) + 1; }

    // Calls fn(item, worker) for every item in [0, count), worker in [0, thread_count()).
    // Returns when all items are done; rethrows the first exception any call threw.
    void parallel_for(std::size_t count, const std::function<void(std::size_t item, int worker)>& fn);

private:
    void stop_workers();
    void worker_loop(int worker);
    void run_items(int worker);

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable start_;
    std::condition_variable done_;
    const std::function<void(std::size_t, int)>* job_ = nullptr;
    std::size_t job_size_ = 0;
    std::atomic<std::size_t> next_item_{0};
    std::size_t generation_ = 0;
    int busy_workers_ = 0;
    bool stopping_ = false;
    std::exception_ptr error_;
};

}  // namespace wt
