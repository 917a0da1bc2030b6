#pragma once
// Distances and destinations on the earth model a task names: the WGS84 ellipsoid (geodesics,
// Karney through GeographicLib) or the FAI sphere (radius 6371 km, great circles), which some
// competitions still score on.

#include "geo/web_mercator.hpp"
#include "track/task/task.hpp"

namespace trailray::track::task {

inline constexpr double kFaiSphereRadiusM = 6371000.0;

class Earth {
 public:
  explicit Earth(EarthModel model = EarthModel::Wgs84) : model_(model) {}

  EarthModel model() const { return model_; }
  double distance_m(const geo::LatLon& a, const geo::LatLon& b) const;
  // The point `distance_m` from `from` along the geodesic (great circle) leaving it at
  // `azimuth_deg` (clockwise from north).
  geo::LatLon destination(const geo::LatLon& from, double azimuth_deg, double distance_m) const;
  // The azimuth (degrees clockwise from north) of the geodesic from `from` to `to` where it
  // leaves `from`; 0 for coincident points.
  double azimuth_deg(const geo::LatLon& from, const geo::LatLon& to) const;

 private:
  EarthModel model_;
};

}  // namespace trailray::track::task
