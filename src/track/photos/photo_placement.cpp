#include "track/photos/photo_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "geo/geodesic.hpp"
#include "geo/wgs84.hpp"
#include "track/io/text_output.hpp"
#include "track/metrics.hpp"
#include "track/photos/exif_time.hpp"

namespace trailray::track {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kMetresPerDegree = 111320.0;  // along the equator; a meridian degree is a little less

// A place on a track: the step from point `i` to `i + 1` of segment `seg` at `frac` (0: the
// point itself), and the distance along the track there.
struct Spot {
  std::size_t track = 0, seg = 0, i = 0;
  double frac = 0;
  double distance_m = 0;
};

struct TimedPoint {
  double t;
  std::size_t seg, i;
};

// What placement needs of one track, worked out once.
struct TrackTimeline {
  const Track* track = nullptr;
  TrackMetrics metrics;
  std::vector<TimedPoint> timed;  // file order
  bool sorted = true;             // times never go backwards (always so after cleaning)
  double first = kNaN, last = kNaN;

  explicit TrackTimeline(const Track* t) : track(t) {
    if (t == nullptr) return;
    metrics = compute_metrics(*t);
    for (std::size_t s = 0; s < t->segments.size(); ++s) {
      const auto& pts = t->segments[s].points;
      for (std::size_t i = 0; i < pts.size(); ++i) {
        if (!std::isfinite(pts[i].time)) continue;
        if (!timed.empty() && pts[i].time < timed.back().t) sorted = false;
        timed.push_back({pts[i].time, s, i});
        first = std::isnan(first) ? pts[i].time : std::min(first, pts[i].time);
        last = std::isnan(last) ? pts[i].time : std::max(last, pts[i].time);
      }
    }
  }
  double distance(std::size_t seg, std::size_t i) const { return metrics.segments[seg].distance_m[i]; }
  bool holds(double t) const { return timed.size() >= 1 && t >= first && t <= last; }
};

double lerp(double a, double b, double f) { return f == 0.0 ? a : a + (b - a) * f; }

// A value interpolated on a step where both ends have one; the one end's where only it has one.
double lerp_present(double a, double b, double f) {
  if (std::isfinite(a) && std::isfinite(b)) return lerp(a, b, f);
  if (std::isfinite(a) && f <= 0.5) return a;
  if (std::isfinite(b) && f >= 0.5) return b;
  return kNaN;
}

// The photo placed at `spot`.
PlacedPhoto placed_at(const PhotoMetadata& photo, const TrackTimeline& line, const Spot& spot, PhotoPlacedBy by) {
  PlacedPhoto p;
  p.photo = photo;
  p.placed_by = by;
  p.track = spot.track;
  p.distance_m = spot.distance_m;
  const auto& pts = line.track->segments[spot.seg].points;
  const TrackPoint& a = pts[spot.i];
  const TrackPoint& b = spot.frac > 0.0 && spot.i + 1 < pts.size() ? pts[spot.i + 1] : a;
  const double f = spot.frac;
  p.lat_deg = lerp(a.lat, b.lat, f);
  p.lon_deg = a.lon + geo::wgs84::wrap_dlon_deg(b.lon - a.lon) * f;
  if (p.lon_deg > 180.0) p.lon_deg -= 360.0;
  if (p.lon_deg < -180.0) p.lon_deg += 360.0;
  p.ele_m = lerp_present(a.ele, b.ele, f);
  p.time_unix_s = lerp_present(a.time, b.time, f);
  if (photo.has_position()) p.gps_offset_m = geo::geodesic_distance_m(photo.lat_deg, photo.lon_deg, p.lat_deg, p.lon_deg);
  return p;
}

// The nearest point of the tracks' polylines to (lat, lon): steps are projected onto a plane
// tangent at the photo (equirectangular: within a fraction of a percent over the 100 m that
// matter), the winner's distance measured on the ellipsoid. Chunks of steps whose bounding box
// is farther than the best so far are skipped.
struct Nearest {
  Spot spot;
  double distance_m = std::numeric_limits<double>::infinity();
};

Nearest nearest_on_tracks(double lat, double lon, const std::vector<TrackTimeline>& lines) {
  const double kx = kMetresPerDegree * std::cos(lat * geo::wgs84::kRadPerDeg);
  const double ky = kMetresPerDegree;
  auto x_of = [&](const TrackPoint& p) { return geo::wgs84::wrap_dlon_deg(p.lon - lon) * kx; };
  auto y_of = [&](const TrackPoint& p) { return (p.lat - lat) * ky; };
  Nearest best;
  double best_plane = std::numeric_limits<double>::infinity();
  constexpr std::size_t kChunk = 64;
  for (std::size_t ti = 0; ti < lines.size(); ++ti) {
    const TrackTimeline& line = lines[ti];
    if (line.track == nullptr) continue;
    for (std::size_t s = 0; s < line.track->segments.size(); ++s) {
      const auto& pts = line.track->segments[s].points;
      for (std::size_t c = 0; c < pts.size(); c += kChunk) {
        const std::size_t chunk_end = std::min(pts.size(), c + kChunk);
        const std::size_t box_end = std::min(pts.size(), chunk_end + 1);  // the chunk's last step ends in the next
        // Lower bound of the chunk's distance: its latitude band alone (a meridian degree is at
        // least 110.5 km), so the skip never loses the nearest step.
        double min_lat = 90, max_lat = -90;
        for (std::size_t i = c; i < box_end; ++i) {
          min_lat = std::min(min_lat, pts[i].lat);
          max_lat = std::max(max_lat, pts[i].lat);
        }
        const double band_m = std::max({0.0, min_lat - lat, lat - max_lat}) * 110500.0;
        if (band_m > best_plane * 1.01 + 1.0) continue;
        for (std::size_t i = c; i < chunk_end; ++i) {
          const double ax = x_of(pts[i]), ay = y_of(pts[i]);
          Spot spot{ti, s, i, 0.0, 0.0};
          double px = ax, py = ay;
          if (i + 1 < pts.size()) {
            const double bx = x_of(pts[i + 1]), by = y_of(pts[i + 1]);
            const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
            const double frac = len2 > 0 ? std::clamp(-(ax * dx + ay * dy) / len2, 0.0, 1.0) : 0.0;
            if (frac >= 1.0) {
              spot.i = i + 1;  // the next fix itself
              px = bx, py = by;
            } else if (frac > 0.0) {
              spot.frac = frac;
              px = ax + dx * frac, py = ay + dy * frac;
            }
          }
          const double d = std::hypot(px, py);
          if (d < best_plane) {
            best_plane = d;
            best.spot = spot;
          }
        }
      }
    }
  }
  if (!std::isfinite(best_plane)) return best;
  const TrackTimeline& line = lines[best.spot.track];
  const Spot& sp = best.spot;
  const double d0 = line.distance(sp.seg, sp.i);
  best.spot.distance_m = sp.frac > 0 ? d0 + (line.distance(sp.seg, sp.i + 1) - d0) * sp.frac : d0;
  const auto& pts = line.track->segments[sp.seg].points;
  const TrackPoint& a = pts[sp.i];
  const TrackPoint& b = sp.frac > 0 ? pts[sp.i + 1] : a;
  best.distance_m = geo::geodesic_distance_m(lat, lon, lerp(a.lat, b.lat, sp.frac),
                                             a.lon + geo::wgs84::wrap_dlon_deg(b.lon - a.lon) * sp.frac);
  return best;
}

// Where `line` (track `ti`) was at time `t`, which its span holds.
Spot spot_at_time(const TrackTimeline& line, std::size_t ti, double t) {
  const auto& timed = line.timed;
  std::size_t b = timed.size();
  if (line.sorted) {
    b = static_cast<std::size_t>(
        std::lower_bound(timed.begin(), timed.end(), t, [](const TimedPoint& p, double v) { return p.t < v; }) -
        timed.begin());
  } else {
    for (std::size_t k = 0; k < timed.size(); ++k)
      if (timed[k].t == t || (k > 0 && timed[k - 1].t < t && t < timed[k].t)) {
        b = k;
        break;
      }
  }
  if (b >= timed.size()) b = timed.size() - 1;  // only when unsorted times never bracket it
  const TimedPoint& pb = timed[b];
  auto at_fix = [&](const TimedPoint& p) { return Spot{ti, p.seg, p.i, 0.0, line.distance(p.seg, p.i)}; };
  if (pb.t == t || b == 0) return at_fix(pb);
  const TimedPoint& pa = timed[b - 1];
  if (pa.seg != pb.seg) return (t - pa.t <= pb.t - t) ? at_fix(pa) : at_fix(pb);  // in a gap: the nearer end
  const double f = (t - pa.t) / (pb.t - pa.t);
  const double da = line.distance(pa.seg, pa.i), db = line.distance(pb.seg, pb.i);
  const double target = da + (db - da) * f;
  // The step between the two fixes (untimed points may lie between them) that holds `target`.
  for (std::size_t i = pa.i; i < pb.i; ++i) {
    const double d0 = line.distance(pa.seg, i), d1 = line.distance(pa.seg, i + 1);
    if (target <= d1 || i + 1 == pb.i) {
      const double frac = d1 > d0 ? std::clamp((target - d0) / (d1 - d0), 0.0, 1.0) : 0.0;
      return Spot{ti, pa.seg, i, frac, target};
    }
  }
  return at_fix(pa);
}

std::string distance_text(double m) {
  return m < 1000.0 ? fmt::format("{:.0f} m", m) : fmt::format("{:.1f} km", m / 1000.0);
}

}  // namespace

double photo_utc_time(const PhotoMetadata& photo, const PhotoPlacementOptions& options) {
  if (!std::isfinite(photo.taken_local_s)) return kNaN;
  const std::optional<int> offset = photo.offset_s ? photo.offset_s : options.default_offset_s;
  if (!offset) return kNaN;
  return photo.taken_local_s - *offset + options.clock_offset_s;
}

std::optional<int> offset_suggested_by_gps_time(const PhotoMetadata& photo) {
  if (!std::isfinite(photo.taken_local_s) || !std::isfinite(photo.gps_time_utc_s)) return std::nullopt;
  // The time of day's difference, in (-12 h, +12 h] (+14 h for the Pacific's zones).
  double diff = std::fmod(photo.taken_local_s - photo.gps_time_utc_s, 86400.0);
  if (diff < 0) diff += 86400.0;
  if (diff > 14 * 3600.0) diff -= 86400.0;
  const double zone = std::round(diff / 900.0) * 900.0;
  if (std::abs(diff - zone) > 120.0 || std::abs(zone) > 14 * 3600.0) return std::nullopt;
  return static_cast<int>(zone);
}

PhotoPlacement place_photos(const std::vector<PhotoMetadata>& photos, const std::vector<const Track*>& tracks,
                            const PhotoPlacementOptions& options) {
  PhotoPlacement out;
  std::vector<TrackTimeline> lines;
  lines.reserve(tracks.size());
  for (const Track* t : tracks) lines.emplace_back(t);
  double first = kNaN, last = kNaN;
  for (const auto& line : lines) {
    if (line.timed.empty()) continue;
    first = std::isnan(first) ? line.first : std::min(first, line.first);
    last = std::isnan(last) ? line.last : std::max(last, line.last);
  }
  const bool any_track = std::any_of(lines.begin(), lines.end(), [](const TrackTimeline& l) {
    return l.track != nullptr && l.track->point_count() > 0;
  });

  for (std::size_t k = 0; k < photos.size(); ++k) {
    const PhotoMetadata& photo = photos[k];
    auto not_placed = [&](const std::string& why) {
      out.unplaced.push_back({k, Diagnostic{photo.path, {}, "not placed: " + why}});
    };
    if (!photo.has_exif) {
      not_placed("it has no EXIF block (no GPS position, no time)");
      continue;
    }
    if (!any_track) {
      not_placed("no track to place it on");
      continue;
    }
    Nearest near;
    if (photo.has_position()) {
      near = nearest_on_tracks(photo.lat_deg, photo.lon_deg, lines);
      if (near.distance_m <= options.max_snap_m) {
        PlacedPhoto p = placed_at(photo, lines[near.spot.track], near.spot, PhotoPlacedBy::gps);
        const double own = photo_utc_time(photo, options);
        if (std::isfinite(own)) p.time_unix_s = own;
        out.placed.push_back(std::move(p));
        out.placed_photo.push_back(k);
        continue;
      }
    }
    const double t = photo_utc_time(photo, options);
    if (std::isfinite(t)) {
      std::optional<Spot> chosen;
      double chosen_m = std::numeric_limits<double>::infinity();
      for (std::size_t ti = 0; ti < lines.size(); ++ti) {
        if (lines[ti].track == nullptr || !lines[ti].holds(t)) continue;
        const Spot spot = spot_at_time(lines[ti], ti, t);
        if (!photo.has_position()) {
          chosen = spot;
          break;
        }
        const PlacedPhoto p = placed_at(photo, lines[ti], spot, PhotoPlacedBy::time);
        if (!chosen || p.gps_offset_m < chosen_m) {
          chosen = spot;
          chosen_m = p.gps_offset_m;
        }
      }
      if (chosen) {
        PlacedPhoto p = placed_at(photo, lines[chosen->track], *chosen, PhotoPlacedBy::time);
        p.time_unix_s = t;
        if (photo.has_position())
          out.warnings.push_back(Diagnostic{
              photo.path, {},
              fmt::format("its GPS position is {} from the nearest track (more than {:.0f} m): placed by its time "
                          "instead, {} from its GPS position",
                          distance_text(near.distance_m), options.max_snap_m, distance_text(p.gps_offset_m))});
        out.placed.push_back(std::move(p));
        out.placed_photo.push_back(k);
        continue;
      }
    }
    // Not placed: say why, and what would help.
    std::string where;
    if (photo.has_position())
      where = fmt::format("its GPS position is {} from the nearest track (more than {:.0f} m)",
                          distance_text(near.distance_m), options.max_snap_m);
    else
      where = "it has no GPS position";
    if (!std::isfinite(photo.taken_local_s)) {
      not_placed(where + " and no time (no DateTimeOriginal)");
    } else if (!std::isfinite(t)) {
      std::string hint = options.time_zone_hint;
      if (const auto zone = offset_suggested_by_gps_time(photo))
        hint += fmt::format(" (its GPS time stamp suggests {})", format_utc_offset(*zone));
      not_placed(where + " and its time has no time zone (no OffsetTimeOriginal): " + hint);
    } else if (std::isnan(first)) {
      not_placed(where + " and the tracks have no times to place it by");
    } else {
      not_placed(fmt::format("{}, and it was taken at {}, outside the tracks' times ({} to {})", where,
                             format_iso_time(t), format_iso_time(first), format_iso_time(last)));
    }
  }
  return out;
}

}  // namespace trailray::track
