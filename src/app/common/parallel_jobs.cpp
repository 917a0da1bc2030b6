#include "app/common/parallel_jobs.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

namespace trailray::app {

unsigned default_job_threads() { return std::max(1u, std::thread::hardware_concurrency()); }

std::size_t run_parallel_jobs(std::size_t count, const std::function<bool(std::size_t)>& job,
                              const ParallelJobsOptions& options) {
  const unsigned wanted = options.threads == 0 ? default_job_threads() : options.threads;
  const std::size_t threads = std::min<std::size_t>(wanted, count);
  if (threads <= 1) {
    std::size_t ran = 0;
    for (std::size_t i = 0; i < count; ++i) {
      ++ran;
      const bool go_on = job(i);
      if (options.progress) options.progress(i + 1, count);
      if (!go_on) break;
    }
    return ran;
  }

  std::atomic<std::size_t> next{0};
  // The lowest index whose job said stop: indexes above it are not started any more.
  std::atomic<std::size_t> stop_after{std::numeric_limits<std::size_t>::max()};
  std::mutex mutex;
  std::condition_variable changed;
  std::atomic<std::size_t> done{0};
  std::size_t finished_threads = 0, ran = 0;

  const auto work = [&] {
    std::size_t mine = 0;
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= count || i > stop_after.load()) break;
      ++mine;
      if (!job(i)) {
        std::size_t seen = stop_after.load();
        while (i < seen && !stop_after.compare_exchange_weak(seen, i)) {
        }
      }
      ++done;  // no wake-up per job: the reporting thread looks ten times a second
    }
    const std::lock_guard<std::mutex> lock(mutex);
    ran += mine;
    ++finished_threads;
    changed.notify_one();
  };
  std::vector<std::thread> pool;
  pool.reserve(threads);
  for (std::size_t t = 0; t < threads; ++t) pool.emplace_back(work);

  // The calling thread only waits and reports, so a progress callback never runs beside itself.
  {
    std::unique_lock<std::mutex> lock(mutex);
    auto last_report = std::chrono::steady_clock::now() - std::chrono::seconds(1);
    while (finished_threads < threads) {
      changed.wait_for(lock, std::chrono::milliseconds(100));
      const auto now = std::chrono::steady_clock::now();
      if (options.progress && now - last_report >= std::chrono::milliseconds(100)) {
        last_report = now;
        const std::size_t so_far = done.load();
        lock.unlock();
        options.progress(so_far, count);
        lock.lock();
      }
    }
  }
  for (std::thread& t : pool) t.join();
  if (options.progress) options.progress(done.load(), count);
  return ran;
}

track::ParallelFor parallel_for(unsigned threads) {
  return [threads](std::size_t count, const std::function<void(std::size_t)>& job) {
    run_parallel_jobs(count,
                      [&job](std::size_t i) {
                        job(i);
                        return true;
                      },
                      {threads, {}});
  };
}

}  // namespace trailray::app
