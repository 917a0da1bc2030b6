#pragma once
// The interactive viewer's state without a window (issue 6): the loaded tracks with the per-point
// numbers the profile chart, the tooltip and the replay read; the settings the panels edit and
// the shell (view_command) turns into SceneRenderOptions; what is hovered and selected; the
// replay clock. Everything here is plain data and pure functions, testable without GL or ImGui;
// the panels that edit it are declared in viewer_panels.hpp.
//
// Points are numbered "flat": the points of a track's non-empty segments one after the other,
// the order TrackBuffer stores them in, so a point index means the same thing to the chart, the
// 3D picking and the replay marker.

#include <glm/glm.hpp>

#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "app/track_scene.hpp"
#include "app/track_style_options.hpp"
#include "scene/colormap.hpp"
#include "render/passes/terrain_pass.hpp"
#include "render/passes/track_buffer.hpp"
#include "render/passes/track_pass.hpp"
#include "terrain/tile_source.hpp"
#include "track/color_values.hpp"
#include "track/metrics.hpp"
#include "track/model.hpp"
#include "track/statistics.hpp"
#include "track/summary.hpp"

namespace trailray::app::view {

// One loaded track (or route) and everything the viewer shows of it. Per-point vectors are
// parallel (flat point index); NaN where a point has no such value.
struct ViewerTrack {
  std::string name;                        // as `render` names it (track name, else file name and number)
  std::string source;                      // the file it came from
  track::Track cleaned;                    // after clean_track (what is drawn and measured)
  track::TrackMetrics metrics;             // compute_metrics(cleaned)
  track::TrackSummary summary;             // raw and clean statistics, as `trailray stats` prints them
  std::vector<std::size_t> segment_first;  // flat index of each non-empty segment's first point

  std::vector<double> distance_m;      // cumulative 2D distance from the start (gaps add nothing)
  std::vector<double> time_unix_s;     // timestamp (NaN: none)
  std::vector<double> elapsed_s;       // since the track's first timestamp
  std::vector<double> altitude_m;      // recorded elevation (NaN: none)
  std::vector<double> ground_m;        // terrain height below (NaN: no terrain / not loaded yet)
  std::vector<double> speed_kmh;       // windowed horizontal speed
  std::vector<double> vspeed_ms;       // windowed vertical speed, positive climbing
  std::vector<double> heart_rate_bpm;  // recorded (NaN: none)
  std::vector<glm::dvec3> ecef;        // where the point is drawn (points without elevation on the ground)

  // What the renderer draws: build_track_scene's geometry, values of settings.color_by.
  scene::TrackGeometry geometry;
  std::size_t geometry_revision = 0;  // bumped when geometry changes: re-upload the TrackBuffer

  // Per-track appearance (track list panel).
  bool visible = true;
  glm::vec3 color_srgb{1.0f, 0.0f, 0.0f};
  bool by_value = true;  // coloured by settings.color_by (when not solid), else color_srgb

  std::size_t point_count() const { return distance_m.size(); }
  // The first and last timestamp (nullopt: fewer than one timed point).
  std::optional<double> start_time() const;
  std::optional<double> end_time() const;
  // The segment holding a flat point index.
  std::size_t segment_of(std::size_t point) const;
};

// Flat per-point vectors from a cleaned track. `ground_m` per segment and point (empty: none).
// Throws std::invalid_argument when the metrics do not match the track.
void fill_point_arrays(ViewerTrack& track, const std::vector<std::vector<double>>& ground_m = {});

// The viewer's tracks from files: the same names, positions, colours and colour values as
// build_track_scene (it is called for them, keeping its analysis), plus each cleaned track, its
// metrics, its summary and the per-point arrays: every track is cleaned and measured once.
// `inputs.heights` may be nullptr (ground heights NaN; set_ground_heights fills them in later).
// Throws what build_track_scene throws.
std::vector<ViewerTrack> build_viewer_tracks(const std::vector<LoadedTrackFile>& files, const TrackStyle& style,
                                             TrackSceneInputs inputs,
                                             const std::function<void(const std::string&)>& warn);

// Samples the terrain below every point (may read tiles: call off the frame loop).
void set_ground_heights(ViewerTrack& track, terrain::HeightSource& heights);

// Replaces the colour values in each track's geometry by `metric`'s (NaN for solid) and bumps
// geometry_revision. Throws std::invalid_argument for agl on a track without ground heights.
void apply_color_metric(std::vector<ViewerTrack>& tracks, track::ColorMetric metric);

// Curtains (walls down to the ground) on or off: sets each line's heights above the ground from
// altitude - ground height (NaN where either is unknown: no wall there), or clears them; bumps
// geometry_revision.
void apply_curtain(std::vector<ViewerTrack>& tracks, bool on);

// The statistics of flat points [first, last] (inclusive; clamped) of a track: the track cut to
// those points (its segments kept), cleaned metrics recomputed on the cut, track_statistics on it:
// what `trailray stats` says of a file holding just that part. nullopt when first > last.
std::optional<track::Statistics> range_statistics(const ViewerTrack& track, std::size_t first, std::size_t last,
                                                  const track::AnalysisOptions& analysis = {});
// The cut itself (exposed for tests and for exporting a selection).
track::Track cut_track(const ViewerTrack& track, std::size_t first, std::size_t last);

// Tooltip of a point: "time", "altitude", "height above ground", "speed", "vertical speed",
// "heart rate", one line each as "label: value unit" (km/h, m/s, m, bpm; the time as
// "YYYY-MM-DD hh:mm:ss UTC"); a missing value reads "—". Empty for an index out of range.
std::vector<std::string> tooltip_lines(const ViewerTrack& track, std::size_t point);

// ---------------------------------------------------------------------------------------------

struct HoverState {
  int track = -1;           // -1: nothing hovered
  std::size_t point = 0;    // flat point index
  bool from_chart = false;  // true: the chart set it (the 3D view marks the point); false: the 3D view
};

// A drag-selected range on the profile chart (flat point indices, inclusive).
struct ChartSelection {
  int track = -1;  // -1: none
  std::size_t first = 0, last = 0;
  std::optional<track::Statistics> statistics;  // range_statistics, set when the drag ends
};

enum class ChartAxis { distance, time };

// Everything the panels edit. The shell turns these into SceneRenderOptions every frame.
struct ViewerSettings {
  // Shading. NaN: the shell picks (the tracks' first time, else today's noon at their place).
  double sun_time_unix = std::numeric_limits<double>::quiet_NaN();
  bool shadows = true;
  bool ssao = true;
  bool atmosphere = true;
  render::SnowCover snow;

  // Tracks: one colour scale for all (the renderer and the legend have one).
  track::ColorMetric color_by = track::ColorMetric::solid;
  scene::Colormap colormap = scene::Colormap::turbo;
  std::optional<track::ValueRange> range;  // nullopt: the robust automatic range of the visible tracks
  render::TrackWidth width;
  render::TrackOcclusion occlusion;
  bool curtain = false;
  bool legend = true;

  // Chart.
  ChartAxis chart_axis = ChartAxis::distance;

  // Which windows are open.
  bool show_menu = true;  // the main menu bar that reopens closed windows
  bool show_tracks = true, show_statistics = true, show_shading = false, show_occlusion = false, show_profiler = false,
       show_chart = true, show_replay = true;
};

// Settings from the command line's track style (the viewer starts as `render` would draw).
ViewerSettings settings_from_style(const TrackStyle& style);

// The colour scale in use: settings.range, else the robust range over the visible tracks coloured
// by value (nullopt: solid, or no value anywhere).
std::optional<track::ValueRange> effective_range(const std::vector<ViewerTrack>& tracks,
                                                 const ViewerSettings& settings);
// What the renderer's track pass needs from the settings (range from effective_range).
render::TrackSceneSettings track_scene_settings(const std::vector<ViewerTrack>& tracks, const ViewerSettings& settings);

// ---------------------------------------------------------------------------------------------

enum class FollowMode { off, chase, orbit };

// Where a track is at a clock time: between points `point` and `point + 1` (fraction 0..1 of the
// way), or on a point (fraction 0). Before the track's start it waits at its first timed point,
// after its end at its last; across a segment gap it waits at the gap's start (never bridged).
struct TrackPosition {
  bool valid = false;     // false: the track has no timed point
  bool active = false;    // the time lies within the track's start..end
  std::size_t point = 0;  // flat index
  double fraction = 0.0;
  glm::dvec3 ecef{0.0};
};
TrackPosition position_at(const ViewerTrack& track, double time_unix_s);

struct TimeSpan {
  double start = 0.0, end = 0.0;  // unix seconds
};
// From the earliest start to the latest end of the tracks with times (nullopt: none has one).
std::optional<TimeSpan> common_time_span(const std::vector<ViewerTrack>& tracks);

// One clock for all tracks: time runs at `speed` times the wall clock while playing, and stops
// (pauses) at the span's end.
class ReplayClock {
 public:
  static constexpr double kMinSpeed = 1.0, kMaxSpeed = 1000.0;

  void set_span(const TimeSpan& span);  // keeps the time when it is inside, else goes to the start
  const std::optional<TimeSpan>& span() const { return span_; }
  double time() const { return time_; }
  double speed() const { return speed_; }
  bool playing() const { return playing_; }
  // 0..1 along the span (0 without a span).
  double fraction() const;

  void play();  // at the end: starts over
  void pause() { playing_ = false; }
  void toggle() { playing_ ? pause() : play(); }
  void set_speed(double speed);       // clamped to kMinSpeed..kMaxSpeed
  void seek(double time_unix_s);      // clamped to the span
  void seek_fraction(double f);       // 0..1
  void advance(double wall_seconds);  // moves the time when playing

  FollowMode follow = FollowMode::off;
  int follow_track = 0;  // the track the camera follows

 private:
  std::optional<TimeSpan> span_;
  double time_ = 0.0;
  double speed_ = 10.0;
  bool playing_ = false;
};

// ---------------------------------------------------------------------------------------------

// The frame profiler's rows as the profiler panel shows them (a plain table, so the panel does not
// need a GL context; profiler_table() in viewer_panels.hpp fills it from a render::FrameProfiler).
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

struct ViewerModel {
  std::vector<ViewerTrack> tracks;
  ViewerSettings settings;
  HoverState hover;
  ChartSelection selection;
  int selected_track = -1;  // the statistics panel's track (-1: none)
  ReplayClock clock;
  ProfilerTable profile;
  std::vector<std::string> errors;  // files that could not be read etc., shown in a window
  track::AnalysisOptions analysis;  // how the tracks were cleaned and measured (range statistics)
  bool loading = false;             // terrain still streaming (the shell sets it)
};

// What the user asked for in the panels this frame, for the shell to carry out.
struct PanelActions {
  int fly_to_track = -1;  // "fly to" pressed on a track (-1: none)
};

// Draws every open window (track list, statistics, shading, occlusion, profiler, profile chart,
// replay, errors) and applies their edits to the model. Call each frame between ImGui::NewFrame
// and ImGui::Render; `wall_seconds` since the last frame drives the replay clock. Colour-by
// changes recompute the tracks' values (watch ViewerTrack::geometry_revision).
PanelActions draw_panels(ViewerModel& model, double wall_seconds);

}  // namespace trailray::app::view
