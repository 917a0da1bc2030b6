#pragma once
// The per-point values a track is coloured by (`--color-by`), their units and their robust
// range. The renderer only looks colours up (DESIGN.md): everything a metric means lives here.
//
// Values are in the user's units (km/h, m/s, %, m, bpm, rpm, W, s) and NaN where a point has
// none (no time for speed, no heart rate recorded, no ground height for agl): the renderer gives
// NaN a neutral colour, never a wrong one. Never infinite (duplicate timestamps were removed by
// cleaning; metrics return NaN for an undefined rate).

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "track/metrics.hpp"
#include "track/model.hpp"

namespace trailray::track {

enum class ColorMetric {
  solid,
  speed,
  vspeed,
  slope,
  altitude,
  agl,
  hr,
  cadence,
  power,
  time,
  phase,
  density,  // how many tracks pass within a radius (track/density.hpp): needs every track at once
  thermals,  // how many flights climbed in a thermal within a radius: the same, over the climbs
  cover      // against a surface model (track/cover.hpp): 0 open, 1 under cover, 2 below the ground
};

// density and thermals: a count over all the tracks of a scene, not a value of one track's points
// (scene/tracks/track_density.hpp computes them where the tracks are finished together).
inline bool counts_neighbours(ColorMetric m) { return m == ColorMetric::density || m == ColorMetric::thermals; }

// Flight phases (`phase`, track/flight/phase_values.hpp): circling points carry their climb in
// m/s, gliding points this marker value (a category drawn in one fixed colour, not a number on
// the scale), ground and unknown points NaN. Finite and far below any measurement, and above the
// renderer's own "no value" code (-3e38), so it survives the upload and the shader can tell it
// apart; robust_range leaves it out.
inline constexpr float kCategoryValue = -1.0e30f;
inline bool is_category_value(float v) { return v <= -1.0e29f && v >= -1.0e31f; }

// "solid", "speed", "vspeed", "slope", "altitude", "agl", "hr", "cadence", "power", "time", "phase",
// "density", "thermals", "cover".
std::string_view color_metric_name(ColorMetric metric);
std::optional<ColorMetric> parse_color_metric(std::string_view name);  // exact lower-case names
std::vector<std::string_view> color_metric_names();                    // every name, in enum order

// What the legend prints: "Speed", "Vertical speed", "Steepness", "Altitude", "Height above
// ground", "Heart rate", "Cadence", "Power", "Elapsed time"; and the unit: "km/h", "m/s", "%",
// "m", "m", "bpm", "rpm", "W", "" (time is printed as h:mm, see format_color_value); phase:
// "Climb in thermals", "m/s"; density: "Tracks nearby", "tracks"; thermals: "Flights climbing
// nearby", "flights" (the legend names the radius: scene/tracks/track_density.hpp).
std::string_view color_metric_label(ColorMetric metric);
std::string_view color_metric_unit(ColorMetric metric);

// Vertical speed is signed around a meaningful zero: a diverging colormap, a range symmetric
// about 0.
bool color_metric_is_signed(ColorMetric metric);

// A value as the legend prints it, with sensible precision for the metric and no unit
// ("12.5", "-3.2", "1:05" for 3900 s of elapsed time, "2450"): speed with one decimal below
// 100 km/h, whole km/h above; vertical speed one decimal (a sign only when negative); the others
// whole numbers; time as h:mm in whole minutes rounded towards zero (59 s -> "0:00",
// -60 s -> "-0:01"). A value that rounds to zero has no sign; a non-finite value gives "n/a".
std::string format_color_value(ColorMetric metric, double value);

// One value per point of each segment (parallel to track.segments[i].points): the metric at that
// point from the cleaned track and its metrics (compute_metrics of that same track).
// `ground_heights_m` (only for agl): per segment and point, the terrain height below the point
// (NaN where unknown); agl = ele - ground. solid gives an all-NaN vector per segment.
// Elapsed time counts from the track's first timestamp. phase needs the flight analysis and
// gives all-NaN here: its values come from flight::phase_color_values; so do density and thermals
// (their counts need every track: scene/tracks/track_density.hpp); cover too (the scene's tracks hold
// their class against the surface model: scene::Track::cover).
// Throws std::invalid_argument when the shapes do not match the track (metrics only checked for
// the metrics that read them: speed, vspeed, slope, time), or for agl without ground heights.
std::vector<std::vector<float>> color_values(const Track& track, const TrackMetrics& metrics, ColorMetric metric,
                                             const std::vector<std::vector<double>>* ground_heights_m = nullptr);

struct ValueRange {
  double min = 0.0, max = 0.0;
};

// The robust automatic range over every finite value given (several tracks together): from the
// `low_percentile` to the `high_percentile` (linear interpolation between order statistics), so
// one GPS spike does not flatten the colours. Category values (kCategoryValue) are left out. Signed metrics get a range
// symmetric about 0 (the larger magnitude of the two percentiles). A range of zero width is widened to
// +-max(0.5, 1% of |value|) so that a colour scale can still be made. nullopt when there is no
// finite value; std::invalid_argument unless 0 <= low_percentile <= high_percentile <= 100.
std::optional<ValueRange> robust_range(std::span<const std::vector<float>> values, bool symmetric_about_zero,
                                       double low_percentile = 2.0, double high_percentile = 98.0);

// `--range MIN:MAX` (finite, MIN < MAX). nullopt for anything else.
std::optional<ValueRange> parse_value_range(std::string_view text);

}  // namespace trailray::track
