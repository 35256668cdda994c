#include "core/thread_pool.h"

namespace wt {

ThreadPool::ThreadPool(int thread_count) {
    for (int w = 1; w < thread_count; ++w) workers_.emplace_back([this, w] { worker_loop(w); });
}

ThreadPool::~ThreadPool() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    start_.notify_all();
    for (std::thread& t : workers_) t.join();
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
