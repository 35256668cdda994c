#include "core/system/thread_pool.h"

#include <stdexcept>
#include <string>
#include <system_error>

namespace wt {

ThreadPool::ThreadPool(int thread_count, const ThreadFactory& start_thread) {
    workers_.reserve(std::size_t(std::max(0, thread_count - 1)));
    try {
        for (int w = 1; w < thread_count; ++w) {
            std::function<void()> loop = [this, w] { worker_loop(w); };
            workers_.push_back(start_thread ? start_thread(std::move(loop)) : std::thread(std::move(loop)));
        }
    } catch (const std::system_error& e) {
        // A throwing constructor runs no destructor: the workers already started would wait on
        // start_ while it is destroyed under them, and join() would never return.
        stop_workers();
        throw std::runtime_error("cannot start " + std::to_string(thread_count) + " threads (" +
                                 std::to_string(workers_.size() + 1) + " could be started: " + e.what() +
                                 "); use fewer threads");
    }
}

ThreadPool::~ThreadPool() { stop_workers(); }

void ThreadPool::stop_workers() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    start_.notify_all();
    for (std::thread& t : workers_)
        if (t.joinable()) t.join();
}

void ThreadPool::run_items(int worker) {
    for (;;) {
        const std::size_t item = next_item_.fetch_add(1, std::memory_order_relaxed);
        if (item >= job_size_) return;
        try {
            (*job_)(item, worker);
        } catch (...) {
            std::lock_guard<std::mutex> lock(mutex_);
            if (!error_) error_ = std::current_exception();
            next_item_.store(job_size_, std::memory_order_relaxed);  // stop handing out work
        }
    }
}

void ThreadPool::worker_loop(int worker) {
    std::size_t seen_generation = 0;
    for (;;) {
        {
            std::unique_lock<std::mutex> lock(mutex_);
            start_.wait(lock, [&] { return stopping_ || generation_ != seen_generation; });
            if (stopping_) return;
            seen_generation = generation_;
        }
        run_items(worker);
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (--busy_workers_ == 0) done_.notify_one();
        }
    }
}

void ThreadPool::parallel_for(std::size_t count, const std::function<void(std::size_t, int)>& fn) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        job_ = &fn;
        job_size_ = count;
        next_item_.store(0, std::memory_order_relaxed);
        busy_workers_ = int(workers_.size());
        error_ = nullptr;
        ++generation_;
    }
    start_.notify_all();
    run_items(0);
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return busy_workers_ == 0; });
    job_ = nullptr;
    if (error_) std::rethrow_exception(error_);
}

}  // namespace wt
