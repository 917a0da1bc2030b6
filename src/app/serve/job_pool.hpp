#pragma once
// A few threads for the answers that take time (a tile warped from a DEM, fetched from a server),
// so the server's network thread only ever does quick work and one slow tile holds up no other
// request. The queue is bounded: a full queue refuses work (the server answers 503) instead of
// growing without end.

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <stop_token>
#include <thread>
#include <vector>

namespace trailray::app::serve {

class JobPool {
 public:
  using Job = std::function<void(std::stop_token)>;

  JobPool(unsigned threads, std::size_t max_queued);
  ~JobPool();  // shutdown()
  JobPool(const JobPool&) = delete;
  JobPool& operator=(const JobPool&) = delete;

  // False when the queue is full or the pool is shutting down (the job is dropped, not run).
  bool submit(Job job);

  // Refuses new jobs, asks the running ones to stop (their stop_token), runs what is queued with
  // the stop requested (so each still finishes its answer, quickly) and joins the threads.
  void shutdown();

 private:
  void work();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Job> queue_;
  std::size_t max_queued_;
  bool stopping_ = false;
  std::stop_source stop_;
  std::vector<std::thread> threads_;
};

}  // namespace trailray::app::serve
