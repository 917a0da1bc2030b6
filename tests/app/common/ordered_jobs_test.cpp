// app::run_ordered_jobs: results consumed in index order, each once, a batch at a time, whatever
// the thread that computed them.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "app/common/ordered_jobs.hpp"

namespace trailray::app {
namespace {

TEST(OrderedJobs, ConsumesEveryResultOnceInOrder) {
  for (const unsigned threads : {1u, 2u, 7u}) {
    SCOPED_TRACE(threads);
    std::atomic<int> computed{0};
    std::vector<std::size_t> order;
    const std::thread::id caller = std::this_thread::get_id();
    OrderedJobsOptions options;
    options.threads = threads;
    options.batch_per_thread = 2;
    run_ordered_jobs<std::size_t>(
        101,
        [&](std::size_t i) {
          // Later jobs finish first within a batch.
          std::this_thread::sleep_for(std::chrono::microseconds(100 * ((101 - i) % 5)));
          ++computed;
          return i * i;
        },
        [&](std::size_t i, std::size_t& r) {
          EXPECT_EQ(std::this_thread::get_id(), caller);
          EXPECT_EQ(r, i * i);
          order.push_back(i);
        },
        options);
    EXPECT_EQ(computed.load(), 101);
    ASSERT_EQ(order.size(), 101u);
    for (std::size_t i = 0; i < order.size(); ++i) EXPECT_EQ(order[i], i);
  }
}

// A batch is consumed before the next is computed: memory stays bounded, output comes early.
TEST(OrderedJobs, ABatchIsConsumedBeforeTheNextStarts) {
  std::atomic<std::size_t> highest_started{0};
  std::vector<std::size_t> started_when_consumed;
  OrderedJobsOptions options;
  options.threads = 2;
  options.batch_per_thread = 3;  // batches of 6
  run_ordered_jobs<int>(
      30,
      [&](std::size_t i) {
        std::size_t seen = highest_started.load();
        while (i > seen && !highest_started.compare_exchange_weak(seen, i)) {
        }
        return 0;
      },
      [&](std::size_t i, int&) {
        if (i % 6 == 0) started_when_consumed.push_back(highest_started.load());
      },
      options);
  ASSERT_EQ(started_when_consumed.size(), 5u);
  for (std::size_t b = 0; b < 5; ++b) EXPECT_EQ(started_when_consumed[b], 6 * b + 5);
}

TEST(OrderedJobs, StandardInputIsReadOnOneThread) {
  EXPECT_EQ(file_job_threads({"a.gpx", "b.gpx"}), 0u);
  EXPECT_EQ(file_job_threads({"a.gpx", "-"}), 1u);
}

}  // namespace
}  // namespace trailray::app
