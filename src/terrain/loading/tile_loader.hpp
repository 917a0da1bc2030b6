#pragma once
// Asynchronous tile loading: a pool of worker threads calls a source's load() for the tiles the
// current view wants, most important first, and keeps the results in a TileMemoryCache.
//
//   loader.request(tiles)   replaces the wanted set (each with a priority, higher first).
//                           Queued tiles that are no longer wanted are dropped and tiles being
//                           loaded that left the view are cancelled (their stop_token fires).
//   loader.get(id)          the decoded tile when it is in memory (render what is there).
//   loader.progress()       wanted / loaded / no data / failed / pending, for a progress bar or
//                           a spinner; wait_until_done() blocks with a progress callback.
//
// Without threads (the page's WebAssembly build, geo/threads.hpp) there are no workers: each
// request() loads a few of the queued tiles on the calling thread. Its sources answer at once
// (the page's fetch tiles over the network themselves, and answer "cancelled" until the bytes are
// there); a cancelled tile stays wanted and is asked for again by a later request().
//
// A failing tile never stops the others: its error is recorded (failures()) and it is not asked
// for again in this loader's lifetime (forget_failures() to retry), so a broken tile does not
// hammer a server each frame. "No data" answers are remembered the same way.

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <queue>
#include <string>
#include <thread>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "geo/threads.hpp"
#include "terrain/loading/stop_token.hpp"
#include "terrain/tile.hpp"
#include "terrain/loading/tile_memory_cache.hpp"

namespace trailray::terrain {

struct TileRequest {
  TileId id;
  double priority = 0.0;  // higher is loaded first
};

struct LoadProgress {
  std::size_t wanted = 0;   // tiles in the current request
  std::size_t loaded = 0;   // of those: in memory
  std::size_t no_data = 0;  // the source has nothing there
  std::size_t failed = 0;   // errors (see failures())
  std::size_t pending() const { return wanted - loaded - no_data - failed; }
  bool done() const { return pending() == 0; }
};

struct TileLoaderOptions {
  unsigned threads = 4;                          // workers; network sources like more
  std::size_t memory_budget_bytes = 512u << 20;  // decoded tiles kept in memory
  std::size_t tiles_per_request = 8;             // without threads: loaded by each request()
};

enum class TileState { unknown, pending, loaded, no_data, failed };

template <class Tile>
class TileLoader {
 public:
  using LoadFunction = std::function<TileResult<Tile>(const TileId&, StopToken)>;

  TileLoader(LoadFunction load, TileLoaderOptions options = {})
      : load_(std::move(load)), cache_(options.memory_budget_bytes), tiles_per_request_(options.tiles_per_request) {
    if (!geo::kThreadsAvailable) return;
    const unsigned n = std::max(1u, options.threads);
    for (unsigned i = 0; i < n; ++i) workers_.emplace_back([this] { work(); });
  }

  ~TileLoader() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
      for (auto& [id, source] : in_flight_) source.request_stop();
      queue_ = {};
    }
    work_ready_.notify_all();
    for (auto& w : workers_) w.join();
  }

  TileLoader(const TileLoader&) = delete;
  TileLoader& operator=(const TileLoader&) = delete;

  // Called (from a worker thread, without locks held) after each tile finishes: a viewer
  // schedules a redraw here.
  void set_on_update(std::function<void()> callback) {
    std::lock_guard lock(mutex_);
    on_update_ = std::move(callback);
  }

  void request(const std::vector<TileRequest>& tiles) {
    {
      std::lock_guard lock(mutex_);
      wanted_.clear();
      queue_ = {};
      for (const auto& r : tiles) {
        if (!wanted_.insert(r.id).second) continue;
        if (state_for_queue(r.id) == TileState::unknown) queue_.push({r.priority, r.id});
      }
      for (auto& [id, source] : in_flight_)
        if (!wanted_.contains(id)) source.request_stop();
    }
    work_ready_.notify_all();
    done_changed_.notify_all();
    if (!geo::kThreadsAvailable) load_on_this_thread(tiles_per_request_);
  }

  std::shared_ptr<const Tile> get(const TileId& id) {
    std::lock_guard lock(mutex_);
    return cache_.get(id);
  }

  TileState state(const TileId& id) const {
    std::lock_guard lock(mutex_);
    return state_locked(id);
  }

  LoadProgress progress() const {
    std::lock_guard lock(mutex_);
    return progress_locked();
  }

  // Errors of failed tiles among the wanted ones ("<source> z/x/y: ..."), in no particular order.
  std::vector<std::string> failures() const {
    std::lock_guard lock(mutex_);
    std::vector<std::string> out;
    for (const auto& id : wanted_)
      if (auto it = failed_.find(id); it != failed_.end()) out.push_back(it->second);
    return out;
  }

  void forget_failures() {
    std::lock_guard lock(mutex_);
    failed_.clear();
  }

  // Blocks until every wanted tile is loaded, empty or failed, or the timeout passes; calls
  // on_progress (if given) about every `tick` and once at the end. True when done.
  bool wait_until_done(std::chrono::milliseconds timeout,
                       const std::function<void(const LoadProgress&)>& on_progress = {},
                       std::chrono::milliseconds tick = std::chrono::milliseconds(100)) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    std::unique_lock lock(mutex_);
    while (true) {
      const LoadProgress p = progress_locked();
      if (on_progress) {
        lock.unlock();
        on_progress(p);
        lock.lock();
      }
      if (p.done()) return true;
      const auto now = std::chrono::steady_clock::now();
      if (now >= deadline) return false;
      done_changed_.wait_until(lock, std::min(deadline, now + tick));
    }
  }

  std::size_t memory_used_bytes() const {
    std::lock_guard lock(mutex_);
    return cache_.used_bytes();
  }

 private:
  struct Queued {
    double priority;
    TileId id;
    bool operator<(const Queued& o) const { return priority < o.priority; }
  };

  TileState state_locked(const TileId& id) const {
    if (cache_.contains(id)) return TileState::loaded;
    if (in_flight_.contains(id)) return TileState::pending;
    if (no_data_.contains(id)) return TileState::no_data;
    if (failed_.contains(id)) return TileState::failed;
    return wanted_.contains(id) ? TileState::pending : TileState::unknown;
  }

  LoadProgress progress_locked() const {
    LoadProgress p;
    p.wanted = wanted_.size();
    for (const auto& id : wanted_) {
      if (cache_.contains(id))
        ++p.loaded;
      else if (no_data_.contains(id))
        ++p.no_data;
      else if (failed_.contains(id))
        ++p.failed;
    }
    return p;
  }

  void work() {
    while (true) {
      TileId id;
      StopSource cancel;
      {
        std::unique_lock lock(mutex_);
        work_ready_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
        if (stopping_) return;
        id = queue_.top().id;
        queue_.pop();
        // Dropped from the view since it was queued, or already being loaded by another worker.
        if (!wanted_.contains(id) || state_for_queue(id) != TileState::unknown) continue;
        in_flight_.emplace(id, cancel);
      }
      finish(id, cancel, load_(id, cancel.get_token()), true);
    }
  }

  // Without workers: up to `count` of the queued tiles, most important first. A tile its source
  // answers "cancelled" for (still on its way) stays wanted; the next request() queues it again.
  void load_on_this_thread(std::size_t count) {
    for (std::size_t done = 0; done < count;) {
      TileId id;
      StopSource cancel;
      {
        std::lock_guard lock(mutex_);
        if (queue_.empty()) return;
        id = queue_.top().id;
        queue_.pop();
        if (!wanted_.contains(id) || state_for_queue(id) != TileState::unknown) continue;
        in_flight_.emplace(id, cancel);
      }
      finish(id, cancel, load_(id, cancel.get_token()), false);
      ++done;
    }
  }

  // Records a loaded tile; a cancelled one that is still wanted is queued again when `requeue`.
  void finish(const TileId& id, const StopSource& cancel, TileResult<Tile> result, bool requeue) {
    std::function<void()> notify;
    {
      std::lock_guard lock(mutex_);
      in_flight_.erase(id);
      if (cancel.stop_requested() || result.status == TileStatus::cancelled) {
        // Left the view while loading; if it came back meanwhile, queue it again.
        if (requeue && wanted_.contains(id)) queue_.push({0.0, id});
      } else if (result.status == TileStatus::ok) {
        cache_.put(id, std::make_shared<const Tile>(std::move(result.tile)),
                   [this](const TileId& t) { return wanted_.contains(t); });
      } else if (result.status == TileStatus::no_data) {
        no_data_.insert(id);
      } else {
        failed_.emplace(id, result.error.empty() ? to_string(id) + ": failed" : result.error);
      }
      notify = on_update_;
    }
    done_changed_.notify_all();
    work_ready_.notify_all();
    if (notify) notify();
  }

  // Like state_locked, but a wanted tile not yet loaded counts as unknown (to be loaded).
  TileState state_for_queue(const TileId& id) const {
    if (cache_.contains(id)) return TileState::loaded;
    if (in_flight_.contains(id)) return TileState::pending;
    if (no_data_.contains(id)) return TileState::no_data;
    if (failed_.contains(id)) return TileState::failed;
    return TileState::unknown;
  }

  static std::string to_string(const TileId& id) { return geo::to_string(id); }

  LoadFunction load_;
  mutable std::mutex mutex_;
  std::condition_variable work_ready_;
  std::condition_variable done_changed_;
  TileMemoryCache<Tile> cache_;
  std::priority_queue<Queued> queue_;
  std::unordered_set<TileId> wanted_;
  std::unordered_map<TileId, StopSource> in_flight_;
  std::unordered_set<TileId> no_data_;
  std::unordered_map<TileId, std::string> failed_;
  std::function<void()> on_update_;
  bool stopping_ = false;
  std::size_t tiles_per_request_ = 8;
  std::vector<std::thread> workers_;  // last: joined before the state above is destroyed
};

}  // namespace trailray::terrain
