#pragma once
// A ParallelFor (track/density.hpp) on two threads, the calling one and one more, taking jobs
// from a shared counter: tests use it to run the density counts as the commands do.

#include <atomic>
#include <cstddef>
#include <functional>
#include <thread>

#include "geo/threads.hpp"
#include "track/density.hpp"

namespace trailray::track::test {

inline void two_threads(std::size_t count, const std::function<void(std::size_t)>& job) {
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t i = next++; i < count; i = next++) job(i);
  };
  if (!geo::kThreadsAvailable) {  // the WebAssembly page's build: the jobs in turn, same results
    work();
    return;
  }
  std::thread other(work);
  work();
  other.join();
}

}  // namespace trailray::track::test
