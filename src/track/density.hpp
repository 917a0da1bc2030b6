#pragma once
// How many distinct tracks passed near each point: the density view (`--color-by density`) and
// the thermal map (`--color-by thermals`: how many flights climbed near each point). It needs
// every track at once, so the scene computes it where the tracks are finished together
// (scene/tracks/track_density.hpp); this file is only the geometry.
//
// "Near" is horizontal: the distance between the points' places on the WGS84 ellipsoid, heights
// left out, measured as the straight line between those places in ECEF. Within the radii allowed
// (1 m to 100 km) that chord is shorter than the distance along the ground by less than
// r^3 / (24 R^2) (nothing at 100 m, 0.2 m at 100 km), and it has no seam: points near a pole or
// on both sides of the antimeridian are neighbours like any others.
//
// A source (a track, or the climbing parts of one flight) passes within r of a point when one of
// its lines comes within r: a line is a polyline (consecutive points joined), so a track sampled
// every 150 m still passes a point 90 m beside the line between two fixes. Lines are never
// joined to each other, and a step longer than max(10 km, 10 r) between two points is a gap, not
// a line (where the track went in between is unknown). Each source counts once however often it
// passes. A point's own track is a source like the others: in the density view every point
// counts at least 1, itself.
//
// How: a spatial hash. ECEF space is cut into cubes a little larger than the radius (cells);
// each source line is registered, as runs of consecutive segments, in every cell it passes
// through (a run's bounding box ruling its segments out at once). The points asked about are
// taken cell by cell, whatever line they are on, so the work on a place is done once for all the
// tracks that pass it (a take-off, a city's paths): the runs of the 27 cells around a cell
// (anything within r of its points is there) are grouped by source, then the cell's points are
// split in halves, again and again, and each part's box decides the sources within r of all of it
// (a segment reaching over the whole box: counted without measuring) and those within r of none
// of it (the distance from the box's centre, less its half diagonal, over r: left out). Only the
// sources left undecided at a few points are measured point by point. A decision for a whole box
// keeps a margin of 0.1 mm from the radius, so a point within rounding of the edge is measured
// segment by segment, as a brute force would. Positions are whole centimetres (int32 ECEF, 12
// bytes a point, exact differences); asking needs 12 to 28 bytes more a point while it runs.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "track/model.hpp"

namespace trailray::track {

inline constexpr double kMinNeighbourRadiusM = 1.0;
inline constexpr double kMaxNeighbourRadiusM = 100000.0;

// Consecutive points of one line (a segment of a track, or a piece of one).
using PointLine = std::span<const TrackPoint>;

// One thing that is counted: a track, or a flight's climbs. A point with no valid position
// (non-finite, |lat| > 90) is left out and ends its line there.
struct NeighbourSource {
  std::vector<PointLine> lines;
};

// Runs job(0) .. job(count - 1), each exactly once, in any order and on any threads: a job writes
// only its own results. Empty: one after the other on the calling thread.
using ParallelFor = std::function<void(std::size_t count, const std::function<void(std::size_t)>& job)>;

// The sources registered once, then asked about any number of points (const, so from several
// threads at once).
class NeighbourIndex {
 public:
  // Throws std::invalid_argument for a radius outside [kMinNeighbourRadiusM, kMaxNeighbourRadiusM]
  // (or not finite), and std::length_error beyond 2^32 points.
  NeighbourIndex(std::span<const NeighbourSource> sources, double radius_m, const ParallelFor& parallel = {});

  double radius_m() const { return radius_m_; }
  std::size_t source_count() const { return source_count_; }

  // How many sources pass within the radius of each point, into `out` (one per point, the same
  // size as `points`; std::invalid_argument otherwise): a whole number, NaN for a point without
  // a valid position.
  void count_near(PointLine points, std::span<float> out) const;
  // The same for one place (for tests and tools): 0 for an invalid position.
  std::size_t count_near(double lat_deg, double lon_deg) const;
  // The same for many lines at once, into out[i] for lines[i] (each as long as its line;
  // std::invalid_argument otherwise): the points are taken cell by cell, whatever line they are
  // on, the cells spread over `parallel`.
  void count_near_lines(std::span<const PointLine> lines, std::span<const std::span<float>> out,
                        const ParallelFor& parallel = {}) const;

 private:
  struct Cm {  // ECEF in whole centimetres
    std::int32_t x = 0, y = 0, z = 0;
  };
  struct Run {  // points [first, last] of one source line (indices into points_), by a cell
    std::uint64_t cell = 0;
    std::uint32_t source = 0, first = 0, last = 0;
    Cm lo, hi;  // bounding box of those points
  };
  struct Line {  // points [first, first + count) of points_
    std::uint32_t first = 0, count = 0;
  };
  struct CellCounter;  // density_cells.cpp: the points of one cell, counted together

  void add_source_runs(const std::vector<Line>& lines, std::uint32_t source, std::vector<Run>& out) const;
  void build_table();
  std::uint32_t find_cell(std::uint64_t key) const;  // kNoCell: no run there

  double radius_m_ = 0.0;
  double radius_cm_ = 0.0;
  std::int64_t cell_cm_ = 0;      // the cells' edge: over the radius, at least 8 m
  std::int64_t max_step_cm_ = 0;  // a longer step is a gap
  std::size_t source_count_ = 0;
  std::vector<Cm> points_;                 // every source's valid points, line after line
  std::vector<Run> runs_;                  // sorted by cell, then source
  std::vector<std::uint32_t> cell_begin_;  // per distinct cell (runs_ order) its first run; one more at the end
  std::vector<std::uint64_t> slot_keys_;   // open addressing over the distinct cells: key per slot
  std::vector<std::uint32_t> slot_cells_;  // ... and the cell's index (kNoCell: free)
};

// Every target's counts at once: per target, per line, one value per point (as count_near), the
// targets spread over `parallel`.
std::vector<std::vector<std::vector<float>>> neighbour_counts(std::span<const NeighbourSource> sources,
                                                              std::span<const std::vector<PointLine>> targets,
                                                              double radius_m, const ParallelFor& parallel = {});

}  // namespace trailray::track
