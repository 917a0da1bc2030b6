#pragma once
// A few independent jobs (one per file) on all cores: a small pool of std::thread that take the
// jobs in index order, while the calling thread reports progress. No job may touch what another
// one does; each writes its own result slot, so results come back in the input order whatever
// finished first.

#include <cstddef>
#include <functional>

#include "track/density.hpp"

namespace trailray::app {

// The threads to use: std::thread::hardware_concurrency(), at least 1.
unsigned default_job_threads();

struct ParallelJobsOptions {
  unsigned threads = 0;  // 0: default_job_threads(); 1: every job on the calling thread, in order
  // Called on the calling thread only, with the jobs done so far: now and then while they run
  // (at most about ten times a second) and once at the end. May be empty.
  std::function<void(std::size_t done, std::size_t count)> progress;
};

// Runs job(0) .. job(count - 1). A job returns false to say that the jobs after it in the order
// need not run: jobs not yet started whose index is above it are skipped (those below it always
// run, so "the first job that failed" is the same as in a sequential run). A job must not throw
// (catch inside and keep the exception in its result). Returns the number of jobs that ran.
std::size_t run_parallel_jobs(std::size_t count, const std::function<bool(std::size_t)>& job,
                              const ParallelJobsOptions& options = {});

// run_parallel_jobs as the track layer's ParallelFor (neighbour counts), every job run.
track::ParallelFor parallel_for(unsigned threads = 0);

}  // namespace trailray::app
