#pragma once
// From track files to scene tracks: each track (and route) cleaned and measured once; its points
// placed in ECEF once (points without an elevation on the terrain, or the neutral ground); the
// colour values of the style's metric; curtain heights; the per-point numbers the viewer reads.
// Segments stay apart: gaps are never bridged.

#include <limits>
#include <vector>

#include "scene/diagnostics.hpp"
#include "scene/style.hpp"
#include "scene/tracks/track_files.hpp"
#include "scene/tracks/track_set.hpp"
#include "terrain/sources/tile_source.hpp"
#include "track/density.hpp"
#include "track/statistics.hpp"

namespace trailray::scene {

struct TrackBuildOptions {
  terrain::HeightSource* heights = nullptr;  // nullptr: no terrain (agl impossible)
  double neutral_ground_m = 0.0;             // where there is no terrain height
  track::AnalysisOptions analysis;           // cleaning and metric windows
  // For a viewer that inspects the tracks: each track's summary (raw and clean statistics) and
  // the terrain under every point when there are heights. Without it only what is drawn: the
  // terrain where the style needs it (agl, curtains, points without elevation), no summary.
  bool inspect = false;
  // Each recorded track's flight analysis (Track::flights): also done for inspect and for
  // --color-by phase, which read it.
  // (with the default FlightOptions, as `trailray flight`).
  bool analyse_flights = false;
  // A surface model beside the terrain (canopy and buildings, --surface): each point's cover
  // (Track::cover) against the two; nullptr: none. Needs `heights`.
  terrain::HeightSource* surface = nullptr;
};

// The tracks of the files, in order (each file's tracks, then its routes), with colours from
// `style.colors` or the palette counted from `first_palette_index` (recorded tracks only: routes
// are is_route, in `style.route_color`, never by value, their values the metres along them). Throws std::runtime_error
// for what the user must change (agl without terrain, a --color count that matches neither 1
// nor the number of tracks). Notes (no value for the metric anywhere) go to `diagnostics`.
std::vector<Track> build_tracks(const std::vector<LoadedTrackFile>& files, const TrackStyle& style,
                                const TrackBuildOptions& options, Diagnostics& diagnostics,
                                std::size_t first_palette_index = 0);

// build_tracks in two steps, so that files can be built apart (on several threads: this reads the
// file and `options.heights`, which is thread-safe, and nothing else shared). The tracks of one
// file, in build_tracks' order, without their colours; throws as build_tracks for agl without terrain.
std::vector<Track> build_file_tracks(const LoadedTrackFile& loaded, const TrackStyle& style,
                                     const TrackBuildOptions& options);
// Then, on all the files' tracks in order: the colours (build_tracks' errors for --color), the
// values of density and thermals (which need every track: track_density.hpp, the tracks spread
// over `parallel`), and the note when no point has a value for the metric (or, for thermals,
// no flight climbed).
void finish_tracks(std::vector<Track>& tracks, const TrackStyle& style, Diagnostics& diagnostics,
                   std::size_t first_palette_index = 0, const track::ParallelFor& parallel = {});

// Fills the flat per-point numbers of a track from its cleaned points and their metrics (worked
// out with track.metrics_options when not given); `ground` per segment and point (empty: none).
// Throws std::invalid_argument when the metrics or the ground heights do not match the track's
// segments and points.
void fill_point_arrays(Track& track, const track::TrackMetrics& metrics,
                       const std::vector<std::vector<double>>& ground = {});
void fill_point_arrays(Track& track, const std::vector<std::vector<double>>& ground = {});

// The terrain height below every point of `t`, per segment; NaN everywhere without `heights`.
std::vector<std::vector<double>> sample_ground_heights(const track::Track& t, terrain::HeightSource* heights);

// Samples the terrain below every point into track.ground_m (may read tiles: call off a frame loop).
void set_ground_heights(Track& track, terrain::HeightSource& heights);

// Replaces the colour values in the track's geometry by `metric`'s (none for solid) and bumps its
// revision; a route keeps its values (metres along it) and revision. Throws std::invalid_argument
// for agl on a track without ground heights, and for phase on a track without its flight analysis.
// density and thermals: no values (NaN); apply_neighbour_counts over all the tracks then gives them.
void apply_color_metric(Track& track, track::ColorMetric metric);

// Curtains (walls down to the ground) on or off: each line's heights above the ground from
// altitude - ground height, where the ground is unknown down to `neutral_ground_m` as
// build_tracks does (NaN: no wall there, nor where the altitude is unknown), or none; bumps revision.
void apply_curtain(Track& track, bool on, double neutral_ground_m = std::numeric_limits<double>::quiet_NaN());

// The statistics of flat points [first, last] (inclusive; clamped): the track cut to those
// points (its segments kept), metrics recomputed on the cut: what `trailray stats` says of a file
// holding just that part. nullopt when first > last.
std::optional<track::Statistics> range_statistics(const Track& track, std::size_t first, std::size_t last,
                                                  const track::AnalysisOptions& analysis = {});
// The cut itself.
track::Track cut_track(const Track& track, std::size_t first, std::size_t last);

}  // namespace trailray::scene
