// libFuzzer target for the track layer's option text and colour values (`--range`,
// `--occlusion-fade`, `--color-by` names) and the numbers they turn into. The first byte picks
// the parser; each must answer or refuse, never crash, and what it accepts must be sane:
//   range    parse_value_range -> finite MIN < MAX, or nullopt
//   metric   parse_color_metric -> a metric whose name parses back to itself, or nullopt
//   values   the bytes as floats through robust_range and format_color_value: a range with
//            finite ends and min <= max; every value prints as text
//   points   read_points_csv (--labels FILE): an error naming the file, or waypoints with
//            valid coordinates and finite elevations

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>
#include <vector>

#include "track/color_values.hpp"
#include "track/io/points_csv.hpp"
#include "track/io/readers.hpp"

namespace {

using namespace trailray::track;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "broken contract: %s\n", what);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  switch (data[0] % 4) {
    case 0: {
      if (const auto range = parse_value_range(text))
        check(std::isfinite(range->min) && std::isfinite(range->max) && range->min < range->max, "range");
      break;
    }
    case 1: {
      if (const auto metric = parse_color_metric(text))
        check(parse_color_metric(color_metric_name(*metric)) == metric, "metric name round trip");
      break;
    }
    case 3: {
      const ReadResult r = read_points_csv(text, "fuzz.csv");
      check(r.ok() || (r.error->file == "fuzz.csv" && r.file.waypoints.empty()), "points error");
      for (const Waypoint& w : r.file.waypoints)
        check(valid_coordinates(w.point.lat, w.point.lon) && (std::isnan(w.point.ele) || std::isfinite(w.point.ele)),
              "points coordinates");
      break;
    }
    default: {
      std::vector<float> values(text.size() / sizeof(float));
      if (!values.empty()) std::memcpy(values.data(), text.data(), values.size() * sizeof(float));
      const std::vector<std::vector<float>> all{values};
      const bool symmetric = (data[0] & 4) != 0;
      if (const auto range = robust_range(all, symmetric)) {
        check(std::isfinite(range->min) && std::isfinite(range->max) && range->min <= range->max, "robust range");
        if (symmetric) check(range->min == -range->max, "symmetric range");
      }
      const auto metric = static_cast<ColorMetric>(data[0] % 10);
      for (float v : values) check(!format_color_value(metric, v).empty(), "formatted value");
      break;
    }
  }
  return 0;
}
