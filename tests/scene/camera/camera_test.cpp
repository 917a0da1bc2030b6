#include "scene/camera/camera.hpp"

#include <gtest/gtest.h>
#include <GeographicLib/Geodesic.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geo/wgs84.hpp"

namespace trailray::scene {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

// Interlaken, 2000 m above the ellipsoid.
const GeoPosition kInterlaken{46.69, 7.86, 2000.0};

Camera camera_at_position(const GeoPosition& p, double heading, double pitch, const Lens& lens = {}) {
  return Camera(ecef_from(p), heading, pitch, lens, depth_range_for(p.height_m, p.height_m));
}

glm::dvec3 offset(const glm::dvec3& p, const glm::dvec3& d) { return p + d; }

void expect_near_vec(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Camera, HeadingAndPitchFollowTheLocalEastNorthUpFrame) {
  const EnuAxes enu = enu_axes_at(kInterlaken.lat_deg, kInterlaken.lon_deg);
  const Camera north = camera_at_position(kInterlaken, 0.0, 0.0);
  expect_near_vec(north.axes().forward, enu.north, 1e-12);
  expect_near_vec(north.axes().right, enu.east, 1e-12);
  expect_near_vec(north.axes().up, enu.up, 1e-12);

  const Camera east = camera_at_position(kInterlaken, 90.0, 0.0);
  expect_near_vec(east.axes().forward, enu.east, 1e-12);
  expect_near_vec(east.axes().right, -enu.north, 1e-12);

  // Pitch -30: looking down, 30 degrees below the horizontal.
  const Camera down = camera_at_position(kInterlaken, 0.0, -30.0);
  EXPECT_NEAR(glm::dot(down.axes().forward, enu.up), -0.5, 1e-12);
  EXPECT_NEAR(glm::dot(down.axes().right, enu.up), 0.0, 1e-12);  // roll 0
  // Straight down: the nadir at the image centre, the heading still orients the screen.
  const Camera nadir = camera_at_position(kInterlaken, 90.0, -90.0);
  expect_near_vec(nadir.axes().forward, -enu.up, 1e-12);
  expect_near_vec(nadir.axes().up, enu.east, 1e-12);
  // Headings are kept in [0, 360).
  EXPECT_DOUBLE_EQ(camera_at_position(kInterlaken, -90.0, 0.0).heading_deg(), 270.0);
  EXPECT_DOUBLE_EQ(camera_at_position(kInterlaken, 720.0, 0.0).heading_deg(), 0.0);
}

TEST(Camera, ProjectsPointsWhereTheyAre) {
  const Lens lens{45.0, 640, 480};
  const Camera camera = camera_at_position(kInterlaken, 0.0, 0.0, lens);
  const EnuAxes enu = enu_axes_at(kInterlaken.lat_deg, kInterlaken.lon_deg);
  // 1 km ahead, at the camera's height: the image centre.
  const auto ahead = camera.project(offset(camera.position(), 1000.0 * enu.north));
  ASSERT_TRUE(ahead);
  EXPECT_NEAR(ahead->x_px, 320.0, 1e-6);
  EXPECT_NEAR(ahead->y_px, 240.0, 1e-6);
  EXPECT_NEAR(ahead->depth_m, 1000.0, 1e-6);
  // 1 km ahead and tan(22.5 deg) km up: the top edge; the same to the east: right of centre.
  const auto top =
      camera.project(offset(camera.position(), 1000.0 * enu.north + 1000.0 * std::tan(22.5 * kRadPerDeg) * enu.up));
  ASSERT_TRUE(top);
  EXPECT_NEAR(top->y_px, 0.0, 1e-6);
  const auto right = camera.project(offset(camera.position(), 1000.0 * enu.north + 100.0 * enu.east));
  ASSERT_TRUE(right);
  EXPECT_GT(right->x_px, 320.0);
  EXPECT_NEAR(right->y_px, 240.0, 1e-6);
  // Behind the camera: no image.
  EXPECT_FALSE(camera.project(offset(camera.position(), -10.0 * enu.north)));
}

TEST(Camera, RayThroughPixelInvertsProject) {
  const Camera camera = camera_at_position(kInterlaken, 123.0, -35.0, Lens{60.0, 800, 600});
  for (double x : {0.0, 0.5, 200.25, 400.0, 799.5, 800.0}) {
    for (double y : {0.0, 10.5, 300.0, 599.0}) {
      const Ray ray = camera.ray_through_pixel(x, y);
      EXPECT_NEAR(glm::length(ray.direction), 1.0, 1e-12);
      const auto s = camera.project(offset(ray.origin, 5000.0 * ray.direction));
      ASSERT_TRUE(s);
      EXPECT_NEAR(s->x_px, x, 1e-6);
      EXPECT_NEAR(s->y_px, y, 1e-6);
    }
  }
}

TEST(Camera, AgreesWithTheLodCameraOfTheTerrainLayer) {
  const Camera camera = camera_at_position(GeoPosition{-33.9, 151.2, 800.0}, 250.0, -20.0, Lens{50.0, 1280, 720});
  const terrain::LodCamera lod = to_lod_camera(camera);
  EXPECT_FALSE(terrain::camera_problem(lod));
  EXPECT_DOUBLE_EQ(lod.vertical_fov_rad, 50.0 * kRadPerDeg);
  EXPECT_EQ(lod.viewport_width_px, 1280u);
  EXPECT_EQ(lod.viewport_height_px, 720u);
  EXPECT_DOUBLE_EQ(lod.near_m, camera.depth_range().near_m);
  EXPECT_DOUBLE_EQ(lod.far_m, camera.depth_range().far_m);
  const terrain::Frustum frustum = terrain::frustum_planes(lod);
  for (double x : {10.0, 640.0, 1270.0}) {
    for (double y : {10.0, 360.0, 710.0}) {
      const Ray ray = camera.ray_through_pixel(x, y);
      const glm::dvec3 p = offset(ray.origin, 3000.0 * ray.direction);
      const auto ours = camera.project(p);
      const auto theirs = terrain::project_to_pixels(lod, p);
      ASSERT_TRUE(ours && theirs);
      EXPECT_NEAR(ours->x_px, theirs->x_px, 1e-6);
      EXPECT_NEAR(ours->y_px, theirs->y_px, 1e-6);
      EXPECT_NEAR(ours->depth_m, theirs->depth_m, 1e-6);
      EXPECT_TRUE(frustum.contains(p));
    }
  }
}

// The float matrix applied to float offsets from an origin lands where the double projection
// does, to a small fraction of a pixel, with the camera a few metres from the points: the
// translation is taken in double (in plain float ECEF, ~6.4e6 m, the same points would be off by
// up to half a metre, tens of pixels at this distance).
TEST(Camera, ViewProjectionRelativeToAnOriginKeepsPrecisionNearTheCamera) {
  const Lens lens{45.0, 1920, 1080};
  const GeoPosition origin_position{46.60, 8.00, 1500.0};
  const glm::dvec3 origin = ecef_from(origin_position);
  const EnuAxes enu = enu_axes_at(origin_position.lat_deg, origin_position.lon_deg);
  // The camera 8 m south of a point 3 km from the origin, looking north at it.
  const glm::dvec3 point_offset = 3000.0 * enu.north + 200.0 * enu.east;
  const glm::dvec3 camera_position = offset(origin, point_offset - 8.0 * enu.north);
  const Camera camera(camera_position, 0.0, 0.0, lens, DepthRange{0.5, 1.0e5});
  const std::array<float, 16> m = camera.view_projection_relative_to(origin);
  for (const glm::dvec3& d : {glm::dvec3(0.0), glm::dvec3(0.3, 0.0, 0.2), glm::dvec3(-0.7, 2.0, -0.4)}) {
    const glm::dvec3 local = point_offset + d.x * enu.east + d.y * enu.north + d.z * enu.up;
    const glm::vec3 f(local);  // what a vertex buffer holds
    float clip[4];
    for (int row = 0; row < 4; ++row) {
      clip[row] = m[static_cast<std::size_t>(row)] * f.x + m[static_cast<std::size_t>(4 + row)] * f.y +
                  m[static_cast<std::size_t>(8 + row)] * f.z + m[static_cast<std::size_t>(12 + row)];
    }
    const double x = 0.5 * (clip[0] / clip[3] + 1.0) * lens.width_px;
    const double y = 0.5 * (1.0 - clip[1] / clip[3]) * lens.height_px;
    const auto exact = camera.project(offset(origin, local));
    ASSERT_TRUE(exact);
    EXPECT_NEAR(x, exact->x_px, 0.25);
    EXPECT_NEAR(y, exact->y_px, 0.25);
  }
  // The uniform form: origin - camera in double, rounded once.
  const glm::vec3 omc = camera.origin_minus_camera(origin);
  const glm::dvec3 expected = origin - camera_position;
  EXPECT_NEAR(omc.x, expected.x, 1e-3);
  EXPECT_NEAR(omc.y, expected.y, 1e-3);
  EXPECT_NEAR(omc.z, expected.z, 1e-3);
}

TEST(Camera, ProjectionMapsNearAndFarToTheDepthRange) {
  const Camera camera(ecef_from(kInterlaken), 0.0, 0.0, Lens{}, DepthRange{10.0, 5000.0});
  const glm::dmat4 p = camera.projection();
  const auto ndc_depth = [&](double distance) {
    const glm::dvec4 clip = p * glm::dvec4(0.0, 0.0, -distance, 1.0);
    return clip.z / clip.w;
  };
  EXPECT_NEAR(ndc_depth(10.0), -1.0, 1e-12);
  EXPECT_NEAR(ndc_depth(5000.0), 1.0, 1e-12);
  // The view rotation is orthonormal: a rotation, no scale.
  const glm::dmat3 r = camera.view_rotation();
  const glm::dmat3 identity = r * glm::transpose(r);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(identity[i][j], i == j ? 1.0 : 0.0, 1e-12);
  }
  EXPECT_NEAR(glm::determinant(r), 1.0, 1e-12);
}

TEST(Camera, DepthRangeFollowsClearanceAndHorizon) {
  const DepthRange high = depth_range_for(3000.0, 2000.0);
  EXPECT_DOUBLE_EQ(high.near_m, 500.0);
  EXPECT_GT(high.far_m, horizon_distance_m(3000.0) + horizon_distance_m(8849.0));
  EXPECT_LT(high.far_m, 1.0e6);
  // A camera on or under the ground still gets a usable range.
  const DepthRange low = depth_range_for(500.0, -20.0);
  EXPECT_DOUBLE_EQ(low.near_m, 0.5);
  EXPECT_GT(low.far_m, low.near_m);
  EXPECT_NEAR(horizon_distance_m(1000.0), std::sqrt(1000.0 * (2.0 * geo::wgs84::kA + 1000.0)), 1e-6);
  EXPECT_EQ(horizon_distance_m(-5.0), 0.0);
}

TEST(Camera, ResizingKeepsTheVerticalFieldOfView) {
  Camera camera = camera_at_position(kInterlaken, 0.0, -10.0, Lens{45.0, 400, 300});
  const Ray ray = camera.ray_through_pixel(200.0, 50.0);
  const glm::dvec3 p = offset(ray.origin, 1000.0 * ray.direction);
  camera.set_image_size(800, 300);
  const auto s = camera.project(p);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->x_px, 400.0, 1e-6);
  EXPECT_NEAR(s->y_px, 50.0, 1e-6);
  EXPECT_THROW(camera.set_image_size(0, 300), std::invalid_argument);
}

TEST(Camera, RefusesBadValuesWithAClearMessage) {
  const glm::dvec3 p = ecef_from(kInterlaken);
  EXPECT_THROW(Camera(glm::dvec3{std::nan(""), 0.0, 0.0}, 0.0, 0.0, Lens{}, DepthRange{}), std::invalid_argument);
  EXPECT_THROW(Camera(p, 0.0, -91.0, Lens{}, DepthRange{}), std::invalid_argument);
  EXPECT_THROW(Camera(p, std::nan(""), 0.0, Lens{}, DepthRange{}), std::invalid_argument);
  EXPECT_THROW(Camera(p, 0.0, 0.0, Lens{0.0, 10, 10}, DepthRange{}), std::invalid_argument);
  EXPECT_THROW(Camera(p, 0.0, 0.0, Lens{45.0, 10, 0}, DepthRange{}), std::invalid_argument);
  EXPECT_THROW(Camera(p, 0.0, 0.0, Lens{}, DepthRange{10.0, 5.0}), std::invalid_argument);
  try {
    Camera(p, 0.0, 95.0, Lens{}, DepthRange{});
    FAIL() << "a pitch of 95 degrees was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("pitch 95 is outside -90..90"), std::string::npos) << e.what();
  }
}

// --- horizon ---------------------------------------------------------------------------------

// A point of the true horizon of the WGS84 ellipsoid seen from `camera`, found without the
// camera's algorithm: walking along the geodesic from the nadir in `azimuth_deg`, the point where
// the line of sight becomes tangent (orthogonal to the ellipsoid's normal there).
glm::dvec3 horizon_point(const Camera& camera, double azimuth_deg) {
  const GeoPosition& g = camera.geodetic();
  const glm::dvec3 eye = camera.position();
  const auto sight_along_normal = [&](double s, glm::dvec3& point) {
    double lat = 0.0, lon = 0.0;
    GeographicLib::Geodesic::WGS84().Direct(g.lat_deg, g.lon_deg, azimuth_deg, s, lat, lon);
    point = ecef_from(GeoPosition{lat, lon, 0.0});
    return glm::dot(point - eye, enu_axes_at(lat, lon).up);
  };
  double below = 1.0, beyond = 4.0e6;  // the line of sight points down at first, up beyond the horizon
  glm::dvec3 point;
  for (int i = 0; i < 200 && beyond - below > 1e-7; ++i) {
    const double mid = 0.5 * (below + beyond);
    (sight_along_normal(mid, point) < 0.0 ? below : beyond) = mid;
  }
  sight_along_normal(below, point);
  return point;
}

bool ray_hits_ellipsoid(const Ray& ray) {
  const double a = geo::wgs84::kA, b = a * (1.0 - geo::wgs84::kF);
  const glm::dvec3 o{ray.origin.x / a, ray.origin.y / a, ray.origin.z / b};
  const glm::dvec3 d{ray.direction.x / a, ray.direction.y / a, ray.direction.z / b};
  const double qa = glm::dot(d, d), qb = 2.0 * glm::dot(o, d), qc = glm::dot(o, o) - 1.0;
  const double disc = qb * qb - 4.0 * qa * qc;
  return disc >= 0.0 && (-qb - std::sqrt(disc)) > 0.0;
}

struct HorizonCase {
  GeoPosition position;
  double heading, pitch;
};

TEST(CameraHorizon, TheProjectedHorizonCircleLiesOnTheHorizonRow) {
  const Lens lens{45.0, 1280, 720};
  for (const HorizonCase& c :
       {HorizonCase{{46.69, 7.86, 1000.0}, 0.0, 0.0}, HorizonCase{{46.69, 7.86, 1000.0}, 135.0, -2.0},
        HorizonCase{{-54.9, -67.6, 10000.0}, 290.0, 3.0}, HorizonCase{{0.0, 120.0, 150.0}, 60.0, 0.5},
        HorizonCase{{75.0, -40.0, 35000.0}, 200.0, -5.0}}) {
    const Camera camera = camera_at_position(c.position, c.heading, c.pitch, lens);
    int seen = 0;
    for (double azimuth = c.heading - 40.0; azimuth <= c.heading + 40.0; azimuth += 5.0) {
      const auto s = camera.project(horizon_point(camera, azimuth));
      if (!s || s->x_px < 0.0 || s->x_px > lens.width_px) continue;
      ++seen;
      const std::optional<double> row = camera.horizon_row_px(s->x_px);
      ASSERT_TRUE(row) << "column " << s->x_px;
      EXPECT_NEAR(*row, s->y_px, 0.01) << "camera at " << c.position.lat_deg << ", " << c.position.height_m
                                       << " m, azimuth " << azimuth;
    }
    EXPECT_GE(seen, 5);
  }
}

TEST(CameraHorizon, RaysBelowTheRowHitTheEarthAndRaysAboveMissIt) {
  const Lens lens{45.0, 640, 360};
  const Camera camera = camera_at_position(GeoPosition{46.0, 10.0, 3000.0}, 20.0, -1.0, lens);
  for (double x : {0.0, 100.0, 320.0, 639.0}) {
    const std::optional<double> row = camera.horizon_row_px(x);
    ASSERT_TRUE(row);
    EXPECT_TRUE(ray_hits_ellipsoid(camera.ray_through_pixel(x, *row + 0.05)));
    EXPECT_FALSE(ray_hits_ellipsoid(camera.ray_through_pixel(x, *row - 0.05)));
  }
}

// Over flat ground with a level camera, the horizon dips below the image centre by
// acos(R / (R + h)), R the Earth's radius of curvature in the view direction (Euler's formula
// from the meridional and prime-vertical radii).
TEST(CameraHorizon, LevelCameraMatchesTheCurvatureFormula) {
  const Lens lens{45.0, 1920, 1080};
  for (double height : {100.0, 1000.0, 10000.0}) {
    for (double heading : {0.0, 90.0, 45.0}) {
      const GeoPosition p{46.69, 7.86, height};
      const Camera camera = camera_at_position(p, heading, 0.0, lens);
      const double s2 = std::pow(std::sin(p.lat_deg * kRadPerDeg), 2.0);
      const double w = std::sqrt(1.0 - geo::wgs84::kE2 * s2);
      const double m = geo::wgs84::kA * (1.0 - geo::wgs84::kE2) / (w * w * w), n = geo::wgs84::kA / w;
      const double az = heading * kRadPerDeg;
      const double r = 1.0 / (std::cos(az) * std::cos(az) / m + std::sin(az) * std::sin(az) / n);
      const double dip = std::acos(r / (r + height));
      const double expected = 540.0 + 540.0 * std::tan(dip) / std::tan(22.5 * kRadPerDeg);
      const std::optional<double> row = camera.horizon_row_px(960.0);
      ASSERT_TRUE(row);
      EXPECT_NEAR(*row, expected, 0.05) << height << " m, heading " << heading;
      EXPECT_GT(*row, 540.0);  // below the centre: the Earth curves away
    }
  }
}

TEST(CameraHorizon, NoHorizonLookingUpOrFromBelowTheSurface) {
  EXPECT_FALSE(camera_at_position(kInterlaken, 0.0, 90.0).horizon_row_px(960.0));
  // Looking up at 60 degrees the horizon is below the image, not absent.
  const std::optional<double> below = camera_at_position(kInterlaken, 0.0, 60.0).horizon_row_px(960.0);
  ASSERT_TRUE(below);
  EXPECT_GT(*below, 1080.0);
  EXPECT_FALSE(camera_at_position(GeoPosition{46.69, 7.86, -10.0}, 0.0, 0.0).horizon_row_px(960.0));
}

// --- options ---------------------------------------------------------------------------------

TEST(CameraOptions, ParsesCameraPlacement) {
  const Result<CameraPlacement> r = parse_camera_option("46.68, 7.86,3000,495,-25.5");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_DOUBLE_EQ(r.value->position.lat_deg, 46.68);
  EXPECT_DOUBLE_EQ(r.value->position.lon_deg, 7.86);
  EXPECT_DOUBLE_EQ(r.value->position.height_m, 3000.0);
  EXPECT_DOUBLE_EQ(r.value->heading_deg, 135.0);
  EXPECT_DOUBLE_EQ(r.value->pitch_deg, -25.5);
  EXPECT_TRUE(parse_camera_option("+46,-7,+10,0,0").ok());
}

void expect_error(const std::string& error, std::initializer_list<const char*> parts) {
  EXPECT_FALSE(error.empty());
  for (const char* part : parts) EXPECT_NE(error.find(part), std::string::npos) << "'" << part << "' not in: " << error;
}

TEST(CameraOptions, CameraErrorsShowTheExpectedForm) {
  const auto error = [](std::string_view text) {
    const Result<CameraPlacement> r = parse_camera_option(text);
    EXPECT_FALSE(r.ok()) << text;
    return r.error;
  };
  expect_error(error("46.68,7.86,3000,135"),
               {"LAT,LON,ALT,HEADING,PITCH", "'46.68,7.86,3000,135'", "4 values instead of 5"});
  expect_error(error(""), {"LAT,LON,ALT,HEADING,PITCH", "instead of 5"});
  expect_error(error("46.68,east,3000,135,-20"), {"LON 'east' is not a number"});
  expect_error(error("46.68,7.86,3000m,135,-20"), {"ALT '3000m' is not a number"});
  expect_error(error("95,7.86,3000,135,-20"), {"latitude 95 is outside -90..90"});
  expect_error(error("46,190,3000,135,-20"), {"longitude 190 is outside -180..180"});
  expect_error(error("46,7,3000,135,-120"), {"pitch -120 is outside -90..90"});
  expect_error(error("46,7,3000,nan,-20"), {"HEADING 'nan' is not a number"});
  expect_error(error("46,7,3000,inf,-20"), {"HEADING 'inf' is not a number"});
}

TEST(CameraOptions, ParsesLookAtTarget) {
  const Result<GeoPosition> r = parse_look_at_option("46.70,7.88,1200");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_DOUBLE_EQ(r.value->lat_deg, 46.70);
  EXPECT_DOUBLE_EQ(r.value->lon_deg, 7.88);
  EXPECT_DOUBLE_EQ(r.value->height_m, 1200.0);
  expect_error(parse_look_at_option("46.70,7.88").error, {"--look-at expects LAT,LON,ALT", "2 values instead of 3"});
  expect_error(parse_look_at_option("-91,7.88,5").error, {"LAT,LON,ALT", "latitude -91 is outside -90..90"});
}

TEST(CameraOptions, CameraAtPlacesTheCameraAsAsked) {
  const Result<Camera> r =
      camera_at(CameraPlacement{{46.68, 7.86, 3000.0}, 135.0, -25.0}, Lens{40.0, 800, 600}, 1000.0);
  ASSERT_TRUE(r.ok()) << r.error;
  const Camera& c = *r.value;
  EXPECT_NEAR(c.geodetic().lat_deg, 46.68, 1e-9);
  EXPECT_NEAR(c.geodetic().lon_deg, 7.86, 1e-9);
  EXPECT_NEAR(c.geodetic().height_m, 3000.0, 1e-6);
  EXPECT_DOUBLE_EQ(c.heading_deg(), 135.0);
  EXPECT_DOUBLE_EQ(c.pitch_deg(), -25.0);
  EXPECT_DOUBLE_EQ(c.lens().vertical_fov_deg, 40.0);
  EXPECT_DOUBLE_EQ(c.depth_range().near_m, 500.0);  // a quarter of the 2000 m clearance
  expect_error(camera_at(CameraPlacement{{46.68, 7.86, 3000.0}, 135.0, -25.0}, Lens{180.0, 800, 600}, 0.0).error,
               {"--fov 180", "(0, 180)"});
  expect_error(camera_at(CameraPlacement{{46.68, 7.86, 3000.0}, 135.0, -25.0}, Lens{45.0, 0, 600}, 0.0).error,
               {"--size 0x600"});
}

TEST(CameraOptions, LookAtPutsTheTargetAtTheImageCentre) {
  const Lens lens{45.0, 1000, 500};
  for (const double pitch : {-35.0, -90.0, 0.0, 20.0}) {
    const LookAt look{GeoPosition{46.70, 7.88, 1200.0}, 8000.0, 135.0, pitch};
    const Result<Camera> r = camera_looking_at(look, lens, 600.0);
    ASSERT_TRUE(r.ok()) << r.error;
    const Camera& c = *r.value;
    const glm::dvec3 target = ecef_from(look.target);
    const auto s = c.project(target);
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->x_px, 500.0, 1e-6) << "pitch " << pitch;
    EXPECT_NEAR(s->y_px, 250.0, 1e-6) << "pitch " << pitch;
    EXPECT_NEAR(s->depth_m, 8000.0, 1e-6);
    // The camera's own heading and pitch differ from the target's by the Earth's curvature
    // over 8 km (0.07 degrees) at most.
    if (pitch > -89.0) {
      EXPECT_NEAR(c.heading_deg(), 135.0, 0.1);
    }
    EXPECT_NEAR(c.pitch_deg(), pitch, 0.1);
    EXPECT_LT(c.depth_range().near_m, 8000.0);
  }
  // Straight down: the camera directly above, the screen oriented by the heading.
  const Camera above =
      *camera_looking_at(LookAt{GeoPosition{46.7, 7.88, 1200.0}, 500.0, 90.0, -90.0}, lens, 1000.0).value;
  EXPECT_NEAR(above.geodetic().height_m, 1700.0, 1e-6);
  EXPECT_NEAR(above.heading_deg(), 90.0, 1e-9);
  EXPECT_NEAR(above.depth_range().near_m, 125.0, 1e-6);  // the 500 m to the target, not the 700 m to the ground
}

TEST(CameraOptions, LookAtErrorsNameTheOption) {
  const Lens lens;
  const GeoPosition t{46.7, 7.88, 1200.0};
  expect_error(camera_looking_at(LookAt{t, 0.0, 0.0, -30.0}, lens, 0.0).error, {"--distance 0", "metres"});
  expect_error(camera_looking_at(LookAt{t, -5.0, 0.0, -30.0}, lens, 0.0).error, {"--distance -5"});
  expect_error(camera_looking_at(LookAt{t, 100.0, 0.0, -130.0}, lens, 0.0).error, {"--pitch -130", "-90..90"});
  expect_error(camera_looking_at(LookAt{t, 100.0, std::nan(""), -30.0}, lens, 0.0).error, {"--heading"});
  expect_error(camera_looking_at(LookAt{{100.0, 7.0, 0.0}, 100.0, 0.0, -30.0}, lens, 0.0).error,
               {"--look-at", "latitude 100"});
}

}  // namespace
}  // namespace trailray::scene
