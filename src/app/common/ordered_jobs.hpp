#pragma once
// Per-file work on all cores whose results are used in the files' order as they come: the files
// go in batches of a few per thread (app/common/parallel_jobs); each batch's results are handed to
// `consume` in order before the next batch starts, so `stats` and `flight` print file after file
// as before (a table appears a batch at a time, not at the very end), memory stays bounded by a
// batch, and the output is the same as one file after the other.

#include <algorithm>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/common/parallel_jobs.hpp"

namespace trailray::app {

struct OrderedJobsOptions {
  unsigned threads = 0;  // 0: every core
  std::size_t batch_per_thread = 4;
  // Called on the calling thread with the jobs finished so far (see ParallelJobsOptions).
  std::function<void(std::size_t done, std::size_t count)> progress;
};

// The threads for reading `paths`: every core, or one when a path is "-" (standard input is read
// once, by the calling thread's order; two readers of it would race).
inline unsigned file_job_threads(const std::vector<std::string>& paths) {
  return std::find(paths.begin(), paths.end(), std::string("-")) != paths.end() ? 1u : 0u;
}

// compute(i) for i in 0..count-1 (on pool threads: it must not touch shared state and must not
// throw), consume(i, result) on the calling thread in index order.
template <typename Result>
void run_ordered_jobs(std::size_t count, const std::function<Result(std::size_t)>& compute,
                      const std::function<void(std::size_t, Result&)>& consume,
                      const OrderedJobsOptions& options = {}) {
  const unsigned threads = options.threads == 0 ? default_job_threads() : options.threads;
  const std::size_t batch = std::max<std::size_t>(1, threads * std::max<std::size_t>(1, options.batch_per_thread));
  std::vector<std::optional<Result>> results;
  for (std::size_t first = 0; first < count; first += batch) {
    const std::size_t n = std::min(batch, count - first);
    results.assign(n, std::nullopt);
    ParallelJobsOptions jobs;
    jobs.threads = threads;
    if (options.progress)
      jobs.progress = [&, first](std::size_t done, std::size_t) { options.progress(first + done, count); };
    run_parallel_jobs(
        n,
        [&](std::size_t k) {
          results[k].emplace(compute(first + k));
          return true;
        },
        jobs);
    for (std::size_t k = 0; k < n; ++k) consume(first + k, *results[k]);
  }
}

}  // namespace trailray::app
