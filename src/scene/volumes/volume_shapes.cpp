#include "scene/volumes/volume_shapes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "geo/longitude.hpp"
#include "terrain/height_sampler.hpp"

namespace trailray::scene {
namespace {

double ground_at(const Volume& v, std::size_t i, double neutral) {
  if (v.ground_m.size() == v.boundary.size() && !std::isnan(v.ground_m[i])) return v.ground_m[i];
  return std::isnan(neutral) ? 0.0 : neutral;
}

double limit_height(const VolumeLimit& limit, double ground) {
  return limit.reference == VolumeHeightReference::Ground ? ground + limit.metres : limit.metres;
}

bool on_ground(const VolumeLimit& limit) {
  return limit.reference == VolumeHeightReference::Ground && limit.metres <= 0.0;
}

// Möller-Trumbore: the distance along the ray to the triangle, nullopt when it misses.
std::optional<double> hit_triangle(const Ray& ray, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a;
  const glm::dvec3 p = glm::cross(ray.direction, ac);
  const double det = glm::dot(ab, p);
  if (std::abs(det) < 1e-12) return std::nullopt;
  const glm::dvec3 s = ray.origin - a;
  const double u = glm::dot(s, p) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const glm::dvec3 q = glm::cross(s, ab);
  const double w = glm::dot(ray.direction, q) / det;
  if (w < 0.0 || u + w > 1.0) return std::nullopt;
  const double t = glm::dot(ac, q) / det;
  if (t <= 0.0) return std::nullopt;
  return t;
}

std::string limit_text(const std::string& written, const VolumeLimit& limit) {
  if (!written.empty()) return written;
  if (limit.unlimited) return "UNL";
  if (limit.reference == VolumeHeightReference::Ground)
    return limit.metres <= 0.0 ? std::string("GND") : fmt::format("{:.0f} m AGL", limit.metres);
  return fmt::format("{:.0f} m", limit.metres);
}

// "CTR MEIRINGEN"; a name that already starts with its class ("CTR Muenchen") is not prefixed again.
std::string class_and_name(const Volume& v) {
  if (v.category.empty()) return v.name;
  if (v.name.size() >= v.category.size()) {
    bool same = true;
    for (std::size_t i = 0; i < v.category.size() && same; ++i)
      same = std::toupper(static_cast<unsigned char>(v.name[i])) == static_cast<unsigned char>(v.category[i]);
    const bool word_ends = v.name.size() == v.category.size() || v.name[v.category.size()] == ' ';
    if (same && word_ends) return v.name;
  }
  return v.category + " " + v.name;
}

}  // namespace

void place_volumes_on_ground(VolumeSet& set, terrain::HeightSource* heights) {
  std::vector<geo::LatLon> points;
  std::vector<Volume*> todo;
  for (Volume& v : set.volumes)
    if (v.ground_m.size() != v.boundary.size()) {
      todo.push_back(&v);
      // Sampled at plain longitudes: a boundary across the antimeridian runs past +-180.
      for (const geo::LatLon& p : v.boundary) points.push_back({p.lat, geo::wrapped_longitude(p.lon)});
    }
  if (todo.empty()) return;
  std::vector<double> ground(points.size(), std::numeric_limits<double>::quiet_NaN());
  if (heights != nullptr && !points.empty()) ground = terrain::HeightSampler(*heights).sample(points);
  std::size_t at = 0;
  for (Volume* v : todo) {
    v->ground_m.assign(ground.begin() + static_cast<std::ptrdiff_t>(at),
                       ground.begin() + static_cast<std::ptrdiff_t>(at + v->boundary.size()));
    at += v->boundary.size();
  }
  ++set.revision;
}

std::vector<VolumeShape> volume_shapes(const VolumeSet& set, double neutral_ground_m) {
  std::vector<VolumeShape> out;
  for (std::size_t index = 0; index < set.volumes.size(); ++index) {
    const Volume& v = set.volumes[index];
    if (!v.visible || v.boundary.size() < 2) continue;
    VolumeShape shape;
    shape.volume = index;
    shape.closed = v.closed && v.boundary.size() > 2;
    shape.floor_outline = !on_ground(v.floor);
    shape.faded_top = v.ceiling.unlimited;
    shape.color_srgb = v.color_srgb;
    shape.opacity = v.opacity;
    shape.columns.reserve(v.boundary.size());
    for (std::size_t i = 0; i < v.boundary.size(); ++i) {
      const double ground = ground_at(v, i, neutral_ground_m);
      double bottom = on_ground(v.floor) ? ground - kBuriedFloorM : limit_height(v.floor, ground);
      const double top = limit_height(v.ceiling, ground);
      bottom = std::min(bottom, top - kMinWallM);
      const geo::LatLon& p = v.boundary[i];
      shape.columns.push_back({ecef_from({p.lat, p.lon, bottom}), ecef_from({p.lat, p.lon, top}), bottom, top});
    }
    out.push_back(std::move(shape));
  }
  return out;
}

std::optional<VolumeHit> pick_volume(const std::vector<VolumeShape>& shapes, const Ray& ray, double max_distance_m) {
  std::optional<VolumeHit> best;
  double nearest = max_distance_m;
  for (const VolumeShape& s : shapes) {
    const std::size_t n = s.columns.size();
    const std::size_t walls = s.closed ? n : n - 1;
    for (std::size_t i = 0; i < walls; ++i) {
      const VolumeColumn& a = s.columns[i];
      const VolumeColumn& b = s.columns[(i + 1) % n];
      for (const auto& hit : {hit_triangle(ray, a.bottom_ecef, b.bottom_ecef, b.top_ecef),
                              hit_triangle(ray, a.bottom_ecef, b.top_ecef, a.top_ecef)})
        if (hit && *hit < nearest) {
          nearest = *hit;
          best = VolumeHit{s.volume, *hit};
        }
    }
  }
  return best;
}

std::vector<VolumeLabel> airspace_labels(const VolumeSet& set) {
  std::vector<VolumeLabel> out;
  for (const Volume& v : set.volumes) {
    if (!v.visible || v.kind != VolumeKind::Airspace || v.name.empty() || v.boundary.empty()) continue;
    double lat = 0.0, lon = 0.0, ground = 0.0;
    int grounds = 0;
    for (std::size_t i = 0; i < v.boundary.size(); ++i) {
      lat += v.boundary[i].lat;
      lon += v.boundary[i].lon;
      if (i < v.ground_m.size() && !std::isnan(v.ground_m[i])) ground += v.ground_m[i], ++grounds;
    }
    const auto n = static_cast<double>(v.boundary.size());
    ground = grounds > 0 ? ground / grounds : 0.0;
    const double floor = std::max(limit_height(v.floor, ground), ground);
    const double top = v.ceiling.unlimited ? floor + 1000.0 : limit_height(v.ceiling, ground);
    out.push_back(
        {class_and_name(v), ecef_from({lat / n, lon / n, 0.5 * (floor + std::max(top, floor))}), v.color_srgb});
  }
  return out;
}

std::vector<std::string> volume_tooltip_lines(const Volume& volume) {
  std::vector<std::string> lines{volume.name.empty() ? std::string("(no name)") : volume.name};
  if (!volume.category.empty())
    lines.push_back((volume.kind == VolumeKind::Airspace ? "class: " : "role: ") + volume.category);
  lines.push_back("floor: " + limit_text(volume.floor_text, volume.floor));
  lines.push_back("ceiling: " + limit_text(volume.ceiling_text, volume.ceiling));
  return lines;
}

void set_volumes_visible(VolumeSet& set, VolumeKind kind, bool visible) {
  for (Volume& v : set.volumes)
    if (v.kind == kind) v.visible = visible;
  ++set.revision;
}

std::string volume_description(const Volume& volume) {
  return fmt::format("{} · {} – {}", class_and_name(volume), limit_text(volume.floor_text, volume.floor),
                     limit_text(volume.ceiling_text, volume.ceiling));
}

}  // namespace trailray::scene
