#pragma once
// Cancellation of tile work: std::stop_token and std::stop_source where the standard library has
// them (native builds), a minimal stand-in where it has not (Emscripten's libc++ 13, whose page
// build also has no threads: a flag shared between the source and its tokens is all it needs).

#if defined(__EMSCRIPTEN__)
#include <atomic>
#include <memory>
#else
#include <stop_token>
#endif

namespace trailray::terrain {

#if defined(__EMSCRIPTEN__)
class StopToken {
 public:
  StopToken() = default;
  bool stop_requested() const noexcept { return stopped_ && stopped_->load(); }
  bool stop_possible() const noexcept { return stopped_ != nullptr; }

 private:
  friend class StopSource;
  explicit StopToken(std::shared_ptr<std::atomic<bool>> stopped) : stopped_(std::move(stopped)) {}
  std::shared_ptr<std::atomic<bool>> stopped_;
};

class StopSource {
 public:
  StopToken get_token() const noexcept { return StopToken(stopped_); }
  bool request_stop() noexcept { return !stopped_->exchange(true); }
  bool stop_requested() const noexcept { return stopped_->load(); }

 private:
  std::shared_ptr<std::atomic<bool>> stopped_ = std::make_shared<std::atomic<bool>>(false);
};
#else
using StopToken = std::stop_token;
using StopSource = std::stop_source;
#endif

}  // namespace trailray::terrain
