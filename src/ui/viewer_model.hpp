#pragma once
// The interactive viewer's state without a window: the scene's tracks and style (the same
// scene::TrackSet and scene::Style `render` draws), what the panels show and edit, what is
// hovered and selected, the replay clock. Plain data, testable without GL or ImGui; the panels
// that edit it are in viewer_panels.hpp, the replay in replay.hpp.

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scene/style.hpp"
#include "scene/tracks/track_set.hpp"
#include "scene/volumes/volumes.hpp"
#include "scene/pins/waypoints.hpp"
#include "track/color_values.hpp"
#include "track/density.hpp"
#include "track/statistics.hpp"
#include "ui/places_statistics.hpp"
#include "track/summary.hpp"
#include "ui/film_state.hpp"
#include "ui/replay.hpp"

namespace trailray::ui {

struct HoverState {
  int track = -1;           // -1: no track point hovered
  std::size_t point = 0;    // flat point index
  bool from_chart = false;  // true: the chart set it (the 3D view marks the point); false: the 3D view
  int waypoint = -1;        // a pin hovered in the 3D view (index into ViewerModel::waypoints), -1: none
  int volume = -1;          // an airspace's wall under the cursor (index into ViewerModel::volumes), -1: none
};

// A drag-selected range on the profile chart (flat point indices, inclusive).
struct ChartSelection {
  int track = -1;  // -1: none
  std::size_t first = 0, last = 0;
  std::optional<track::Statistics> statistics;  // range_statistics, set when the drag ends
};

enum class ChartAxis { distance, time };

// Everything the panels edit.
struct ViewerSettings {
  scene::Style style;  // as `render` draws: the command line's, then the panels' edits
  // The sun's time. NaN: the tracks' first day at noon (today's noon at their place without times).
  double sun_time_unix = std::numeric_limits<double>::quiet_NaN();
  ChartAxis chart_axis = ChartAxis::distance;
  // Which windows are open.
  bool show_menu = true;  // the main menu bar that reopens closed windows
  bool show_tracks = true, show_statistics = true, show_shading = false, show_occlusion = false, show_profiler = false,
       show_chart = true, show_replay = true, show_film = false;
  bool show_waypoints = true;  // the pins and labels of waypoints and places (--no-waypoints: false)
  bool show_airspace = true;   // the volumes of --airspace
  bool moving_frame = true;    // a cheaper frame while the camera moves (moving_frame.hpp)
};

// The frame profiler's rows as the profiler panel shows them (a plain table, so the panel does not
// need a GL context; profiler_table() fills it from a render::FrameProfiler).
struct ProfilerRow {
  std::string pass;
  std::optional<double> cpu_ms, gpu_ms;
};
struct ProfilerTable {
  std::vector<ProfilerRow> rows;
  double fps = 0.0;
  double frame_ms = 0.0;
  // Terrain on the GPU (held now, and the budgets least recently used tiles are freed down to).
  std::size_t mesh_bytes = 0, mesh_budget_bytes = 0, imagery_bytes = 0, imagery_budget_bytes = 0;
};

// The colour scale in use (scene::color_range), computed again only when something it depends on
// changed: the metric, the given range, or a track's visibility, colouring or revision. A robust
// range is a percentile over every value of every track: too costly to take several times a frame.
class ColorRangeCache {
 public:
  const std::optional<track::ValueRange>& get(const scene::TrackSet& tracks, const scene::Style& style);

 private:
  struct Key {
    track::ColorMetric metric = track::ColorMetric::solid;
    std::optional<std::pair<double, double>> range;
    std::vector<std::uint64_t> tracks;  // per track: id, revision, visible and by_value packed
    bool operator==(const Key&) const = default;
  };
  std::optional<Key> key_;
  std::optional<track::ValueRange> value_;
};

struct ViewerModel {
  scene::TrackSet tracks;
  scene::WaypointSet waypoints;  // the files' waypoints (as they load), then the places of --labels
  scene::VolumeSet volumes;      // --task: the task's cylinders, then the airspaces of --airspace
  ViewerSettings settings;
  HoverState hover;
  ChartSelection selection;
  int selected_track = -1;  // the statistics panel's track (-1: none)
  // --places: the summits and huts around the tracks; the statistics panel lists those the
  // selected track reached (worked out once per track revision).
  std::vector<track::places::Place> visit_places;
  PlacesVisitCache places_visited;
  ReplayClock clock;
  FilmSettings film;       // the replay panel's "record film" (the desktop's; the page has none)
  FilmStatus film_status;  // the recording (the shell updates it)
  // How the panels' recolouring spreads density and thermal counts over the cores (the desktop:
  // a pool; empty: on the calling thread, as in the page).
  track::ParallelFor parallel_for;
  // The ground where no terrain is known (the tracks' lowest point, as the tracks were built
  // with): where a curtain switched on in the panels goes down to.
  double neutral_ground_m = std::numeric_limits<double>::quiet_NaN();
  // Whether the viewer draws a cheaper frame while the camera moves (the desktop's; the page
  // draws the full frame): the shading panel offers the switch only then.
  bool offers_moving_frame = true;
  ProfilerTable profile;
  std::vector<std::string> errors;  // files that could not be read etc., shown in a window
  track::AnalysisOptions analysis;  // how the tracks were cleaned and measured (range statistics)
  bool loading = false;             // terrain still streaming (the shell sets it)
  // The track list's rows as last drawn (pixels, 0: not drawn yet), so that rows scrolled out of
  // sight are skipped by their height: a season of 10,000 tracks costs the rows on screen only.
  std::vector<float> track_row_heights;
  std::string track_filter;  // the track list's filter (names containing it, any case)

  // The colour scale in use (cached).
  const std::optional<track::ValueRange>& color_range() { return color_range_.get(tracks, settings.style); }

 private:
  ColorRangeCache color_range_;
};

// Every track's colour values for `metric` (none for solid); density and thermals counted over
// all the tracks within `neighbour_radius_m` (nullopt: the metric's default), spread by `parallel`.
// Throws std::invalid_argument for agl on a track without ground heights.
void apply_color_metric(scene::TrackSet& tracks, track::ColorMetric metric,
                        std::optional<double> neighbour_radius_m = std::nullopt,
                        const track::ParallelFor& parallel = {});
// The replay clock spans every track with times: tracks added later widen it (the panels keep it
// so each frame, the session when tracks arrive).
void keep_clock_span(ViewerModel& model);
// Curtains on or off for every track.
// Where the ground is unknown the walls go down to `neutral_ground_m` (NaN: no wall there).
void apply_curtain(scene::TrackSet& tracks, bool on,
                   double neutral_ground_m = std::numeric_limits<double>::quiet_NaN());

}  // namespace trailray::ui
