#include "scene/volumes/airspace_volumes.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <utility>

#include "geo/longitude.hpp"

namespace trailray::scene {
namespace {

namespace air = track::airspace;

constexpr double kEarthRadiusM = 6371008.8;
constexpr double kDegToRad = M_PI / 180.0;

struct ClassEntry {
  std::array<std::string_view, 3> names;  // the classes that look alike
  AirspaceClassStyle style;
};

// The table of airspace_volumes.hpp, in the order the legend lists the classes.
const std::array<ClassEntry, 10> kClasses{{
    {{"CTR", "", ""}, {{0.86f, 0.13f, 0.13f}, 0.16f}},
    {{"R", "P", "GP"}, {{0.93f, 0.30f, 0.10f}, 0.16f}},
    {{"Q", "", ""}, {{0.98f, 0.58f, 0.08f}, 0.15f}},
    {{"A", "B", ""}, {{0.52f, 0.22f, 0.78f}, 0.12f}},
    {{"C", "", ""}, {{0.16f, 0.28f, 0.86f}, 0.12f}},
    {{"D", "", ""}, {{0.20f, 0.55f, 0.98f}, 0.14f}},
    {{"E", "", ""}, {{0.22f, 0.68f, 0.36f}, 0.11f}},
    {{"F", "G", ""}, {{0.58f, 0.66f, 0.30f}, 0.11f}},
    {{"TMZ", "RMZ", ""}, {{0.58f, 0.60f, 0.64f}, 0.12f}},
    {{"W", "", ""}, {{0.30f, 0.78f, 0.86f}, 0.11f}},
}};
const AirspaceClassStyle kOtherClass{{0.62f, 0.52f, 0.74f}, 0.11f};

std::size_t class_index(std::string_view normalized) {
  for (std::size_t i = 0; i < kClasses.size(); ++i)
    for (std::string_view name : kClasses[i].names)
      if (!name.empty() && name == normalized) return i;
  return kClasses.size();
}

// A local plane around `origin` (metres east, north): enough for simplification and distances
// over the few hundred kilometres of a region.
struct LocalPlane {
  geo::LatLon origin;
  glm::dvec2 operator()(const geo::LatLon& p) const {
    return {(p.lon - origin.lon) * kDegToRad * kEarthRadiusM * std::cos(origin.lat * kDegToRad),
            (p.lat - origin.lat) * kDegToRad * kEarthRadiusM};
  }
};

double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  const double t = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

// Douglas-Peucker over points [first, last] (both kept), marking the kept ones.
void simplify_range(const std::vector<glm::dvec2>& xy, std::size_t first, std::size_t last, double tolerance,
                    std::vector<bool>& keep) {
  std::vector<std::pair<std::size_t, std::size_t>> stack{{first, last}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    double worst = -1.0;
    std::size_t at = a;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double d = distance_to_segment(xy[i], xy[a], xy[b]);
      if (d > worst) worst = d, at = i;
    }
    if (worst > tolerance) {
      keep[at] = true;
      stack.push_back({a, at});
      stack.push_back({at, b});
    }
  }
}

// The ring with the points within `tolerance` metres of the simplified ring dropped (a ring keeps
// at least 3 points, a line its 2).
std::vector<geo::LatLon> simplified_ring(const std::vector<geo::LatLon>& ring, double tolerance) {
  if (ring.size() <= 4) return ring;
  const LocalPlane plane{ring.front()};
  std::vector<glm::dvec2> xy;
  xy.reserve(ring.size());
  for (const geo::LatLon& p : ring) xy.push_back(plane(p));
  // The ring split at its first point and the point farthest from it: two open chains.
  std::size_t far = 1;
  for (std::size_t i = 1; i < xy.size(); ++i)
    if (glm::length(xy[i] - xy[0]) > glm::length(xy[far] - xy[0])) far = i;
  xy.push_back(xy.front());
  std::vector<bool> keep(xy.size(), false);
  keep[0] = keep[far] = keep.back() = true;
  simplify_range(xy, 0, far, tolerance, keep);
  simplify_range(xy, far, xy.size() - 1, tolerance, keep);
  std::vector<geo::LatLon> out;
  for (std::size_t i = 0; i < ring.size(); ++i)
    if (keep[i]) out.push_back(ring[i]);
  if (out.size() < 3) return ring;
  return out;
}

// The ring with points added so that no step is longer than `step_m` (limits above the ground
// then follow the terrain between the file's points).
std::vector<geo::LatLon> densified_ring(const std::vector<geo::LatLon>& ring, bool closed, double step_m) {
  if (ring.size() < 2 || step_m <= 0.0) return ring;
  const LocalPlane plane{ring.front()};
  std::vector<geo::LatLon> out;
  const std::size_t edges = closed ? ring.size() : ring.size() - 1;
  for (std::size_t i = 0; i < edges; ++i) {
    const geo::LatLon& a = ring[i];
    const geo::LatLon& b = ring[(i + 1) % ring.size()];
    const int steps = std::clamp(static_cast<int>(std::ceil(glm::length(plane(b) - plane(a)) / step_m)), 1, 500);
    for (int k = 0; k < steps; ++k) {
      const double t = static_cast<double>(k) / steps;
      out.push_back({a.lat + (b.lat - a.lat) * t, a.lon + (b.lon - a.lon) * t});
    }
  }
  if (!closed) out.push_back(ring.back());
  return out;
}

geo::LatLonBounds bounds_of(const std::vector<geo::LatLon>& ring) {
  geo::LatLonBounds b;
  for (const geo::LatLon& p : ring) b.add(p.lat, p.lon);
  return b;
}

geo::LatLonBounds grown(const geo::LatLonBounds& b, double margin_m) {
  const double dlat = margin_m / (kEarthRadiusM * kDegToRad);
  const double mid = std::clamp((b.min_lat + b.max_lat) / 2.0, -85.0, 85.0);
  const double dlon = dlat / std::cos(mid * kDegToRad);
  return {b.min_lat - dlat, b.min_lon - dlon, b.max_lat + dlat, b.max_lon + dlon};
}

// A box a whole turn away (`turns` of 360 degrees east): an airspace across the antimeridian
// has its box past +-180 (its ring's longitudes are continuous).
geo::LatLonBounds turned(geo::LatLonBounds b, int turns) {
  b.min_lon += 360.0 * turns;
  b.max_lon += 360.0 * turns;
  return b;
}

bool overlaps(const geo::LatLonBounds& a, const geo::LatLonBounds& b) {
  for (const int turns : {0, -1, 1}) {
    const geo::LatLonBounds c = turned(b, turns);
    if (a.min_lat <= c.max_lat && c.min_lat <= a.max_lat && a.min_lon <= c.max_lon && c.min_lon <= a.max_lon)
      return true;
  }
  return false;
}

// Metres from the region's centre to the nearest point of a box (0 inside).
double distance_to_box(const geo::LatLon& centre, const geo::LatLonBounds& box) {
  const double lon = geo::longitude_near(centre.lon, box.min_lon, box.max_lon);
  const geo::LatLon nearest{std::clamp(centre.lat, box.min_lat, box.max_lat), std::clamp(lon, box.min_lon, box.max_lon)};
  return glm::length(LocalPlane{{centre.lat, lon}}(nearest));
}

// The drawn limit; `floor_m` (the floor's drawn height) bounds capped ceilings from below.
VolumeLimit volume_limit(const air::AltitudeLimit& limit, bool is_ceiling, double floor_m, double cap_m) {
  VolumeLimit out;
  out.reference =
      limit.reference == air::AltitudeReference::Agl ? VolumeHeightReference::Ground : VolumeHeightReference::Msl;
  const std::optional<double> metres = drawn_limit_metres(limit);
  out.metres = metres.value_or(0.0);
  if (is_ceiling && (!metres || out.metres > cap_m)) {
    out.reference = VolumeHeightReference::Msl;
    out.metres = std::max(cap_m, floor_m + 1000.0);
    out.unlimited = true;
  }
  return out;
}

}  // namespace

std::string_view airspace_class_meaning(std::string_view normalized) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 8> kMeanings{{
      {"CTR", "control zone"},
      {"R", "restricted"},
      {"P", "prohibited"},
      {"GP", "glider prohibited"},
      {"Q", "danger"},
      {"TMZ", "transponder mandatory"},
      {"RMZ", "radio mandatory"},
      {"W", "wave window"},
  }};
  for (const auto& [name, meaning] : kMeanings)
    if (name == normalized) return meaning;
  if (normalized.size() == 1 && normalized[0] >= 'A' && normalized[0] <= 'G') return "class";
  return {};
}

std::string normalized_airspace_class(std::string_view airspace_class) {
  std::string out;
  for (char c : airspace_class)
    if (!std::isspace(static_cast<unsigned char>(c)))
      out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

AirspaceClassStyle airspace_class_style(std::string_view airspace_class) {
  const std::size_t i = class_index(normalized_airspace_class(airspace_class));
  return i < kClasses.size() ? kClasses[i].style : kOtherClass;
}

std::optional<double> drawn_limit_metres(const air::AltitudeLimit& limit) {
  // AltitudeLimit holds a flight level as its pressure altitude in metres (FL n = n * 100 ft):
  // in the standard atmosphere that is the height above MSL, which is what is drawn.
  if (limit.reference == air::AltitudeReference::Unlimited) return std::nullopt;
  return limit.metres;
}

AirspaceVolumes airspace_volumes(const air::AirspaceFile& file, const std::string& source,
                                 const AirspaceDrawOptions& options) {
  AirspaceVolumes out;
  std::optional<geo::LatLonBounds> region;
  geo::LatLon centre{0.0, 0.0};
  if (options.region && !options.region->empty()) {
    region = grown(*options.region, options.margin_m);
    centre = {(options.region->min_lat + options.region->max_lat) / 2.0,
              (options.region->min_lon + options.region->max_lon) / 2.0};
  }
  struct Candidate {
    const air::Airspace* airspace;
    double distance_m;
  };
  std::vector<Candidate> kept;
  for (const air::Airspace& a : file.airspaces) {
    if (a.boundary.size() < 2) continue;
    const geo::LatLonBounds box = bounds_of(a.boundary);
    if (region && !overlaps(*region, box)) {
      ++out.outside_region;
      continue;
    }
    const std::optional<double> floor = drawn_limit_metres(a.floor);
    if (!floor || *floor > options.max_floor_m) {
      ++out.above_floor;
      continue;
    }
    kept.push_back({&a, region ? distance_to_box(centre, box) : 0.0});
  }
  std::stable_sort(kept.begin(), kept.end(),
                   [](const Candidate& x, const Candidate& y) { return x.distance_m < y.distance_m; });
  if (kept.size() > options.max_volumes) {
    out.over_cap = kept.size() - options.max_volumes;
    kept.resize(options.max_volumes);
  }
  for (const Candidate& c : kept) {
    const air::Airspace& a = *c.airspace;
    Volume v;
    v.kind = VolumeKind::Airspace;
    v.name = a.name;
    v.category = normalized_airspace_class(a.airspace_class);
    v.source = source;
    v.line = a.line;
    v.floor_text = a.floor.text;
    v.ceiling_text = a.ceiling.text;
    v.closed = a.boundary.size() > 2;
    v.floor = volume_limit(a.floor, false, 0.0, options.ceiling_cap_m);
    v.ceiling = volume_limit(a.ceiling, true, v.floor.metres, options.ceiling_cap_m);
    const double tolerance = options.simplify_m + options.simplify_per_km * c.distance_m / 1000.0;
    v.boundary = v.closed ? simplified_ring(a.boundary, tolerance) : a.boundary;
    out.points_before += a.boundary.size();
    if (v.floor.reference == VolumeHeightReference::Ground || v.ceiling.reference == VolumeHeightReference::Ground)
      v.boundary = densified_ring(v.boundary, v.closed, options.ground_step_m);
    out.points_after += v.boundary.size();
    const AirspaceClassStyle style = airspace_class_style(v.category);
    v.color_srgb = style.color_srgb;
    v.opacity = style.opacity;
    out.volumes.push_back(std::move(v));
  }
  return out;
}

std::vector<AirspaceClassShown> airspace_classes_shown(const VolumeSet& set) {
  std::vector<std::pair<std::size_t, std::string>> seen;  // (row of the table, class)
  for (const Volume& v : set.volumes)
    if (v.visible && v.kind == VolumeKind::Airspace) seen.emplace_back(class_index(v.category), v.category);
  std::sort(seen.begin(), seen.end());
  seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
  std::vector<AirspaceClassShown> out;
  for (const auto& [row, name] : seen) {
    const std::string_view meaning = airspace_class_meaning(name);
    const std::string shown = name.empty() ? std::string("(no class)") : name;
    const std::string label = meaning.empty()      ? shown
                              : meaning == "class" ? "class " + shown
                                                   : shown + " " + std::string(meaning);
    out.push_back({label, airspace_class_style(name).color_srgb});
  }
  return out;
}

}  // namespace trailray::scene
