#include "render/gl/frame_profiler.hpp"

#include <EGL/egl.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <numeric>

namespace trailray::render {

// The extension's entry points (ES 3 core has glGenQueries, but not the 64-bit result read).
struct FrameProfiler::GlTimerFunctions {
  PFNGLBEGINQUERYEXTPROC begin_query = nullptr;
  PFNGLENDQUERYEXTPROC end_query = nullptr;
  PFNGLGETQUERYOBJECTUIVEXTPROC get_query_uiv = nullptr;
  PFNGLGETQUERYOBJECTUI64VEXTPROC get_query_ui64v = nullptr;

  bool complete() const { return begin_query && end_query && get_query_uiv && get_query_ui64v; }
};

struct FrameProfiler::PassRecord {
  std::string name;
  std::deque<double> cpu_ms, gpu_ms;   // one sample per frame that ran the pass, newest last
  std::optional<double> frame_cpu_ms;  // this frame's sum so far (a pass may run twice)
};

// A frame's GPU queries, read together once the last of them has its result.
struct FrameProfiler::PendingQuery {
  std::size_t frame = 0;
  std::chrono::steady_clock::time_point begun;         // no GPU time in the frame can be longer than since then
  std::vector<std::pair<std::size_t, Query>> queries;  // pass index, query
};

namespace {

template <class F>
F lookup(const char* name) {
  return reinterpret_cast<F>(eglGetProcAddress(name));
}

void push_sample(std::deque<double>& samples, double value, std::size_t window) {
  samples.push_back(value);
  while (samples.size() > window) samples.pop_front();
}

std::optional<double> mean_of(const std::deque<double>& samples) {
  if (samples.empty()) return std::nullopt;
  return std::accumulate(samples.begin(), samples.end(), 0.0) / static_cast<double>(samples.size());
}

std::optional<double> median_of(const std::deque<double>& samples) {
  if (samples.empty()) return std::nullopt;
  std::vector<double> sorted(samples.begin(), samples.end());
  std::sort(sorted.begin(), sorted.end());
  const std::size_t mid = sorted.size() / 2;
  return sorted.size() % 2 == 1 ? sorted[mid] : 0.5 * (sorted[mid - 1] + sorted[mid]);
}

std::string cell(const std::optional<double>& ms) {
  if (!ms) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", *ms);
  return text;
}

std::string pad_left(const std::string& text, std::size_t width) {
  return text.size() >= width ? text : std::string(width - text.size(), ' ') + text;
}

std::string pad_right(const std::string& text, std::size_t width) {
  return text.size() >= width ? text : text + std::string(width - text.size(), ' ');
}

}  // namespace

FrameProfiler::FrameProfiler(const GlCapabilities& caps, std::size_t frame_window)
    : frame_window_(std::max<std::size_t>(frame_window, 1)) {
  for (std::string_view name : kStandardPasses) passes_.push_back(PassRecord{std::string(name), {}, {}, {}});
  if (caps.disjoint_timer_query) {
    static const GlTimerFunctions functions = [] {
      GlTimerFunctions f;
      f.begin_query = lookup<PFNGLBEGINQUERYEXTPROC>("glBeginQueryEXT");
      f.end_query = lookup<PFNGLENDQUERYEXTPROC>("glEndQueryEXT");
      f.get_query_uiv = lookup<PFNGLGETQUERYOBJECTUIVEXTPROC>("glGetQueryObjectuivEXT");
      f.get_query_ui64v = lookup<PFNGLGETQUERYOBJECTUI64VEXTPROC>("glGetQueryObjectui64vEXT");
      return f;
    }();
    if (functions.complete()) {
      gl_ = &functions;
      gpu_timing_ = true;
      // Reading the flag clears it: a disjoint event from before profiling must not drop frame 1.
      GLint disjoint = 0;
      glGetIntegerv(GL_GPU_DISJOINT_EXT, &disjoint);
    }
  }
}

FrameProfiler::~FrameProfiler() {
  // A query left active would make the next glBeginQuery of the context fail.
  if (gpu_timing_ && open_pass_) gl_->end_query(GL_TIME_ELAPSED_EXT);
}

FrameProfiler::PassRecord& FrameProfiler::record_for(std::string_view name) {
  for (PassRecord& record : passes_) {
    if (record.name == name) return record;
  }
  passes_.push_back(PassRecord{std::string(name), {}, {}, {}});
  return passes_.back();
}

void FrameProfiler::begin_frame() {
  const std::size_t frame = frames_ended_ + 1;
  if (in_frame_)
    throw ProfilerError("frame profiler: frame " + std::to_string(frame + 1) + " begun before frame " +
                        std::to_string(frame) + " ended");
  in_frame_ = true;
  if (gpu_timing_) {
    collect_gpu_results(false);
    pending_.push_back(PendingQuery{frame, std::chrono::steady_clock::now(), {}});
  }
}

void FrameProfiler::begin_pass(std::string_view name) {
  const std::string frame = std::to_string(frames_ended_ + 1);
  if (!in_frame_)
    throw ProfilerError("frame profiler: pass '" + std::string(name) + "' begun outside a frame (begin_frame first)");
  if (open_pass_)
    throw ProfilerError("frame profiler: pass '" + std::string(name) + "' begun while pass '" + *open_pass_ +
                        "' is still open in frame " + frame + " (passes do not nest)");
  PassRecord& record = record_for(name);
  open_pass_ = record.name;
  if (gpu_timing_) {
    // Queries are reused once their results are read: no GL allocation per pass and frame.
    Query query;
    if (free_queries_.empty()) {
      query = Query::create();
    } else {
      query = std::move(free_queries_.back());
      free_queries_.pop_back();
    }
    gl_->begin_query(GL_TIME_ELAPSED_EXT, query.id());
    pending_.back().queries.emplace_back(static_cast<std::size_t>(&record - passes_.data()), std::move(query));
  }
  open_since_ = std::chrono::steady_clock::now();
}

void FrameProfiler::end_pass(std::string_view name) {
  const auto now = std::chrono::steady_clock::now();
  const std::string frame = std::to_string(frames_ended_ + 1);
  if (!open_pass_)
    throw ProfilerError("frame profiler: pass '" + std::string(name) + "' ended but not begun in frame " + frame);
  if (*open_pass_ != name)
    throw ProfilerError("frame profiler: pass '" + std::string(name) + "' ended while pass '" + *open_pass_ +
                        "' is open in frame " + frame);
  if (gpu_timing_) gl_->end_query(GL_TIME_ELAPSED_EXT);
  PassRecord& record = record_for(name);
  const double ms = std::chrono::duration<double, std::milli>(now - open_since_).count();
  record.frame_cpu_ms = record.frame_cpu_ms.value_or(0.0) + ms;
  open_pass_.reset();
}

void FrameProfiler::end_frame() {
  const std::size_t frame = frames_ended_ + 1;
  if (!in_frame_) throw ProfilerError("frame profiler: frame " + std::to_string(frame) + " ended but not begun");
  std::optional<std::string> left_open = std::move(open_pass_);
  open_pass_.reset();
  if (left_open && gpu_timing_) {
    // The half-timed pass's query is ended and dropped with its frame's GPU results.
    gl_->end_query(GL_TIME_ELAPSED_EXT);
    for (auto& [pass, query] : pending_.back().queries) free_queries_.push_back(std::move(query));
    pending_.pop_back();
  }
  for (PassRecord& record : passes_) {
    if (record.frame_cpu_ms && !left_open) push_sample(record.cpu_ms, *record.frame_cpu_ms, frame_window_);
    record.frame_cpu_ms.reset();
  }
  in_frame_ = false;
  ++frames_ended_;
  if (left_open)
    throw ProfilerError("frame profiler: frame " + std::to_string(frame) + " ended with pass '" + *left_open +
                        "' still open (missing end_pass); the frame is not counted");
  if (gpu_timing_) collect_gpu_results(false);
}

void FrameProfiler::finish() {
  if (!gpu_timing_) return;
  glFinish();
  collect_gpu_results(true);
}

void FrameProfiler::collect_gpu_results(bool wait) {
  // Only frames that have ended: the current frame's queries may still be open.
  std::vector<PendingQuery> ready;
  while (!pending_.empty() && pending_.front().frame <= frames_ended_) {
    PendingQuery& oldest = pending_.front();
    bool available = true;
    for (const auto& [pass, query] : oldest.queries) {
      GLuint done = 0;
      gl_->get_query_uiv(query.id(), GL_QUERY_RESULT_AVAILABLE_EXT, &done);
      if (!done) available = false;
    }
    if (!available && !wait) break;
    ready.push_back(std::move(oldest));
    pending_.pop_front();
  }
  if (ready.empty()) return;
  // The disjoint flag covers the interval since it was last read: a set flag spoils every
  // result read now, so those frames get no GPU sample.
  GLint disjoint = 0;
  glGetIntegerv(GL_GPU_DISJOINT_EXT, &disjoint);
  const auto now = std::chrono::steady_clock::now();
  for (PendingQuery& frame : ready) {
    std::vector<std::optional<double>> per_pass(passes_.size());
    for (auto& [pass, query] : frame.queries) {
      GLuint64 ns = 0;
      gl_->get_query_ui64v(query.id(), GL_QUERY_RESULT_EXT, &ns);
      per_pass[pass] = per_pass[pass].value_or(0.0) + static_cast<double>(ns) * 1e-6;
      free_queries_.push_back(std::move(query));
    }
    if (disjoint) continue;
    // A time longer than the wall time since the frame began is not a measurement: llvmpipe
    // answers a query that saw no rendered scene with an absolute clock reading (hours), which
    // would swamp every mean. Such a frame is dropped like a disjoint one.
    const double bound_ms = std::chrono::duration<double, std::milli>(now - frame.begun).count();
    if (std::any_of(per_pass.begin(), per_pass.end(), [&](const auto& ms) { return ms && *ms > bound_ms; })) continue;
    for (std::size_t i = 0; i < passes_.size(); ++i) {
      if (per_pass[i]) push_sample(passes_[i].gpu_ms, *per_pass[i], frame_window_);
    }
  }
}

FrameProfiler::Scope::Scope(FrameProfiler& profiler, std::string_view name) : profiler_(profiler), name_(name) {
  profiler_.begin_pass(name_);
}

FrameProfiler::Scope::~Scope() {
  try {
    profiler_.end_pass(name_);
  } catch (const ProfilerError&) {
    // Ended already by hand (or the frame was ended around it): end_pass has reported nothing
    // worth terminating for, and a destructor must not throw.
  }
}

std::vector<PassTimes> FrameProfiler::times() const {
  std::vector<PassTimes> out;
  for (const PassRecord& record : passes_) {
    PassTimes t;
    t.name = record.name;
    t.cpu_samples = record.cpu_ms.size();
    t.gpu_samples = record.gpu_ms.size();
    t.cpu_mean_ms = mean_of(record.cpu_ms);
    t.cpu_median_ms = median_of(record.cpu_ms);
    t.gpu_mean_ms = mean_of(record.gpu_ms);
    t.gpu_median_ms = median_of(record.gpu_ms);
    out.push_back(std::move(t));
  }
  return out;
}

std::string FrameProfiler::table() const {
  const std::vector<PassTimes> rows = times();
  std::size_t name_width = 4;
  for (const PassTimes& row : rows) name_width = std::max(name_width, row.name.size());
  constexpr std::size_t kColumn = 12;
  std::string out = "frame profile over " + std::to_string(std::min(frames_ended_, frame_window_)) + " of " +
                    std::to_string(frames_ended_) + " frames, ms (GPU: " +
                    (gpu_timing_ ? "EXT_disjoint_timer_query" : "n/a, no EXT_disjoint_timer_query") + ")\n";
  out += pad_right("pass", name_width) + pad_left("CPU mean", kColumn) + pad_left("CPU median", kColumn) +
         pad_left("GPU mean", kColumn) + pad_left("GPU median", kColumn) + "\n";
  for (const PassTimes& row : rows) {
    out += pad_right(row.name, name_width) + pad_left(cell(row.cpu_mean_ms), kColumn) +
           pad_left(cell(row.cpu_median_ms), kColumn) + pad_left(cell(row.gpu_mean_ms), kColumn) +
           pad_left(cell(row.gpu_median_ms), kColumn) + "\n";
  }
  return out;
}

void wait_for_gpu() { glFinish(); }

}  // namespace trailray::render
