// libFuzzer target: the task readers (XCTrack JSON v1, the XCTSK: QR form, XCSoar .tsk XML, IGC C records) over
// arbitrary bytes, then the distances of what they read. Contract: a task or an error, never
// both nor neither; a task has turnpoints with finite coordinates; its distances are finite.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "track/task/task_distance.hpp"
#include "track/task/task_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace tt = trailray::track::task;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const tt::TaskReadResult r = tt::read_task_text(text, "fuzz.xctsk");
  if (r.task.has_value() == r.error.has_value()) std::abort();
  if (!r.task) return 0;
  if (r.task->turnpoints.empty()) std::abort();
  for (const tt::Turnpoint& t : r.task->turnpoints)
    if (!std::isfinite(t.lat) || !std::isfinite(t.lon) || !(t.radius_m >= 0.0)) std::abort();
  // The optimisation costs milliseconds per turnpoint: small tasks only, a few sweeps.
  if (r.task->turnpoints.size() <= 12) {
    tt::OptimiseOptions options;
    options.max_sweeps = 20;
    const tt::TaskDistances d = tt::measure_task(*r.task, options);
    if (!std::isfinite(d.centre_m) || !std::isfinite(d.optimised.distance_m)) std::abort();
  }
  return 0;
}
