#pragma once
// Distances on the WGS84 ellipsoid (Karney's algorithm through GeographicLib):
// exact to nanometres, no spherical approximation.

namespace trailray::geo {

// Geodesic distance in metres between two points given in degrees.
double geodesic_distance_m(double lat1, double lon1, double lat2, double lon2);

}  // namespace trailray::geo
