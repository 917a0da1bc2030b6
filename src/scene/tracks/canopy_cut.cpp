#include "scene/tracks/canopy_cut.hpp"

#include <algorithm>
#include <cmath>

#include "geo/geodesic.hpp"
#include "geo/tile_id.hpp"
#include "terrain/tile_sampling.hpp"
#include "track/cover.hpp"

namespace trailray::scene {
namespace {

std::int64_t key(std::int64_t x, std::int64_t y) { return (x << 32) ^ (y & 0xffffffff); }

// Where sample (i, j) of a tile sits, as a fraction of the tile from its north-west corner.
double fraction(std::uint32_t i, std::uint32_t n, terrain::SampleLayout layout) {
  return layout == terrain::SampleLayout::pixel_is_point ? double(i) / double(std::max(n - 1, 1u)) : (i + 0.5) / n;
}

}  // namespace

CanopyCutHeights::CanopyCutHeights(terrain::HeightSource& surface, terrain::HeightSource& ground, double radius_m)
    : surface_(surface), ground_(ground), radius_m_(radius_m), info_(surface.info()) {
  info_.name = surface.info().name + " (the canopy cut along the tracks under cover)";
}

void CanopyCutHeights::set_cut_lines(const std::vector<std::vector<geo::LatLon>>& lines) {
  points_.clear();
  scale_.clear();
  cells_.clear();
  // Points along each line no further apart than half the radius: the corridor has no gaps.
  const double step = std::max(radius_m_ / 2.0, 0.5);
  for (const auto& line : lines)
    for (std::size_t i = 0; i < line.size(); ++i) {
      const geo::LatLon& a = line[i];
      const geo::LatLon& b = i + 1 < line.size() ? line[i + 1] : a;
      const double length = geo::geodesic_distance_m(a.lat, a.lon, b.lat, b.lon);
      const int pieces = std::max(1, static_cast<int>(std::ceil(length / step)));
      for (int k = 0; k < (i + 1 < line.size() ? pieces : 1); ++k) {
        const double f = double(k) / pieces;
        const double lat = a.lat + (b.lat - a.lat) * f, lon = a.lon + (b.lon - a.lon) * f;
        points_.push_back(geo::mercator_from_latlon(lat, lon));
        scale_.push_back(geo::mercator_scale_factor(lat));
      }
    }
  if (points_.empty()) return;
  cell_ = 4.0 * radius_m_ * *std::max_element(scale_.begin(), scale_.end());
  for (std::uint32_t i = 0; i < points_.size(); ++i)
    cells_[key(static_cast<std::int64_t>(std::floor(points_[i].x / cell_)),
               static_cast<std::int64_t>(std::floor(points_[i].y / cell_)))]
        .push_back(i);
}

bool CanopyCutHeights::any_near(double min_x, double min_y, double max_x, double max_y, double reach) const {
  const auto x0 = static_cast<std::int64_t>(std::floor((min_x - reach) / cell_));
  const auto x1 = static_cast<std::int64_t>(std::floor((max_x + reach) / cell_));
  const auto y0 = static_cast<std::int64_t>(std::floor((min_y - reach) / cell_));
  const auto y1 = static_cast<std::int64_t>(std::floor((max_y + reach) / cell_));
  if ((x1 - x0 + 1) * (y1 - y0 + 1) > std::int64_t(cells_.size())) {
    for (const geo::MercatorPoint& p : points_)
      if (p.x >= min_x - reach && p.x <= max_x + reach && p.y >= min_y - reach && p.y <= max_y + reach) return true;
    return false;
  }
  for (std::int64_t x = x0; x <= x1; ++x)
    for (std::int64_t y = y0; y <= y1; ++y)
      if (cells_.count(key(x, y)) != 0) return true;
  return false;
}

bool CanopyCutHeights::near(const geo::MercatorPoint& p, double reach) const {
  const auto cx = static_cast<std::int64_t>(std::floor(p.x / cell_)), cy = static_cast<std::int64_t>(std::floor(p.y / cell_));
  const std::int64_t span = static_cast<std::int64_t>(std::ceil(reach / cell_));
  for (std::int64_t x = cx - span; x <= cx + span; ++x)
    for (std::int64_t y = cy - span; y <= cy + span; ++y) {
      const auto it = cells_.find(key(x, y));
      if (it == cells_.end()) continue;
      for (const std::uint32_t i : it->second) {
        const double dx = points_[i].x - p.x, dy = points_[i].y - p.y;
        if (dx * dx + dy * dy <= reach * reach) return true;
      }
    }
  return false;
}

terrain::TileResult<terrain::HeightTile> CanopyCutHeights::load(const terrain::TileId& id, terrain::StopToken stop) {
  terrain::TileResult<terrain::HeightTile> result = surface_.load(id, stop);
  if (result.status != terrain::TileStatus::ok || points_.empty()) return result;
  terrain::HeightTile& tile = result.tile;
  const std::optional<geo::MercatorBounds> box = geo::tile_bounds_mercator(id);
  if (!box || tile.width < 2 || tile.height < 2) return result;
  const double dx = (box->max_x - box->min_x) / tile.width, dy = (box->max_y - box->min_y) / tile.height;
  // The corridor in Mercator metres (the scale of the tile's middle), never narrower than the
  // samples are apart: a coarse level cuts its nearest samples rather than none.
  const double middle_lat = geo::latlon_from_mercator(0.0, 0.5 * (box->min_y + box->max_y)).lat;
  const double reach = std::max(radius_m_ * geo::mercator_scale_factor(middle_lat), 0.75 * std::max(dx, dy));
  if (!any_near(box->min_x, box->min_y, box->max_x, box->max_y, reach)) return result;
  const terrain::TileResult<terrain::HeightTile> ground = ground_.load(id, stop);
  if (ground.status != terrain::TileStatus::ok || ground.tile.width < 2 || ground.tile.height < 2) return result;
  const terrain::HeightTile& g = ground.tile;
  bool changed = false;
  for (std::uint32_t row = 0; row < tile.height; ++row) {
    const double fy = fraction(row, tile.height, tile.layout);
    for (std::uint32_t col = 0; col < tile.width; ++col) {
      const double fx = fraction(col, tile.width, tile.layout);
      const geo::MercatorPoint at{box->min_x + fx * (box->max_x - box->min_x), box->max_y - fy * (box->max_y - box->min_y)};
      if (!near(at, reach)) continue;
      // The same place in the ground's samples.
      const double gc = g.layout == terrain::SampleLayout::pixel_is_point ? fx * (g.width - 1) : fx * g.width - 0.5;
      const double gr = g.layout == terrain::SampleLayout::pixel_is_point ? fy * (g.height - 1) : fy * g.height - 0.5;
      const double h = terrain::bilinear_in_tile(g, gc, gr);
      if (std::isnan(h)) continue;
      tile.heights[std::size_t{row} * tile.width + col] = static_cast<float>(std::min<double>(h, tile.at(col, row)));
      changed = true;
    }
  }
  if (changed) terrain::update_height_range(tile);
  return result;
}

std::vector<std::vector<geo::LatLon>> covered_lines(const TrackSet& tracks) {
  std::vector<std::vector<geo::LatLon>> lines;
  for (const Track& t : tracks.tracks()) {
    if (!t.visible || t.cover.empty()) continue;
    std::size_t flat = 0;
    for (const track::Segment& s : t.cleaned.segments) {
      bool open_run = false;
      for (const track::TrackPoint& p : s.points) {
        const bool covered = flat < t.cover.size() && t.cover[flat] == static_cast<std::uint8_t>(track::Cover::covered);
        ++flat;
        if (!covered) {
          open_run = false;
          continue;
        }
        if (!open_run) lines.emplace_back();
        open_run = true;
        lines.back().push_back({p.lat, p.lon});
      }
    }
  }
  return lines;
}

}  // namespace trailray::scene
